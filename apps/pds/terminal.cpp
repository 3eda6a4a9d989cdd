#include "terminal.h"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>

namespace pds::cli {
namespace {

// The handler may read only what is async-signal-safe: a fixed buffer whose
// use is announced by an atomic flag.
char g_remove[4096];
std::atomic<bool> g_remove_set{false};

extern "C" void on_interrupt(int signal) {
  constexpr char kMessage[] = "\npds: interrupted\n";
  [[maybe_unused]] const auto written = ::write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
  if (g_remove_set.load()) ::unlink(g_remove);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

void install_interrupt_handler() {
  // A shell starts background jobs with SIGINT ignored: leave it so.
  if (std::signal(SIGINT, on_interrupt) == SIG_IGN) std::signal(SIGINT, SIG_IGN);
}

void interrupt_removes(const std::string& path) {
  g_remove_set.store(false);
  if (path.empty() || path.size() >= sizeof g_remove) return;
  std::memcpy(g_remove, path.c_str(), path.size() + 1);
  g_remove_set.store(true);
}

std::string progress_line(const std::string& label, double done, double total, double seconds, int width) {
  const double share = total > 0 ? std::min(1.0, done / total) : 0.0;
  const int filled = static_cast<int>(share * width);
  std::ostringstream line;
  line << label << " [" << std::string(filled, '#') << std::string(width - filled, '.') << "] "
       << static_cast<long long>(done) << '/' << static_cast<long long>(total) << ' ' << static_cast<int>(share * 100)
       << '%';
  if (share > 0 && share < 1) line << ' ' << std::lround(seconds * (1 - share) / share) << " s left";
  return line.str();
}

ProgressBar::ProgressBar(std::string label, bool quiet)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()), last_(start_) {
  if (quiet || !::isatty(STDERR_FILENO)) return;
  progress_.report = [this](double done, double total) { return draw(done, total); };
}

ProgressBar::~ProgressBar() {
  if (drawn_) std::cerr << "\r\033[K" << std::flush;
}

bool ProgressBar::draw(double done, double total) {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - start_).count();
  if (seconds < 0.5 || (drawn_ && now - last_ < std::chrono::milliseconds(100) && done < total)) return true;
  last_ = now;
  drawn_ = true;
  std::cerr << "\r\033[K" << progress_line(label_, done, total, seconds, 30) << std::flush;
  return true;
}

}  // namespace pds::cli
