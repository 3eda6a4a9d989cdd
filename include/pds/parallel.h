#pragma once
// The one place where pds runs work on several threads. Samplers and analyses
// call parallel_for; nothing else in the library starts a thread.
//
// Determinism: a body is called on chunks [b, e) that split [begin, end) in
// an order no caller may rely on, on whichever thread is free. Callers write
// each chunk's results to places of their own (or combine them in index
// order afterwards), so the output never depends on the number of threads or
// on which thread ran what (tested by every parallel method's tests).
//
// The default backend is a small pool of std::threads, started on first use
// and kept for the life of the process; with `threads == 1` (or a range of
// one chunk) the body runs on the calling thread and no thread is started.
// A call made from inside a body runs serially on that thread.

#include <cstddef>
#include <functional>

namespace pds {

/// The body of a parallel loop: called with [chunk_begin, chunk_end).
using ChunkBody = std::function<void(std::size_t, std::size_t)>;

/// Calls body on chunks of at most `grain` indices covering [begin, end),
/// using up to `threads` threads (0: all hardware threads), and returns when
/// every chunk is done. An exception thrown by a body is rethrown here (the
/// first one; remaining chunks are skipped).
void parallel_for(std::size_t begin, std::size_t end, std::size_t grain, int threads, const ChunkBody& body);

/// The threads parallel_for uses for `threads` == 0: the hardware's, at least 1.
int hardware_threads();

/// Caps the threads of every parallel_for in the process while it lives
/// (nested limits: the innermost holds), e.g. to check that 1 and 4 threads
/// give the same result, or to keep a library call off the other cores.
class ThreadLimit {
 public:
  explicit ThreadLimit(int max_threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  int previous_;
};

}  // namespace pds
