#pragma once
// The neighbour index of the variable-radius samplers (constrained.cpp): is
// a new point at x with radius r in conflict with a stored one, under the
// rule distance < max(r, r_q) (samplers/constraints.h)?
//
// One grid over [rmin, rmax] would cost in proportion to (rmax/rmin)^D cells
// a query (cells sized by rmin, a search out to rmax). Instead points are
// stored by radius level: level l holds radii in [rmin 2^l, rmin 2^(l+1)),
// in a pds::Grid whose cell edge min(2^(l+1) rmin, rmax) is at least every radius it
// holds, so the points at a level that can conflict with x lie in the block
// of cells around x (3 per axis when r is at most the edge). A query at level
// L searches the levels >= L out to max(r, the largest radius stored there),
// and the finer levels, whose radii are below r, out to r: those are
// usually far from x (a sparse sample in a dense region is rare in a smooth
// field), so each level >= 1 also counts, per cell, the points of the levels
// below it, and the finer levels are read only when a cell around x holds
// some. Every conflict is found (a test compares with brute force); only the
// work depends on the field.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "pds/domain.h"
#include "pds/grid.h"
#include "pds/point.h"

namespace pds::detail {

template <int D>
class RadiusLevels {
 public:
  /// Radii outside [rmin, rmax] are accepted (they land in the end levels)
  /// and still handled exactly, only slower.
  RadiusLevels(const Domain<D>& domain, double rmin, double rmax) : rmin_(rmin) {
    int levels = 1;
    while (levels < kMaxLevels && rmin * static_cast<double>(std::uint64_t{1} << levels) <= rmax) ++levels;
    for (int l = 0; l < levels; ++l) {
      const double edge = std::min(rmax, rmin * static_cast<double>(std::uint64_t{2} << l));
      levels_.push_back(Level{Grid<D>(domain, edge), {}, 0.0, {}});
      if (l > 0) levels_.back().below.assign(levels_.back().grid.cell_count(), 0);
    }
  }

  /// True if a stored point q has distance(x, q) < max(r, r_q).
  bool conflicts(const Point<D>& x, double r) const {
    const int own = level_of(r);
    const double r2 = r * r;
    const auto closer = [&](const Level& level, double reach) {
      return !level.grid.for_each_within(x, reach, [&](std::int32_t i, double d2) {
        const double rq = level.radii[static_cast<std::size_t>(i)];
        return !(d2 < std::max(r2, rq * rq));
      });
    };
    for (int l = own; l < levels(); ++l) {
      const Level& level = levels_[static_cast<std::size_t>(l)];
      if (!level.radii.empty() && closer(level, std::max(r, level.max_radius))) return true;
    }
    if (own == 0) return false;
    const Level& mine = levels_[static_cast<std::size_t>(own)];
    const bool finer_near = !mine.grid.for_each_cell_near(x, r, [&](std::size_t cell) { return mine.below[cell] == 0; });
    if (!finer_near) return false;
    for (int l = 0; l < own; ++l)
      if (closer(levels_[static_cast<std::size_t>(l)], r)) return true;
    return false;
  }

  /// Stores x (in the domain) with radius r.
  void insert(const Point<D>& x, double r) {
    const int own = level_of(r);
    Level& level = levels_[static_cast<std::size_t>(own)];
    level.grid.insert(x);
    level.radii.push_back(r);
    level.max_radius = std::max(level.max_radius, r);
    for (int l = own + 1; l < levels(); ++l) {
      Level& coarser = levels_[static_cast<std::size_t>(l)];
      ++coarser.below[coarser.grid.cell_of(x)];
    }
  }

  int levels() const { return static_cast<int>(levels_.size()); }

 private:
  // 2^40 covers any radius ratio a grid at rmin can hold in memory.
  static constexpr int kMaxLevels = 40;

  struct Level {
    Grid<D> grid;
    std::vector<double> radii;  // by the grid's point index
    double max_radius;
    std::vector<std::uint32_t> below;  // points of finer levels, per cell (levels >= 1)
  };

  int level_of(double r) const {
    int l = 0;
    while (l + 1 < levels() && r >= rmin_ * static_cast<double>(std::uint64_t{2} << l)) ++l;
    return l;
  }

  double rmin_;
  std::vector<Level> levels_;
};

}  // namespace pds::detail
