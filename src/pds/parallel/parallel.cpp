#include "pds/parallel.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace pds {
namespace {

thread_local bool inside_body = false;
constexpr int kMaxThreads = 256;
std::atomic<int> thread_cap{0};  // 0: none

/// One loop at a time: workers and the caller take chunks from a shared
/// counter until none is left. Loops that arrive while one runs (from other
/// user threads) wait for the pool; loops nested in a body run serially.
class Pool {
 public:
  static Pool& instance() {
    static Pool pool;
    return pool;
  }

  void run(std::size_t chunks, int threads, const std::function<void(std::size_t)>& chunk) {
    std::unique_lock<std::mutex> busy(busy_);
    ensure_workers(threads - 1);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      chunk_ = &chunk;
      chunks_ = chunks;
      next_.store(0);
      done_ = 0;
      failure_ = nullptr;
      failed_.store(false);
      helpers_ = std::min<std::size_t>(static_cast<std::size_t>(threads - 1), chunks - 1);
      joined_ = 0;
      ++generation_;
    }
    wake_.notify_all();
    work();
    std::unique_lock<std::mutex> lock(mutex_);
    finished_.wait(lock, [&] { return done_ == chunks_ && joined_ == helpers_; });
    chunk_ = nullptr;
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  Pool() = default;
  ~Pool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
  }

  void ensure_workers(int wanted) {
    while (static_cast<int>(workers_.size()) < wanted) {
      const std::size_t id = workers_.size();
      workers_.emplace_back([this, id] { worker(id); });
    }
  }

  void worker(std::size_t id) {
    inside_body = true;
    std::uint64_t seen = 0;
    while (true) {
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return stop_ || (generation_ != seen && chunk_ && id < helpers_); });
        if (stop_) return;
        seen = generation_;
      }
      work();
      {
        std::lock_guard<std::mutex> lock(mutex_);
        ++joined_;
      }
      finished_.notify_all();
    }
  }

  /// Takes chunks until none is left.
  void work() {
    const bool was_inside = inside_body;
    inside_body = true;
    std::size_t finished = 0;
    for (std::size_t c; (c = next_.fetch_add(1)) < chunks_;) {
      if (!failed_.load(std::memory_order_relaxed)) {
        try {
          (*chunk_)(c);
        } catch (...) {
          std::lock_guard<std::mutex> lock(mutex_);
          if (!failure_) failure_ = std::current_exception();
          failed_.store(true);
        }
      }
      ++finished;
    }
    inside_body = was_inside;
    std::lock_guard<std::mutex> lock(mutex_);
    done_ += finished;
    finished_.notify_all();
  }

  std::mutex busy_;  // one loop at a time
  std::mutex mutex_;
  std::condition_variable wake_, finished_;
  std::vector<std::thread> workers_;
  const std::function<void(std::size_t)>* chunk_ = nullptr;
  std::size_t chunks_ = 0, done_ = 0, helpers_ = 0, joined_ = 0;
  std::atomic<std::size_t> next_{0};
  std::atomic<bool> failed_{false};
  std::exception_ptr failure_;
  std::uint64_t generation_ = 0;
  bool stop_ = false;
};

}  // namespace

int hardware_threads() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

ThreadLimit::ThreadLimit(int max_threads) : previous_(thread_cap.exchange(std::max(max_threads, 1))) {}
ThreadLimit::~ThreadLimit() { thread_cap.store(previous_); }

void parallel_for(std::size_t begin, std::size_t end, std::size_t grain, int threads, const ChunkBody& body) {
  if (end <= begin) return;
  grain = std::max<std::size_t>(grain, 1);
  const std::size_t chunks = (end - begin + grain - 1) / grain;
  if (threads <= 0) threads = hardware_threads();
  threads = std::min(threads, kMaxThreads);
  if (const int cap = thread_cap.load(); cap > 0) threads = std::min(threads, cap);
  if (threads == 1 || chunks == 1 || inside_body) {
    for (std::size_t b = begin; b < end; b += grain) body(b, std::min(end, b + grain));
    return;
  }
  Pool::instance().run(chunks, threads, [&](std::size_t c) {
    const std::size_t b = begin + c * grain;
    body(b, std::min(end, b + grain));
  });
}

}  // namespace pds
