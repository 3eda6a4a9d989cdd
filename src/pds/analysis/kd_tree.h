#pragma once
// An exact k-d tree for the analysis in four and more dimensions, box or
// torus, with the dimension known at run time (Friedman, Bentley & Finkel,
// "An algorithm for finding best matches in logarithmic expected time", ACM
// TOMS 3(3), 1977; the incremental distance to a cell of Arya & Mount,
// "Algorithms for fast vector quantization", DCC 1993).
//
// Why not the background grid: a query within a radius of about the point
// spacing visits (2 ceil(sqrt(D)) + 1)^D cells of a grid whose cells hold
// about one point, 5^4 = 625 in 4D and 7^8 = 5.7 million in 8D; the tree
// visits a few leaves. docs/analysis.md has the measured crossover (the grid
// stays in 2D and 3D).
//
// Exactness: every pruning test compares a lower bound on the squared
// distance to a cell (the sum of the per-axis gaps, each the shorter way
// round on a torus) with the squared distance sought, so a point within the
// radius is never skipped; distances are the domain's own (the shorter
// difference per axis on a torus, as Domain::delta computes it).
//
// Internal to the analysis component (not installed).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace pds::detail {

class KdTree {
 public:
  /// points: n points of `dim` coordinates each, point after point, all in
  /// [lo, hi) per axis; the tree keeps pointers to points, lo and hi.
  KdTree(const double* points, std::size_t n, int dim, const double* lo, const double* hi, bool periodic)
      : points_(points), dim_(dim), lo_(lo), hi_(hi), periodic_(periodic), index_(n) {
    std::iota(index_.begin(), index_.end(), std::int32_t{0});
    if (n > 0) build(0, n);
  }

  /// Squared distance between two points of the domain.
  double distance2(const double* a, const double* b) const {
    double s = 0.0;
    for (int k = 0; k < dim_; ++k) {
      const double d = delta(a[k], b[k], k);
      s += d * d;
    }
    return s;
  }

  /// The stored point nearest to q other than `self` (-1: none excluded):
  /// {index, squared distance}, {-1, inf} if there is none. Ties go to the
  /// smaller index, so the answer does not depend on the tree's shape.
  std::pair<std::int32_t, double> nearest(const double* q, std::int64_t self) const {
    std::pair<std::int32_t, double> best{-1, std::numeric_limits<double>::infinity()};
    Search s{q, std::vector<double>(static_cast<std::size_t>(dim_), 0.0), cell_bounds(), best.second};
    auto leaf = [&](std::int32_t i, double d2) {
      if (i != self && (d2 < best.second || (d2 == best.second && i < best.first))) best = {i, d2};
      return best.second;
    };
    if (!nodes_.empty()) visit(0, s, 0.0, leaf);
    return best;
  }

  /// Calls f(index, squared distance) for every stored point within r of q
  /// (distance <= r); f returns false to stop. Returns false if stopped.
  template <class F>
  bool for_each_within(const double* q, double r, F&& f) const {
    if (nodes_.empty()) return true;
    const double r2 = r * r;
    bool go_on = true;
    Search s{q, std::vector<double>(static_cast<std::size_t>(dim_), 0.0), cell_bounds(), r2};
    auto leaf = [&](std::int32_t i, double d2) {
      if (d2 <= r2 && !f(i, d2)) go_on = false;
      return go_on ? r2 : -1.0;  // -1 prunes every cell: the search stops
    };
    visit(0, s, 0.0, leaf);
    return go_on;
  }

 private:
  static constexpr std::size_t kLeafSize = 8;

  struct Node {
    std::size_t begin, end;  // the points index_[begin, end)
    int axis = -1;           // -1: a leaf
    double split = 0.0;      // left: coordinate <= split, right: >= split
    std::int32_t left = -1, right = -1;
  };

  struct Search {
    const double* q;
    std::vector<double> gap;                    // per-axis gap from q to the current cell
    std::vector<std::pair<double, double>> cell;  // the current cell's bounds per axis
    double limit;                                 // squared distance beyond which cells are skipped
  };

  const double* point(std::int32_t i) const { return points_ + static_cast<std::size_t>(i) * dim_; }

  double delta(double a, double b, int k) const {
    double d = b - a;
    if (periodic_) {
      const double L = hi_[k] - lo_[k];
      if (d > 0.5 * L)
        d -= L;
      else if (d < -0.5 * L)
        d += L;
    }
    return d;
  }

  std::vector<std::pair<double, double>> cell_bounds() const {
    std::vector<std::pair<double, double>> c(static_cast<std::size_t>(dim_));
    for (int k = 0; k < dim_; ++k) c[k] = {lo_[k], hi_[k]};
    return c;
  }

  // The distance along axis k from x to the interval [a, b] (0 inside), the
  // shorter way round on a torus.
  double gap_to(double x, double a, double b, int k) const {
    double g = x < a ? a - x : (x > b ? x - b : 0.0);
    if (periodic_ && g > 0.0) {
      g = std::min(g, x < a ? (x - lo_[k]) + (hi_[k] - b) : (hi_[k] - x) + (a - lo_[k]));
    }
    return std::max(g, 0.0);
  }

  std::int32_t build(std::size_t begin, std::size_t end) {
    const auto id = static_cast<std::int32_t>(nodes_.size());
    nodes_.push_back({begin, end});
    if (end - begin <= kLeafSize) return id;
    // Split the axis of largest spread at the median.
    int axis = 0;
    double spread = -1.0;
    for (int k = 0; k < dim_; ++k) {
      double a = std::numeric_limits<double>::infinity(), b = -a;
      for (std::size_t i = begin; i < end; ++i) {
        const double x = point(index_[i])[k];
        a = std::min(a, x);
        b = std::max(b, x);
      }
      if (b - a > spread) {
        spread = b - a;
        axis = k;
      }
    }
    if (!(spread > 0.0)) return id;  // all points equal: one leaf
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(index_.begin() + static_cast<std::ptrdiff_t>(begin),
                     index_.begin() + static_cast<std::ptrdiff_t>(mid), index_.begin() + static_cast<std::ptrdiff_t>(end),
                     [&](std::int32_t a, std::int32_t b) { return point(a)[axis] < point(b)[axis]; });
    const double split = point(index_[mid])[axis];
    nodes_[id].axis = axis;
    nodes_[id].split = split;
    const std::int32_t left = build(begin, mid);
    const std::int32_t right = build(mid, end);
    nodes_[id].left = left;
    nodes_[id].right = right;
    return id;
  }

  // Depth first, nearer child first. `leaf` is called for every point of a
  // visited leaf and returns the squared distance beyond which cells are
  // skipped from then on (s.limit; negative stops the search). `bound` is the
  // squared distance from q to the node's cell.
  template <class Leaf>
  void visit(std::int32_t id, Search& s, double bound, Leaf& leaf) const {
    const Node& node = nodes_[static_cast<std::size_t>(id)];
    if (node.axis < 0) {
      for (std::size_t i = node.begin; i < node.end && s.limit >= 0.0; ++i)
        s.limit = leaf(index_[i], distance2(s.q, point(index_[i])));
      return;
    }
    const int k = node.axis;
    const auto saved = s.cell[k];
    const double saved_gap = s.gap[k];
    const bool left_first = s.q[k] <= node.split;
    for (int side = 0; side < 2; ++side) {
      const bool go_left = (side == 0) == left_first;
      s.cell[k] = go_left ? std::make_pair(saved.first, node.split) : std::make_pair(node.split, saved.second);
      const double g = gap_to(s.q[k], s.cell[k].first, s.cell[k].second, k);
      const double child_bound = bound - saved_gap * saved_gap + g * g;
      s.gap[k] = g;
      // A hair of slack: the bound is updated incrementally and may round up.
      if (child_bound * (1.0 - 1e-12) <= s.limit) visit(go_left ? node.left : node.right, s, child_bound, leaf);
    }
    s.cell[k] = saved;
    s.gap[k] = saved_gap;
  }

  const double* points_;
  int dim_;
  const double* lo_;
  const double* hi_;
  bool periodic_;
  std::vector<std::int32_t> index_;
  std::vector<Node> nodes_;
};

}  // namespace pds::detail
