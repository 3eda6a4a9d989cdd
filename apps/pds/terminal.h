#pragma once
// What the command line does at the terminal: a progress bar on stderr for
// long runs, and Ctrl-C that stops at once and leaves no partial file.

#include <chrono>
#include <string>

#include "pds/progress.h"

namespace pds::cli {

/// SIGINT: say so on stderr, remove the output's temporary file (if one is
/// being written, see interrupt_removes), and die of the signal (status 130
/// in a shell). Installed once by main().
void install_interrupt_handler();

/// The file a Ctrl-C removes from now on (pds::temporary_path of the
/// output): set before writing, cleared after.
void interrupt_removes(const std::string& path);

/// A bar with count, percentage and time left, redrawn on one line of stderr
/// at most ten times a second, shown only when stderr is a terminal, the run
/// has lasted half a second and `quiet` is false; erased when destroyed.
class ProgressBar {
 public:
  ProgressBar(std::string label, bool quiet);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// The callback to hand to the library (empty when the bar is off).
  const Progress& progress() const { return progress_; }

 private:
  bool draw(double done, double total);

  std::string label_;
  Progress progress_;
  std::chrono::steady_clock::time_point start_, last_;
  bool drawn_ = false;
};

/// The bar's line: "label [#####.....] 512000/1000000 51% 12 s left".
std::string progress_line(const std::string& label, double done, double total, double seconds, int width);

}  // namespace pds::cli
