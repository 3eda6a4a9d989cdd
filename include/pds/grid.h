#pragma once
// A uniform background grid over a Domain for neighbour queries within a
// radius, on boxes and tori.
//
// Cells have edge at most radius/sqrt(D) (their diagonal is at most the
// radius), so in a set whose points are at least `radius` apart each cell holds
// at most one point. Any number of points per cell is still handled (a linked
// list through the points), so the grid also serves arbitrary point sets.
// The cell count per axis is a whole number that divides the extent exactly,
// which makes the cells line up across a torus's seam.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "pds/detail/format.h"
#include "pds/domain.h"
#include "pds/error.h"
#include "pds/grid_neighbourhood.h"
#include "pds/point.h"

namespace pds {

/// The most cells a Grid allocates (4 bytes each): 1 GiB.
inline constexpr std::size_t kMaxGridCells = std::size_t{1} << 28;

template <int D>
class Grid {
 public:
  /// A grid whose cells have edge at most `max_cell_edge` along every axis.
  /// Throws InvalidArgument if the edge is not positive and finite or if more
  /// than `max_cells` cells would be needed.
  Grid(const Domain<D>& domain, double max_cell_edge, std::size_t max_cells = kMaxGridCells) : domain_(domain) {
    if (!(max_cell_edge > 0.0) || !std::isfinite(max_cell_edge))
      throw InvalidArgument("grid: cell edge must be positive and finite, got " + detail::format_number(max_cell_edge));
    double total = 1.0;
    std::array<int, D> cells;
    for (int i = 0; i < D; ++i) {
      const double n = std::max(1.0, std::ceil(domain.extent(i) / max_cell_edge));
      total *= n;
      if (total > static_cast<double>(max_cells))
        throw InvalidArgument("grid: cell edge " + detail::format_number(max_cell_edge) +
                              " is too small for the domain: the neighbour grid would need more than " +
                              std::to_string(max_cells) + " cells");
      cells[i] = static_cast<int>(n);
      inv_edge_[i] = n / domain.extent(i);
    }
    hood_ = GridNeighbourhood<D>(domain, cells);
    head_.assign(hood_.size(), -1);
    for (int i = 0; i < D; ++i)
      extent_scale_ = std::max({extent_scale_, std::abs(domain.lo[i]), std::abs(domain.hi[i])});
  }

  /// `edge`, doubled until a grid of that edge would have at most max_cells
  /// cells: a thin axis would otherwise make far more cells than points.
  static double edge_for_at_most(const Domain<D>& domain, double edge, double max_cells) {
    for (;;) {
      double cells = 1.0;
      for (int i = 0; i < D; ++i) cells *= std::max(1.0, std::ceil(domain.extent(i) / edge));
      if (cells <= max_cells) return edge;
      edge *= 2.0;
    }
  }

  /// The grid for points at least `radius` apart: cell edge radius/sqrt(D).
  static Grid for_radius(const Domain<D>& domain, double radius, std::size_t max_cells = kMaxGridCells) {
    return Grid(domain, radius / std::sqrt(static_cast<double>(D)), max_cells);
  }

  /// The grid that answers "is any point closer than radius" fastest: in the
  /// plane and space the one-point-a-cell grid of for_radius (a 2D query
  /// reads 21 cells); from 4 dimensions cells of edge `radius`, several
  /// points a cell, because the block around a query grows as
  /// (2 sqrt(D) + 1)^D cells with edge radius/sqrt(D) (9^4 = 6,561 in 4D,
  /// 7^8 = 5.8 million in 8D) but as 3^D with edge radius, of which the
  /// pruned walk (for_each_cell_near) visits about sum_k C(D,k) V_k (V_k the
  /// volume of the unit k-ball): 50 in 4D, 255 in 6D, 1,166 in 8D.
  static Grid for_conflicts(const Domain<D>& domain, double radius, std::size_t max_cells = kMaxGridCells) {
    if constexpr (D <= 3) return for_radius(domain, radius, max_cells);
    // Fewer, larger cells when the domain would need too many: still correct.
    double cells = 1.0;
    for (int i = 0; i < D; ++i) cells *= std::max(1.0, std::ceil(domain.extent(i) / radius));
    const double widen = std::max(1.0, std::pow(cells / static_cast<double>(max_cells), 1.0 / D) * 1.01);
    return Grid(domain, radius * widen, max_cells);
  }

  const Domain<D>& domain() const { return domain_; }
  const PointSet<D>& points() const { return points_; }
  /// Hands the stored points over without a copy; the grid is spent. A
  /// sampler's output is usually its grid's whole content, and a copy of it
  /// beside the grid would be the run's peak.
  PointSet<D> take_points() && { return std::move(points_); }
  std::size_t size() const { return points_.size(); }
  /// Room for n points, so that a sampler that knows its count never holds
  /// a vector and its doubled copy at once.
  void reserve(std::size_t n) {
    points_.reserve(n);
    next_.reserve(n);
  }
  std::size_t cell_count() const { return head_.size(); }
  /// Whether no stored point lies in cell `cell` (0 <= cell < cell_count()).
  bool cell_empty(std::size_t cell) const { return head_[cell] < 0; }
  int cells(int axis) const { return hood_.cells(axis); }
  double cell_edge(int axis) const { return hood_.edge(axis); }
  /// The cell arithmetic (windows, stencils) of this grid.
  const GridNeighbourhood<D>& neighbourhood() const { return hood_; }

  /// Cell coordinate of x along one axis, clamped into the grid.
  int cell_coord(double x, int axis) const {
    const double last = static_cast<double>(hood_.cells(axis) - 1);
    const double c = std::clamp((x - domain_.lo[axis]) * inv_edge_[axis], 0.0, last);
    return static_cast<int>(c);  // not negative: the truncation is the floor
  }

  std::size_t cell_of(const Point<D>& p) const {
    std::size_t c = 0;
    for (int i = 0; i < D; ++i) c += static_cast<std::size_t>(cell_coord(p[i], i)) * hood_.stride(i);
    return c;
  }

  /// Stores p (which must lie in the domain) and returns its index.
  std::int32_t insert(const Point<D>& p) {
    if (points_.size() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
      throw InvalidArgument("grid: more than 2^31 - 1 points");
    const auto index = static_cast<std::int32_t>(points_.size());
    const std::size_t c = cell_of(p);
    points_.push_back(p);
    next_.push_back(head_[c]);
    head_[c] = index;
    return index;
  }

  /// Moves stored point `index` to p (which must lie in the domain). Walks
  /// its old cell's list to unlink it, so cells should hold few points.
  void move(std::int32_t index, const Point<D>& p) {
    const auto i = static_cast<std::size_t>(index);
    std::int32_t* link = &head_[cell_of(points_[i])];
    while (*link != index) link = &next_[static_cast<std::size_t>(*link)];
    *link = next_[i];
    const std::size_t c = cell_of(p);
    points_[i] = p;
    next_[i] = head_[c];
    head_[c] = index;
  }
  /// Calls f(index, distance2) for every stored point q with
  /// distance(p, q) <= r; f returns false to stop early. Returns false if
  /// stopped.
  template <class F>
  bool for_each_within(const Point<D>& p, double r, F&& f) const {
    const double r2 = r * r;
    return for_each_cell_near(p, r, [&](std::size_t cell) {
      for (std::int32_t i = head_[cell]; i >= 0; i = next_[static_cast<std::size_t>(i)]) {
        const double d2 = domain_.distance2(p, points_[static_cast<std::size_t>(i)]);
        if (d2 <= r2 && !f(i, d2)) return false;
      }
      return true;
    });
  }

  /// Calls f(index, distance2) for the points stored in p's own cell; f
  /// returns false to stop early. Returns false if stopped. (A cheap first
  /// look before a walk: p's cell is the one a walk would visit first.)
  template <class F>
  bool for_each_in_own_cell(const Point<D>& p, F&& f) const {
    for (std::int32_t i = head_[cell_of(p)]; i >= 0; i = next_[static_cast<std::size_t>(i)])
      if (!f(i, domain_.distance2(p, points_[static_cast<std::size_t>(i)]))) return false;
    return true;
  }

  /// True if some stored point lies strictly closer than r to p.
  bool any_closer_than(const Point<D>& p, double r) const { return find_closer_than(p, r) >= 0; }

  /// The index of a stored point strictly closer than r to p (the first the
  /// walk meets), or -1 if there is none.
  std::int32_t find_closer_than(const Point<D>& p, double r) const {
    const double r2 = r * r;
    std::int32_t found = -1;
    for_each_cell_near(p, r, [&](std::size_t cell) {
      for (std::int32_t i = head_[cell]; i >= 0; i = next_[static_cast<std::size_t>(i)])
        if (domain_.distance2(p, points_[static_cast<std::size_t>(i)]) < r2) {
          found = i;
          return false;
        }
      return true;
    });
    return found;
  }

  /// Calls f(cell) for every cell that may hold a point within distance r of
  /// p, each cell once; f returns false to stop. Returns false if stopped.
  template <class F>
  bool for_each_cell_near(const Point<D>& p, double r, F&& f) const {
    // A small widening keeps a point at distance exactly r inside the range
    // despite the rounding of the cell arithmetic; extra cells cost nothing.
    r = r * (1.0 + 1e-12) + 1e-12 * extent_scale_;
    std::array<int, D> first, last;
    for (int i = 0; i < D; ++i) {
      const double x = p[i] - domain_.lo[i];
      // Clamped before the cast: a radius of many cells along a thin axis
      // would not fit an int, and a window past the box, or longer than a
      // period of a torus, takes the whole axis anyway.
      const double bound = static_cast<double>(hood_.cells(i)) + 1.0;
      first[i] = clamped_floor((x - r) * inv_edge_[i], bound);
      last[i] = clamped_floor((x + r) * inv_edge_[i], bound);
    }
    if constexpr (D >= 4) {
      return for_each_cell_pruned(p, r, first, last, f);
    } else {
      return hood_.for_each_cell(hood_.window(first, last),
                                 [&](std::size_t cell, const std::array<int, D>&) { return f(cell); });
    }
  }

 private:
  // floor(v) clamped into [-bound, 2 bound] (bound a whole number), as an
  // int: clamped before the cast, then truncated and corrected below zero
  // (std::floor is a long instruction sequence on baseline x86-64).
  static int clamped_floor(double v, double bound) {
    v = std::clamp(v, -bound, 2.0 * bound);
    const int t = static_cast<int>(v);
    return t - (v < t);
  }

  // The cells of the block [first, last] whose gap to p is at most r, each
  // once: per axis the candidate cells (wrapped on a torus, clipped in a box)
  // with their squared gap to p (the smallest over a cell's images), then a
  // depth-first walk over the axes that drops a branch once the summed
  // squared gaps pass r^2. The whole block has 3^D cells or more; the walk
  // visits those the ball around p reaches (the 2D and 3D blocks are small,
  // so they take the plain window).
  template <class F>
  bool for_each_cell_pruned(const Point<D>& p, double r, const std::array<int, D>& first,
                            const std::array<int, D>& last, F& f) const {
    struct Candidate {
      std::size_t offset;
      double gap2;
    };
    constexpr int kMaxPerAxis = 8;
    std::array<std::array<Candidate, kMaxPerAxis>, D> axis_cells;
    std::array<int, D> counts{};
    const double r2 = r * r;
    for (int a = 0; a < D; ++a) {
      const int n = hood_.cells(a);
      const double edge = hood_.edge(a);
      const double x = p[a] - domain_.lo[a];
      int lo = first[a], hi = last[a];
      if (!hood_.periodic()) {
        lo = std::max(lo, 0);
        hi = std::min(hi, n - 1);
      } else if (hi - lo + 1 > n) {
        lo = 0;  // the block spans a period: every cell once, at its nearest image
        hi = n - 1;
      }
      if (hi - lo + 1 > kMaxPerAxis)  // fine cells (an analysis grid): the plain window
        return hood_.for_each_cell(hood_.window(first, last),
                                   [&](std::size_t cell, const std::array<int, D>&) { return f(cell); });
      const bool whole_period = hood_.periodic() && last[a] - first[a] + 1 > n;
      std::array<Candidate, kMaxPerAxis> block;
      int count = 0;
      for (int u = lo; u <= hi; ++u) {
        int periods = 0, cell = u;
        if (hood_.periodic()) cell = hood_.wrap(u, a, periods);
        // The gap to the image at u; over a whole period, to the nearest of
        // the cell's images (x lies in [0, L), so one period either way).
        double gap = std::max(0.0, std::max(u * edge - x, x - (u + 1) * edge));
        if (whole_period)
          for (const double shift : {-domain_.extent(a), domain_.extent(a)})
            gap = std::min(gap, std::max({0.0, u * edge + shift - x, x - (u + 1) * edge - shift}));
        if (gap * gap > r2) continue;
        block[count++] = {static_cast<std::size_t>(cell) * hood_.stride(a), gap * gap};
      }
      counts[a] = count;
      // Nearest first along every axis, so the walk starts at p's own cell
      // (a conflict query usually stops there), ties in the block's order
      // (a stable sort) so that the order is the same on every platform.
      auto& sorted = axis_cells[a];
      if (whole_period) {
        // Gaps to the nearest image: an insertion sort (a few cells;
        // std::stable_sort allocates).
        std::copy_n(block.begin(), count, sorted.begin());
        for (int i = 1; i < count; ++i)
          for (int j = i; j > 0 && sorted[j].gap2 < sorted[j - 1].gap2; --j) std::swap(sorted[j], sorted[j - 1]);
      } else {
        // Along a run of cells the gap falls to p's cell and rises after it
        // (strictly, but for the zeros of a p on a face), so the sorted order
        // merges the cells before the first nearest one, walked backwards,
        // with the rest, walked forwards: a merge, not a sort (the per-axis
        // set-up was most of a 4D conflict query's instructions).
        if (count == 3 && block[1].gap2 < block[0].gap2 && block[1].gap2 <= block[2].gap2) {
          // p's cell between its two neighbours (nearly always from 4D,
          // where cells have edge about r): the nearer neighbour second.
          const bool lower_first = block[0].gap2 <= block[2].gap2;
          sorted[0] = block[1];
          sorted[1] = block[lower_first ? 0 : 2];
          sorted[2] = block[lower_first ? 2 : 0];
          continue;
        }
        int m = 0;
        for (int i = 1; i < count; ++i)
          if (block[i].gap2 < block[m].gap2) m = i;
        int left = m - 1, right = m;
        for (int k = 0; k < count; ++k)
          sorted[k] =
              (right == count || (left >= 0 && block[left].gap2 <= block[right].gap2)) ? block[left--] : block[right++];
      }
    }
    return walk<0>(axis_cells, counts, 0, 0.0, r2, f);
  }

  template <int A, class Cells, class F>
  bool walk(const Cells& cells, const std::array<int, D>& counts, std::size_t index, double gap2, double r2,
            F& f) const {
    for (int k = 0; k < counts[A]; ++k) {
      const double g = gap2 + cells[A][k].gap2;
      if (g > r2) break;  // each axis's cells are sorted by gap: the rest are farther
      if constexpr (A + 1 == D) {
        if (!f(index + cells[A][k].offset)) return false;
      } else {
        if (!walk<A + 1>(cells, counts, index + cells[A][k].offset, g, r2, f)) return false;
      }
    }
    return true;
  }

  Domain<D> domain_;
  GridNeighbourhood<D> hood_;
  std::array<double, D> inv_edge_{};
  double extent_scale_ = 0.0;
  std::vector<std::int32_t> head_;
  std::vector<std::int32_t> next_;
  PointSet<D> points_;
};

}  // namespace pds
