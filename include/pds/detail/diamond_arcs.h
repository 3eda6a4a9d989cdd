#pragma once
// Arcs of a circle without trigonometry, for boundary sampling
// (Dunbar-Humphreys variant 0): a direction is kept as its "diamond angle",
// a free set of directions as a list of arcs in that measure, and a direction
// uniform in true angle over the free arcs is drawn by rejection.

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "pds/error.h"
#include "pds/rng.h"

namespace pds::detail {

/// A direction (x, y) != 0 as its "diamond angle" in [0, 4]: where the ray
/// meets the square |x| + |y| = 1, counted quadrant by quadrant (4 is 0 again).
/// It increases with the true angle, costs one division, and is exact to
/// rounding, so arcs can be ordered and cut without trigonometry.
inline double diamond_angle(double x, double y) {
  const double ax = std::abs(x), ay = std::abs(y);
  const double f = ay / (ax + ay);             // past the x axis, within the quadrant
  const double upper = x < 0.0 ? 2.0 - f : f;  // the angle of (x, |y|), in [0, 2]
  return y < 0.0 ? 4.0 - upper : upper;        // below the axis: mirrored
}

/// A direction at diamond angle t in [0, 4) (the inverse of diamond_angle, on
/// the square |x| + |y| = 1).
inline std::array<double, 2> diamond_direction(double t) {
  const int quadrant = std::min(static_cast<int>(t), 3);
  const double s = t - quadrant, c = 1.0 - s;
  switch (quadrant) {
    case 0:
      return {c, s};
    case 1:
      return {-s, c};
    case 2:
      return {-c, -s};
    default:
      return {s, -c};
  }
}

/// An arc of directions: from diamond angle `lo` in [0, 4) counterclockwise
/// over `len` in [0, 4).
struct DiamondArc {
  double lo, len;
};

/// The arc from direction a counterclockwise to direction b (less than a full turn).
inline DiamondArc diamond_arc(double ax, double ay, double bx, double by) {
  double lo = diamond_angle(ax, ay), len = diamond_angle(bx, by) - lo;
  lo = lo >= 4.0 ? lo - 4.0 : lo;
  len = len < 0.0 ? len + 4.0 : len;
  return {lo, len};
}

/// How far x lies past `lo` counterclockwise, in [0, 4) (both in [0, 4)).
inline double diamond_past(double x, double lo) {
  const double d = x - lo;
  return d < 0.0 ? d + 4.0 : d;
}

/// The free part of a circle: disjoint arcs of directions (DiamondArc).
class FreeArcs {
 public:
  // The most arcs a circle of radius r gets blocked by: samples at least r
  // apart and from its centre, within 2r of it, have disjoint disks of radius
  // r / 2 inside the ring 0.5 r..2.5 r, so there are at most 24; plus 4 walls.
  static constexpr int kMaxBlocked = 32;

  /// The directions that no arc of `blocked` holds in its interior; sorts
  /// `blocked` by start.
  void assign_complement(DiamondArc* blocked, int count) {
    arcs_.clear();
    // Insertion sort: the 5-10 arcs of a front sample.
    for (int i = 1; i < count; ++i) {
      const DiamondArc a = blocked[i];
      int j = i;
      for (; j > 0 && blocked[j - 1].lo > a.lo; --j) blocked[j] = blocked[j - 1];
      blocked[j] = a;
    }
    // Sweep from 0, where the arcs that wrap past 4 already cover [0, covered).
    double covered = 0.0;
    for (int i = 0; i < count; ++i) covered = std::max(covered, blocked[i].lo + blocked[i].len - 4.0);
    for (int i = 0; i < count; ++i) {
      if (blocked[i].lo - covered > kMinArc) arcs_.push_back({covered, blocked[i].lo - covered});
      covered = std::max(covered, blocked[i].lo + blocked[i].len);
    }
    if (4.0 - covered > kMinArc) arcs_.push_back({covered, 4.0 - covered});
  }

  bool empty() const { return arcs_.empty(); }
  const std::vector<DiamondArc>& arcs() const { return arcs_; }

  /// Removes the open arc `cut` (of less than a full turn).
  void remove(DiamondArc cut) {
    const std::size_t n = arcs_.size();
    std::size_t out = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const DiamondArc a = arcs_[i];
      // In positions past a.lo the cut covers (from, to) and, when to passes
      // 4, also [0, to - 4).
      const double from = diamond_past(cut.lo, a.lo), to = from + cut.len;
      const double head_end = std::min(from, a.len);
      if (to > 4.0) {
        if (head_end - (to - 4.0) > kMinArc) arcs_[out++] = shifted(a, to - 4.0, head_end);
        continue;
      }
      if (head_end > kMinArc) arcs_[out++] = shifted(a, 0.0, head_end);
      if (a.len - to > kMinArc) arcs_.push_back(shifted(a, to, a.len));
    }
    // Pieces appended after n move down (the order is deterministic).
    for (std::size_t i = n; i < arcs_.size(); ++i) arcs_[out++] = arcs_[i];
    arcs_.resize(out);
  }

  /// The diamond angle at fraction u in [0, 1) of the free length.
  double at(double u) const {
    double total = 0.0;
    for (const DiamondArc& a : arcs_) total += a.len;
    double x = u * total;
    for (const DiamondArc& a : arcs_) {
      if (x < a.len) {
        const double t = a.lo + x;
        return t >= 4.0 ? t - 4.0 : t;
      }
      x -= a.len;
    }
    return arcs_.back().lo;  // only if rounding ran past the end
  }

  /// A direction uniform in true angle over the free arcs, as a diamond
  /// angle; requires !empty(). Uniform in diamond angle t, kept with
  /// probability (dtheta/dt) / 2: dtheta/dt = 1 / (c^2 + s^2) lies in [1, 2]
  /// (s the position of t within its quadrant, c = 1 - s).
  double sample(Rng& rng) const {
    for (int attempt = 0; attempt < 1000; ++attempt) {
      const double t = at(rng.uniform());
      const double s = t - std::floor(t), c = 1.0 - s;
      if (2.0 * (c * c + s * s) * rng.uniform() < 1.0) return t;
    }
    // Each try succeeds with probability at least 1/2.
    throw Failure("free arcs: 1000 directions rejected in a row (random generator broken?)");
  }

 private:
  /// The part [from, to) of `a`, in positions past a.lo.
  static DiamondArc shifted(const DiamondArc& a, double from, double to) {
    const double lo = a.lo + from;
    return {lo >= 4.0 ? lo - 4.0 : lo, to - from};
  }

  // Free arcs shorter than this are dropped: under 2e-13 rad (dtheta/dt <= 2),
  // an opening between disks narrower than 2e-13 radius.
  static constexpr double kMinArc = 1e-13;
  std::vector<DiamondArc> arcs_;
};

}  // namespace pds::detail
