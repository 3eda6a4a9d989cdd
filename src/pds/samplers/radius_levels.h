#pragma once
// The neighbour index of the variable-radius samplers (constrained.cpp) from
// 4 dimensions on, and the overflow of flat_levels.h (the 1 to 3 dimensional
// index, which answers the same): is a new point at x with radius r in
// conflict with a stored one, under the rule distance < max(r, r_q)
// (samplers/constraints.h)?
//
// One grid over [rmin, rmax] would cost in proportion to (rmax/rmin)^D cells
// a query (cells sized by rmin, a search out to rmax). Instead points are
// stored by radius level: level l holds radii in [rmin q^l, rmin q^(l+1)),
// q = sqrt(2), in a pds::Grid whose cell edge min(q^(l+1) rmin, rmax) is at
// least every radius it holds, so the points of a level that can conflict
// with x lie in the block of cells around x (3 per axis when the reach is at
// most the edge). Most levels hold nothing near x (in a smooth field one or
// two levels meet anywhere), so every cell of every level keeps a bit per
// other level that may hold a conflicting point: an insert at level l sets
// bit l in the cells of each other level from which a query could conflict
// with it (within the point's radius for the finer levels, whose queries'
// radii are smaller; within the level's largest radius for the coarser
// ones). A query searches its own level and the levels flagged in its own
// cell. Every conflict is found (a test compares with brute force); only the
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
  /// Radii must lie in [rmin, rmax] (the samplers clamp them).
  RadiusLevels(const Domain<D>& domain, double rmin, double rmax) {
    // Level l starts at rmin q^l; the last starts at or below rmax and ends
    // at rmax.
    starts_.push_back(rmin);
    while (static_cast<int>(starts_.size()) < kMaxLevels && starts_.back() * kLevelRatio <= rmax)
      starts_.push_back(starts_.back() * kLevelRatio);
    const int levels = static_cast<int>(starts_.size());
    for (int l = 0; l < levels; ++l) {
      const double edge = l + 1 < levels ? starts_[static_cast<std::size_t>(l) + 1] : rmax;
      levels_.push_back(Level{Grid<D>(domain, edge), edge, {}, 0.0, {}});
      if (levels > 1) levels_.back().others.assign(levels_.back().grid.cell_count(), 0);
    }
  }

  /// True if a stored point q has distance(x, q) < max(r, r_q).
  bool conflicts(const Point<D>& x, double r) const {
    const int own = level_of(r);
    const double r2 = r * r;
    const auto search = [&](int l) {
      const Level& level = levels_[static_cast<std::size_t>(l)];
      if (level.radii.empty()) return false;
      // Finer levels hold radii below r: out to r; the others out to their largest.
      const double reach = l < own ? r : std::max(r, level.max_radius);
      return !level.grid.for_each_within(x, reach, [&](std::int32_t i, double d2) {
        const double rq = level.radii[static_cast<std::size_t>(i)];
        return !(d2 < std::max(r2, rq * rq));
      });
    };
    if (search(own)) return true;
    if (levels() == 1) return false;
    const Level& mine = levels_[static_cast<std::size_t>(own)];
    std::uint32_t flagged = mine.others[mine.grid.cell_of(x)];
    for (int l = 0; flagged; ++l, flagged >>= 1)
      if ((flagged & 1) && search(l)) return true;
    return false;
  }

  /// Stores x (in the domain) with radius r.
  void insert(const Point<D>& x, double r) {
    const int own = level_of(r);
    Level& level = levels_[static_cast<std::size_t>(own)];
    level.grid.insert(x);
    level.radii.push_back(r);
    level.max_radius = std::max(level.max_radius, r);
    const std::uint32_t bit = std::uint32_t{1} << own;
    for (int l = 0; l < levels(); ++l) {
      if (l == own) continue;
      Level& other = levels_[static_cast<std::size_t>(l)];
      // A query at a finer level conflicts within r; at a coarser one, within
      // its own radius, at most that level's edge.
      other.grid.for_each_cell_near(x, l < own ? r : other.edge, [&](std::size_t cell) {
        other.others[cell] |= bit;
        return true;
      });
    }
  }

  /// conflicts() then, if none, insert(); returns whether x was stored.
  bool insert_if_free(const Point<D>& x, double r) {
    if (conflicts(x, r)) return false;
    insert(x, r);
    return true;
  }

  int levels() const { return static_cast<int>(levels_.size()); }

 private:
  // Radii grow by sqrt(2) a level: a cell is at most sqrt(2) times the
  // smallest radius it holds, so a query's 3^D block holds few points. 32
  // levels (a ratio of 2^15.5, about 46,000) fit Level::others's 32 bits
  // (64 bits measured ~7% slower: more memory per cell); larger radii share
  // the last level, still exactly, only slower.
  static constexpr double kLevelRatio = 1.4142135623730951;
  static constexpr int kMaxLevels = 32;

  struct Level {
    Grid<D> grid;
    double edge;                        // the largest radius the level holds
    std::vector<double> radii;          // by the grid's point index
    double max_radius;                  // the largest stored
    std::vector<std::uint32_t> others;  // per cell: a bit per other level that may conflict here
  };

  int level_of(double r) const {
    const auto after = std::upper_bound(starts_.begin(), starts_.end(), r);
    return std::max(0, static_cast<int>(after - starts_.begin()) - 1);
  }

  std::vector<double> starts_;  // the smallest radius of each level
  std::vector<Level> levels_;
};

}  // namespace pds::detail
