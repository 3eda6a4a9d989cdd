#pragma once
// Arcs of a circle without trigonometry, for boundary sampling
// (Dunbar-Humphreys variant 0): a direction is kept as its "diamond angle",
// a free set of directions as a list of arcs in that measure, and a direction
// uniform in true angle over the free arcs is drawn by rejection.

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>

#include "pds/error.h"
#include "pds/rng.h"

namespace pds::detail {

/// A direction (x, y) != 0 as its "diamond angle" in [0, 4]: where the ray
/// meets the square |x| + |y| = 1, measured along the square (so 1 per
/// quadrant; 4 is 0 again). With u = x / (|x| + |y|) it is 1 - u above the
/// x axis and 3 + u below, i.e. 2 - copysign(1 + u, y): one division and no
/// branch (the sign of y picks the half). It increases with the true angle
/// (rounding is monotone), so arcs can be ordered and cut without trigonometry.
inline double diamond_angle(double x, double y) {
  const double u = x / (std::abs(x) + std::abs(y));
  return 2.0 - std::copysign(1.0 + u, y);
}

/// A direction at diamond angle t in [0, 4) (the inverse of diamond_angle, on
/// the square |x| + |y| = 1): x = |t - 2| - 1, y = +-(1 - |x|), + for t < 2.
inline std::array<double, 2> diamond_direction(double t) {
  const double x = std::abs(t - 2.0) - 1.0;
  return {x, std::copysign(1.0 - std::abs(x), 2.0 - t)};
}

/// An arc of directions: from diamond angle `lo` in [0, 4) counterclockwise
/// over `len` in [0, 4).
struct DiamondArc {
  double lo, len;
};

/// The arc from direction a counterclockwise to direction b (less than a full turn).
inline DiamondArc diamond_arc(double ax, double ay, double bx, double by) {
  // The wraps are arithmetic (adding 0 or 4 is exact) so that no branch
  // depends on the random directions.
  double lo = diamond_angle(ax, ay), len = diamond_angle(bx, by) - lo;
  lo -= 4.0 * static_cast<double>(lo >= 4.0);
  len += 4.0 * static_cast<double>(len < 0.0);
  return {lo, len};
}

/// diamond_arc with one division for both ends instead of two: 1 / (sa sb)
/// for the ends' sums sa = |ax| + |ay| and sb, then each quotient as a
/// product (ax sb / (sa sb)), for the hot loop where divisions set the pace.
/// The quotients are a few ulps off the correctly rounded ones (clamped to 1,
/// so the angles stay in [0, 4]), and, unlike the two quotients of
/// diamond_arc, the two ends no longer round alike: an arc a few ulps long
/// could come out slightly negative and wrap to almost a full turn. Such a
/// length (above 3) is set to 0; the arcs this serves are at most 120 degrees,
/// under 2.1 in diamond measure. The components should be near 1 in size
/// (four of them are multiplied together).
inline DiamondArc diamond_arc_one_division(double ax, double ay, double bx, double by) {
  const double sa = std::abs(ax) + std::abs(ay), sb = std::abs(bx) + std::abs(by);
  const double inv = 1.0 / (sa * sb);
  const double ua = std::min(ax * sb * inv, 1.0), ub = std::min(bx * sa * inv, 1.0);
  double lo = 2.0 - std::copysign(1.0 + ua, ay), len = (2.0 - std::copysign(1.0 + ub, by)) - lo;
  lo -= 4.0 * static_cast<double>(lo >= 4.0);
  len += 4.0 * static_cast<double>(len < 0.0);
  len *= static_cast<double>(len <= 3.0);
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

  /// The directions that no blocked arc (starts `lo`, lengths `len`) holds
  /// in its interior, without sorting the arcs: the gap before arc k begins
  /// where the arcs that start before it (ties: earlier in the list) stop
  /// covering, which is exactly the value a sweep over the arcs sorted by
  /// start reaches there; the last gap ends at 4. The gaps come out in the
  /// order of the arcs they end at. O(count^2) comparisons and no
  /// data-dependent branch: a front sample has about 8 arcs, in random order,
  /// and sorting them cost a mispredicted branch per arc.
  void assign_complement_unsorted(const double* lo, const double* len, int count) {
    if (count > kMaxBlocked) throw std::logic_error("free arcs: more blocked arcs than a circle can have");
    double first = 0.0;  // [0, first) is covered by arcs that wrap past 4
    for (int i = 0; i < count; ++i) first = std::max(first, lo[i] + len[i] - 4.0);
    DiamondArc* out = arcs_;
    int kept = 0;
    double last = first;
    for (int k = 0; k < count; ++k) {
      double covered = first;
      for (int i = 0; i < count; ++i) {
        const bool before = (lo[i] < lo[k]) | ((lo[i] == lo[k]) & (i < k));
        // Ends are >= 0 and so is covered: an end times 0 leaves it unchanged.
        covered = std::max(covered, (lo[i] + len[i]) * static_cast<double>(before));
      }
      const double gap = lo[k] - covered;
      out[kept] = {covered, gap};
      kept += gap > kMinArc;
      last = std::max(last, lo[k] + len[k]);
    }
    out[kept] = {last, 4.0 - last};
    kept += 4.0 - last > kMinArc;
    size_ = static_cast<std::size_t>(kept);
  }

  /// Room for `most` arcs, to be written directly (by a vectorised
  /// complement that computes what assign_complement_unsorted does), then
  /// finish_fill with how many were written.
  DiamondArc* begin_fill(std::size_t most) {
    if (most > kCapacity) throw std::logic_error("free arcs: fill beyond the capacity");
    return arcs_;
  }
  void finish_fill(std::size_t count) { size_ = count; }
  static constexpr double min_arc() { return kMinArc; }

  bool empty() const { return size_ == 0; }
  std::span<const DiamondArc> arcs() const { return {arcs_, size_}; }

  /// Removes the open arc `cut` (of less than a full turn).
  void remove(DiamondArc cut) {
    const std::size_t n = size_;
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
      if (a.len - to > kMinArc) {
        if (size_ == kCapacity) throw std::logic_error("free arcs: more pieces than a circle can have");
        arcs_[size_++] = shifted(a, to, a.len);
      }
    }
    // Pieces appended after n move down (the order is deterministic).
    for (std::size_t i = n; i < size_; ++i) arcs_[out++] = arcs_[i];
    size_ = out;
  }

  /// The diamond angle at fraction u in [0, 1) of the free length.
  double at(double u) const { return at(u, total()); }

  /// The free length (summed in list order).
  double total() const {
    double sum = 0.0;
    for (const DiamondArc& a : arcs()) sum += a.len;
    return sum;
  }

  /// As at(u), with the free length `total` already summed (sample() tries
  /// several u on the same arcs).
  double at(double u, double total) const {
    double x = u * total;
    for (const DiamondArc& a : arcs()) {
      if (x < a.len) {
        const double t = a.lo + x;
        return t >= 4.0 ? t - 4.0 : t;
      }
      x -= a.len;
    }
    return arcs_[size_ - 1].lo;  // only if rounding ran past the end
  }

  /// A direction uniform in true angle over the free arcs, as a diamond
  /// angle; requires !empty(). Uniform in diamond angle t, kept with
  /// probability (dtheta/dt) / 2: dtheta/dt = 1 / (c^2 + s^2) lies in [1, 2]
  /// (s the position of t within its quadrant, c = 1 - s).
  double sample(Rng& rng) const {
    const double free_length = total();
    for (int attempt = 0; attempt < 1000; ++attempt) {
      const double t = at(rng.uniform(), free_length);
      const double s = t - static_cast<double>(static_cast<int>(t)), c = 1.0 - s;  // t >= 0: truncation is floor
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
  // Fixed storage (a front sample's arcs are few; no resizing or
  // zero-filling per front sample): at most kMaxBlocked + 1 arcs
  // after a complement, one more per cut (at most 6 samples and 24
  // slivers around one front sample), and room for begin_fill's whole-vector
  // stores.
  static constexpr std::size_t kCapacity = 64;
  DiamondArc arcs_[kCapacity];
  std::size_t size_ = 0;
};

}  // namespace pds::detail
