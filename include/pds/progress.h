#pragma once
// Progress of a long run and a way to stop it, for library callers (the
// command line draws its bar from it). Optional everywhere: an empty
// Progress costs one test of an empty std::function per report.
//
// A run reports (done, total) from the thread that called it, done never
// decreasing and at most total; total is fixed for the run, in the run's own
// unit (samples placed, iterations, sets analysed). A method that stops on
// its own (a maximal set) reports its best estimate of the total and a last
// (total, total) when it ends. Returning false from the callback stops the
// run: it throws pds::Cancelled, and nothing it would have returned exists.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>

#include "pds/error.h"

namespace pds {

/// Thrown by a run whose progress callback returned false.
class Cancelled : public Failure {
 public:
  Cancelled() : Failure("cancelled") {}
};

struct Progress {
  /// Called with (done, total); return false to stop the run.
  std::function<bool(double done, double total)> report;

  explicit operator bool() const { return static_cast<bool>(report); }
};

/// Part `index` of `parts` runs made one after another, as a Progress of its
/// own: the part's (done, total) reaches `whole` as (index + done / total,
/// parts), so the whole stays monotone across the parts.
inline Progress part_of(const Progress& whole, std::size_t index, std::size_t parts) {
  if (!whole) return {};
  return {[whole, index, parts](double done, double total) {
    return whole.report(static_cast<double>(index) + (total > 0 ? done / total : 0.0), static_cast<double>(parts));
  }};
}

/// What a run holds while it works: forwards reports to a Progress, at most
/// about a thousand for the whole run however often update() is called (and
/// ten a second while poll() is),
/// keeps them monotone, and throws Cancelled when asked to stop.
class ProgressReporter {
 public:
  ProgressReporter(const Progress& progress, double total) : progress_(progress), total_(total > 0 ? total : 1) {
    update(0);
  }

  /// Reports `done` (clamped into [last reported, total]) when it has moved
  /// by a thousandth of the total since the last report or first reaches the
  /// total, or every 2^16 calls, so that a run whose count stalls (or has
  /// passed its estimated total) still hears a cancellation.
  void update(double done) {
    if (!progress_) return;
    if (done < done_) done = done_;
    if (done > total_) done = total_;
    if (reported_ && done < next_ && done < total_ && (++calls_ & 0xffff) != 0) return;
    if (reported_ && done_ >= total_ && (++calls_ & 0xffff) != 0) return;  // the total was reported
    send(done);
  }

  /// For work that does not move the run's count (a refinement between two
  /// levels of darts): repeats the last report once a tenth of a second has
  /// passed since the last one, so that a stop is heard promptly. The output
  /// never depends on it, only when a stop is heard.
  void poll() {
    if (progress_ && std::chrono::steady_clock::now() - last_send_ >= std::chrono::milliseconds(100)) send(done_);
  }
  /// The last report, (total, total); call when the run has succeeded.
  void finish() {
    if (progress_ && done_ < total_) send(total_);
  }

  double total() const { return total_; }

  /// The stretch [from, to] of this run's total as a Progress of its own,
  /// for a part that reports in its own unit (one measure of a set): its
  /// (done, total) arrives here as from + (to - from) done / total. Empty
  /// when this run has no callback; valid while this reporter lives.
  Progress span(double from, double to) {
    if (!progress_) return {};
    return {[this, from, to](double done, double total) {
      update(from + (to - from) * (total > 0 ? done / total : 0.0));
      return true;  // a stop was already thrown by update()
    }};
  }

 private:
  void send(double done) {
    last_send_ = std::chrono::steady_clock::now();
    done_ = done;
    next_ = done + total_ / 1000;
    reported_ = true;
    if (!progress_.report(done, total_)) throw Cancelled();
  }

  Progress progress_;  // a copy: the caller's may be a temporary
  double total_;
  double done_ = 0, next_ = 0;
  std::uint32_t calls_ = 0;
  std::chrono::steady_clock::time_point last_send_{};
  bool reported_ = false;
};

}  // namespace pds
