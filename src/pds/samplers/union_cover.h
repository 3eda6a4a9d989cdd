#pragma once
// A test that the union of several disks covers a box, for the samplers that
// drop covered sub-cells (ebeida, wei) in high dimensions, where most of the
// space near the samples lies close to the edge of the nearest disk and a
// box is seldom inside any one disk.

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace pds::detail {

/// Whether the union of disks covers a box that no one of them covers. It
/// does if some weights w_i >= 0 summing to 1 keep the weighted mean of the
/// squared distances to the disks' centres, sum_i w_i |x - s_i|^2, below the
/// squared radius at every corner: the mean is convex in x, so it is below
/// on the whole box, and the nearest centre is no farther than the mean.
/// With the box's centre as origin (d_i the disks' centres, e its edges, h
/// its half diagonal) the largest corner value is sum_i w_i |d_i|^2 +
/// sum_a e_a |m_a| + h^2, m = sum_i w_i d_i: close disks whose weighted
/// centre is near the box's. A weight on one disk alone is the single-disk
/// test; Frank-Wolfe steps (towards one disk at a time, exact line search)
/// improve the weights, and any weights found prove coverage.
template <int D>
class UnionCover {
 public:
  /// near: the disks' centres and `centre` the box's, from one origin.
  bool covers(const std::vector<std::array<double, D>>& near, const std::array<double, D>& centre,
              const std::array<double, D>& edge, double radius2) {
    const std::size_t k = near.size();
    if (k < 2) return false;
    d_.resize(k);
    q_.resize(k);
    double h2 = 0.0;
    for (int a = 0; a < D; ++a) h2 += 0.25 * edge[a] * edge[a];
    const double target = radius2 - h2;
    // Start at the disk whose single-disk value is least.
    std::size_t start = 0;
    double value = std::numeric_limits<double>::infinity(), least_q = value;
    for (std::size_t i = 0; i < k; ++i) {
      double q = 0.0, spread = 0.0;
      for (int a = 0; a < D; ++a) {
        const double d = near[i][a] - centre[a];
        d_[i][a] = d;
        q += d * d;
        spread += edge[a] * std::abs(d);
      }
      q_[i] = q;
      least_q = std::min(least_q, q);
      if (q + spread < value) {
        value = q + spread;
        start = i;
      }
    }
    // Every weighting's value is at least the least |d_i|^2 (a box whose
    // centre no disk reaches is not covered): no search then.
    if (!(least_q < target)) return false;
    double mean_q = q_[start];
    std::array<double, D> m = d_[start];
    for (int step = 0; step < kSteps && !(value < target); ++step) {
      // The edges signed by m's axes once a step: each disk's slope below is
      // then a dot product without branches (the same sums, term for term).
      std::array<double, D> signed_edge;
      for (int a = 0; a < D; ++a) signed_edge[a] = m[a] > 0.0 ? edge[a] : m[a] < 0.0 ? -edge[a] : 0.0;
      // The disk that lowers the value fastest from here.
      std::size_t best = 0;
      double slope = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < k; ++i) {
        double g = q_[i];
        for (int a = 0; a < D; ++a) g += signed_edge[a] * d_[i][a];
        if (g < slope) {
          slope = g;
          best = i;
        }
      }
      // Every weighting's value is at least the least slope (the value is
      // convex, and its linearization here is sum_i w_i g_i): once that
      // reaches the target no weights can prove coverage, and the search
      // stops with the answer it would end with. (It also ends the search
      // when no disk improves on the value, which is at least the target.)
      if (!(slope < target)) return false;
      // The value along (1 - t) w + t e_best is convex and piecewise linear
      // in t: its least is at t = 1 or where some m_a crosses 0.
      const auto& d = d_[best];
      const auto at = [&](double t) {
        double v = (1.0 - t) * mean_q + t * q_[best];
        for (int a = 0; a < D; ++a) v += edge[a] * std::abs((1.0 - t) * m[a] + t * d[a]);
        return v;
      };
      double step_t = 1.0, step_value = at(1.0);
      for (int a = 0; a < D; ++a) {
        if (m[a] == d[a]) continue;
        const double t = m[a] / (m[a] - d[a]);
        if (t > 0.0 && t < 1.0) {
          const double v = at(t);
          if (v < step_value) {
            step_value = v;
            step_t = t;
          }
        }
      }
      if (!(step_value < value)) break;
      mean_q = (1.0 - step_t) * mean_q + step_t * q_[best];
      for (int a = 0; a < D; ++a) m[a] = (1.0 - step_t) * m[a] + step_t * d[a];
      value = mean_q;
      for (int a = 0; a < D; ++a) value += edge[a] * std::abs(m[a]);
    }
    return value < target;
  }

 private:
  static constexpr int kSteps = 24;  // 8 left 18% more sub-cells open in 6D, in the same time
  std::vector<std::array<double, D>> d_;  // the disks' centres, from the box's
  std::vector<double> q_;                 // and their squared distances
};

}  // namespace pds::detail
