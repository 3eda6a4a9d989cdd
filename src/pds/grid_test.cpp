#include "pds/grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "pds/rng.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

// The order of the pruned walk (from 4D), rebuilt the slow way: along each
// axis the block's cells with their gaps to p (to the nearest image when the
// block spans a period), stably sorted by gap, then every combination in
// lexicographic order whose summed squared gaps stay within r^2. Callers sum
// over neighbours in this order, so it must not depend on how the sort is done.
template <int D>
std::optional<std::vector<std::size_t>> expected_walk(const Grid<D>& grid, const Point<D>& p, double r) {
  const Domain<D>& domain = grid.domain();
  const auto& hood = grid.neighbourhood();
  double scale = 0.0;
  for (int a = 0; a < D; ++a) scale = std::max({scale, std::abs(domain.lo[a]), std::abs(domain.hi[a])});
  r = r * (1.0 + 1e-12) + 1e-12 * scale;  // the grid's widening
  std::array<std::vector<std::pair<double, std::size_t>>, D> axis;
  for (int a = 0; a < D; ++a) {
    const double x = p[a] - domain.lo[a], edge = hood.edge(a), inv_edge = hood.cells(a) / domain.extent(a);
    const int n = hood.cells(a);
    int lo = static_cast<int>(std::floor((x - r) * inv_edge)), hi = static_cast<int>(std::floor((x + r) * inv_edge));
    const bool whole = domain.periodic && hi - lo + 1 > n;
    if (whole) {  // every cell once, at its nearest image
      lo = 0;
      hi = n - 1;
    } else if (!domain.periodic) {
      lo = std::max(lo, 0);
      hi = std::min(hi, n - 1);
    }
    if (hi - lo + 1 > 8) return std::nullopt;  // fine cells: the grid takes the plain window
    for (int u = lo; u <= hi; ++u) {
      double gap = std::max({0.0, u * edge - x, x - (u + 1) * edge});
      if (whole)
        for (double shift : {-domain.extent(a), domain.extent(a)})
          gap = std::min(gap, std::max({0.0, u * edge + shift - x, x - (u + 1) * edge - shift}));
      if (gap * gap > r * r) continue;
      int periods = 0;
      const int cell = domain.periodic ? hood.wrap(u, a, periods) : u;
      axis[a].push_back({gap * gap, static_cast<std::size_t>(cell) * hood.stride(a)});
    }
    std::stable_sort(axis[a].begin(), axis[a].end(), [](const auto& s, const auto& t) { return s.first < t.first; });
  }
  std::vector<std::size_t> cells;
  const auto walk = [&](auto&& self, int a, std::size_t index, double gap2) -> void {
    for (const auto& [g, offset] : axis[a]) {
      if (gap2 + g > r * r) break;
      if (a + 1 == D)
        cells.push_back(index + offset);
      else
        self(self, a + 1, index + offset, gap2 + g);
    }
  };
  walk(walk, 0, 0, 0.0);
  return cells;
}

// Every neighbour query of the grid equals the brute-force answer, for points
// near the faces and corners, on boxes and tori, with radii around and above
// the cell size.
template <int D>
void check_against_brute_force(const Domain<D>& domain, double grid_radius, std::uint64_t seed,
                               bool conflicts = false) {
  const PointSet<D> points = white_noise<D>({.count = 400}, domain, seed);
  Grid<D> grid = conflicts ? Grid<D>::for_conflicts(domain, grid_radius) : Grid<D>::for_radius(domain, grid_radius);
  for (const auto& p : points) grid.insert(p);
  ASSERT_EQ(grid.size(), points.size());
  if (!conflicts) {
    for (int i = 0; i < D; ++i) EXPECT_LE(grid.cell_edge(i), grid_radius / std::sqrt(double(D)) * (1 + 1e-12));
  }

  Rng rng(seed + 1);
  for (int q = 0; q < 200; ++q) {
    Point<D> p = uniform_point(rng, domain);
    if (q % 4 == 0) p[0] = domain.lo[0];                               // on a face
    if (q % 4 == 1) p[D - 1] = std::nextafter(domain.hi[D - 1], 0.0);  // on the far face
    for (double r : {0.5 * grid_radius, grid_radius, 2.7 * grid_radius, 0.6 * domain.extent(0)}) {
      std::vector<int> found, expected;
      grid.for_each_within(p, r, [&](std::int32_t i, double d2) {
        EXPECT_DOUBLE_EQ(d2, domain.distance2(p, points[i]));
        found.push_back(i);
        return true;
      });
      for (std::size_t i = 0; i < points.size(); ++i)
        if (domain.distance2(p, points[i]) <= r * r) expected.push_back(static_cast<int>(i));
      std::sort(found.begin(), found.end());
      EXPECT_EQ(found, expected) << domain << " query " << p << " r " << r;
      EXPECT_EQ(grid.any_closer_than(p, r), std::any_of(expected.begin(), expected.end(),
                                                        [&](int i) { return domain.distance2(p, points[i]) < r * r; }));
      const std::int32_t closer = grid.find_closer_than(p, r);
      if (closer >= 0) {
        EXPECT_LT(domain.distance2(p, points[static_cast<std::size_t>(closer)]), r * r);
      }
      if constexpr (D >= 4) {
        if (const auto expected_cells = expected_walk(grid, p, r)) {
          std::vector<std::size_t> walked;
          grid.for_each_cell_near(p, r, [&](std::size_t cell) {
            walked.push_back(cell);
            return true;
          });
          EXPECT_EQ(walked, *expected_cells) << domain << " query " << p << " r " << r;
        }
      }
    }
  }
}

TEST(Grid, MatchesBruteForceOnBoxAndTorus2D) {
  check_against_brute_force<2>(Domain<2>::unit(false), 0.07, 1);
  check_against_brute_force<2>(Domain<2>::unit(true), 0.07, 2);
  check_against_brute_force<2>(Domain<2>::torus({-2, 1}, {1, 2.5}), 0.13, 3);
}

// A radius of far more cells than an int holds along a thin axis (it was
// undefined behaviour in the cell arithmetic, found by the sanitizers): the
// window takes the whole axis, in a box and on a torus.
TEST(Grid, RadiusOfMoreCellsThanAnIntHolds) {
  for (bool torus : {false, true}) {
    const Domain<2> domain{{0, 0}, {1e-150, 1e150}, torus};
    const PointSet<2> points = white_noise<2>({.count = 50}, domain, 9);
    Grid<2> grid(domain, 1e145);  // one cell across, 10^5 along
    for (const auto& p : points) grid.insert(p);
    for (double r : {1e-100, 1.0, 1e145, 1e300}) {
      std::vector<int> found, expected;
      grid.for_each_within(points[0], r, [&](std::int32_t i, double) {
        found.push_back(i);
        return true;
      });
      for (std::size_t i = 0; i < points.size(); ++i)
        if (domain.distance2(points[0], points[i]) <= r * r) expected.push_back(static_cast<int>(i));
      std::sort(found.begin(), found.end());
      EXPECT_EQ(found, expected) << "torus " << torus << " r " << r;
    }
  }
}

// Moved points are found at their new place only, with their index kept,
// whether they stay in their cell or leave it, first or last in its list.
TEST(Grid, MovedPointsAreFoundWhereTheyWent) {
  const auto domain = Domain<2>::unit(true);
  PointSet<2> points = white_noise<2>({.count = 300}, domain, 7);
  Grid<2> grid(domain, 0.2);  // several points a cell
  for (const auto& p : points) grid.insert(p);
  Rng rng(8);
  for (int m = 0; m < 500; ++m) {
    const auto i = static_cast<std::int32_t>(rng.below(points.size()));
    Point<2> to = points[static_cast<std::size_t>(i)];
    to[0] += m % 2 ? 1e-3 : 0.3;  // the same cell, or another
    to = domain.wrap(to);
    grid.move(i, to);
    points[static_cast<std::size_t>(i)] = to;
  }
  ASSERT_EQ(grid.size(), points.size());
  EXPECT_EQ(grid.points(), points);
  for (int q = 0; q < 100; ++q) {
    const Point<2> p = uniform_point(rng, domain);
    std::vector<int> found, expected;
    grid.for_each_within(p, 0.15, [&](std::int32_t i, double) {
      found.push_back(i);
      return true;
    });
    for (std::size_t i = 0; i < points.size(); ++i)
      if (domain.distance2(p, points[i]) <= 0.15 * 0.15) expected.push_back(static_cast<int>(i));
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected) << "query " << p;
  }
}

TEST(Grid, MatchesBruteForceOnBoxAndTorus3D) {
  check_against_brute_force<3>(Domain<3>::unit(false), 0.15, 4);
  check_against_brute_force<3>(Domain<3>::unit(true), 0.15, 5);
  check_against_brute_force<3>(Domain<3>::box({0, 0, 0}, {2, 1, 0.5}), 0.2, 6);
}

// From 4D the walk over neighbouring cells is pruned by the gap to the query
// (and sorted nearest first); for_conflicts' cells have edge r. Tori whose
// periods hold 1, 2 or 3 cells make the images of one cell meet.
template <int D>
void check_high_dimension(std::uint64_t seed) {
  Point<D> lo, hi;
  for (int a = 0; a < D; ++a) {
    lo[a] = -0.5 * a;
    hi[a] = lo[a] + (a == 0 ? 1.0 : a == 1 ? 0.25 : a == 2 ? 0.45 : 0.7);
  }
  for (bool torus : {false, true}) {
    const Domain<D> domain{lo, hi, torus};
    check_against_brute_force<D>(domain, 0.21, seed, true);  // for_conflicts: pruned walk
    // Finer cells: the pruned walk, or the plain window past 8 cells an axis.
    if (D == 4) check_against_brute_force<D>(domain, 0.21, seed, false);
  }
}

TEST(Grid, MatchesBruteForceFrom4To8Dimensions) {
  check_high_dimension<4>(11);
  check_high_dimension<5>(12);
  check_high_dimension<6>(13);
  check_high_dimension<8>(14);
}

TEST(Grid, CellsDivideTheTorusPeriodExactly) {
  const auto torus = Domain<2>::torus({0, 0}, {1, 3});
  const auto grid = Grid<2>::for_radius(torus, 0.1);
  for (int i = 0; i < 2; ++i) EXPECT_DOUBLE_EQ(grid.cell_edge(i) * grid.cells(i), torus.extent(i));
}

TEST(Grid, FindsANeighbourExactlyAcrossTheSeam) {
  const auto torus = Domain<2>::unit(true);
  Grid<2> grid = Grid<2>::for_radius(torus, 0.1);
  grid.insert({0.995, 0.5});
  EXPECT_TRUE(grid.any_closer_than({0.005, 0.5}, 0.0100001));
  EXPECT_FALSE(grid.any_closer_than({0.005, 0.5}, 0.0099999));
  Grid<2> box = Grid<2>::for_radius(Domain<2>::unit(false), 0.1);
  box.insert({0.995, 0.5});
  EXPECT_FALSE(box.any_closer_than({0.005, 0.5}, 0.1));
}

TEST(Grid, RefusesAGridThatWouldNotFitInMemory) {
  EXPECT_THROW(Grid<2>::for_radius(Domain<2>::unit(), 1e-9), InvalidArgument);
  EXPECT_THROW(Grid<3>::for_radius(Domain<3>::unit(), 1e-4), InvalidArgument);
  EXPECT_THROW(Grid<2>(Domain<2>::unit(), 0.0), InvalidArgument);
  EXPECT_THROW(Grid<2>(Domain<2>::unit(), NAN), InvalidArgument);
}

}  // namespace
}  // namespace pds
