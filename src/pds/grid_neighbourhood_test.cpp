#include "pds/grid_neighbourhood.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "pds/grid.h"
#include "pds/rng.h"
#include "pds/samplers/bridson.h"
#include "pds/samplers/ebeida.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

// Grids that have broken neighbour arithmetic before: thin boxes (one cell
// across, cells far narrower along one axis than another), tori with periods
// of one, two and three cells, and ordinary ones.
template <int D>
struct Layout {
  Domain<D> domain;
  std::array<int, D> cells;
};

std::vector<Layout<2>> layouts2() {
  std::vector<Layout<2>> out;
  for (const bool torus : {false, true}) {
    const auto make = [&](Point<2> lo, Point<2> hi, std::array<int, 2> n) {
      out.push_back({torus ? Domain<2>::torus(lo, hi) : Domain<2>::box(lo, hi), n});
    };
    make({0, 0}, {1, 1}, {9, 9});
    make({0, 0}, {1, 0.01}, {40, 1});   // thin: one cell across
    make({0, 0}, {1, 0.05}, {12, 2});   // two cells across
    make({-1, 2}, {0.5, 2.3}, {3, 1});  // periods of one and three cells
    make({0, 0}, {0.2, 3}, {2, 17});    // different widths
    make({0, 0}, {1, 1}, {1, 1});
    make({0, 0}, {1, 1}, {2, 2});
  }
  return out;
}

std::vector<Layout<3>> layouts3() {
  std::vector<Layout<3>> out;
  for (const bool torus : {false, true}) {
    const auto make = [&](Point<3> lo, Point<3> hi, std::array<int, 3> n) {
      out.push_back({torus ? Domain<3>::torus(lo, hi) : Domain<3>::box(lo, hi), n});
    };
    make({0, 0, 0}, {1, 1, 1}, {5, 5, 5});
    make({0, 0, 0}, {1, 0.02, 0.5}, {7, 1, 2});
    make({0, 0, 0}, {0.1, 1, 2}, {2, 6, 3});
  }
  return out;
}

template <int D>
std::string describe(const Layout<D>& l) {
  std::string s = l.domain.periodic ? "torus" : "box";
  for (int a = 0; a < D; ++a) {
    s += ' ';
    s += std::to_string(l.cells[a]);
    s += 'x';
    s += std::to_string(l.domain.extent(a));
  }
  return s;
}

template <int D>
std::vector<std::array<int, D>> all_cells(const std::array<int, D>& n) {
  std::vector<std::array<int, D>> out;
  std::array<int, D> c{};
  while (true) {
    out.push_back(c);
    int a = 0;
    while (a < D && ++c[a] == n[a]) c[a++] = 0;
    if (a == D) return out;
  }
}

// Windows around a centre cell: every cell whose coordinate along each axis
// lies within the reach of the centre's (on a torus: of some periodic image
// of it), each exactly once; `seam` exactly when coordinates are not the
// nearest images' (a torus window crossing the seam or spanning a period).
template <int D>
void check_windows(const Layout<D>& l) {
  const GridNeighbourhood<D> hood(l.domain, l.cells);
  for (const auto& centre : all_cells<D>(l.cells))
    for (int r : {0, 1, 2, 3, 5}) {
      std::array<int, D> reach;
      for (int a = 0; a < D; ++a) reach[a] = (r + a) % 4;  // a different reach per axis
      const auto w = hood.window_around(centre, reach);
      std::multiset<std::size_t> seen;
      hood.for_each_cell(w, [&](std::size_t index, const std::array<int, D>& c) {
        EXPECT_EQ(hood.index(c), index);
        seen.insert(index);
        return true;
      });
      std::multiset<std::size_t> expected;
      bool seam = false;
      for (const auto& x : all_cells<D>(l.cells)) {
        bool near = true;
        for (int a = 0; a < D; ++a) {
          const int n = l.cells[a];
          bool axis = false;
          for (int k = l.domain.periodic ? -3 : 0; k <= (l.domain.periodic ? 3 : 0); ++k)
            axis = axis || std::abs(x[a] + k * n - centre[a]) <= reach[a];
          near = near && axis;
        }
        if (near) expected.insert(hood.index(x));
      }
      for (int a = 0; a < D; ++a)
        seam = seam || (l.domain.periodic && (centre[a] - reach[a] < 0 || centre[a] + reach[a] >= l.cells[a] ||
                                              2 * reach[a] + 1 >= l.cells[a]));
      EXPECT_EQ(seen, expected) << describe(l);
      EXPECT_EQ(w.seam, seam) << describe(l);
      if (!w.seam) {
        // Rows: each starts a run of count[0] consecutive cells; together
        // they are the window's cells, in for_each_cell's order.
        std::vector<std::size_t> by_cell, by_row;
        hood.for_each_cell(w, [&](std::size_t index, const std::array<int, D>&) {
          by_cell.push_back(index);
          return true;
        });
        hood.for_each_row(w, [&](std::size_t first) {
          for (int k = 0; k < w.count[0]; ++k) by_row.push_back(first + static_cast<std::size_t>(k));
        });
        EXPECT_EQ(by_row, by_cell) << describe(l);
      }
    }
}

TEST(GridNeighbourhood, WindowsMatchBruteForce) {
  for (const auto& l : layouts2()) check_windows(l);
  for (const auto& l : layouts3()) check_windows(l);
}

// The smallest distance from p to a point of cell x, over the periodic images
// of the cell on a torus: by brute force over images.
template <int D>
double distance_to_cell(const Layout<D>& l, const GridNeighbourhood<D>& hood, const Point<D>& p,
                        const std::array<int, D>& x) {
  double total = 0.0;
  for (int a = 0; a < D; ++a) {
    double best = INFINITY;
    for (int k = l.domain.periodic ? -3 : 0; k <= (l.domain.periodic ? 3 : 0); ++k) {
      const double lo = l.domain.lo[a] + x[a] * hood.edge(a) + k * l.domain.extent(a), hi = lo + hood.edge(a);
      best = std::min(best, p[a] < lo ? lo - p[a] : (p[a] > hi ? p[a] - hi : 0.0));
    }
    total += best * best;
  }
  return std::sqrt(total);
}

// Windows around a point: the block of cells that [x - r, x + r] touches
// along each axis holds every cell within distance r of p, each once.
template <int D>
void check_point_windows(const Layout<D>& l, std::uint64_t seed) {
  const GridNeighbourhood<D> hood(l.domain, l.cells);
  Rng rng(seed);
  for (int q = 0; q < 300; ++q) {
    const Point<D> p = uniform_point(rng, l.domain);
    const double r = rng.uniform() * 0.8 * l.domain.extent(q % D) + 1e-3;
    std::array<int, D> lo, hi;
    for (int a = 0; a < D; ++a) {
      lo[a] = static_cast<int>(std::floor((p[a] - l.domain.lo[a] - r) / hood.edge(a)));
      hi[a] = static_cast<int>(std::floor((p[a] - l.domain.lo[a] + r) / hood.edge(a)));
    }
    std::map<std::size_t, int> seen;
    hood.for_each_cell(hood.window(lo, hi), [&](std::size_t index, const std::array<int, D>&) {
      ++seen[index];
      return true;
    });
    for (const auto& [index, times] : seen) EXPECT_EQ(times, 1) << describe(l);
    for (const auto& x : all_cells<D>(l.cells)) {
      if (distance_to_cell<D>(l, hood, p, x) < r * (1 - 1e-9)) {
        EXPECT_TRUE(seen.count(hood.index(x))) << describe(l) << " p " << p << " r " << r;
      }
    }
  }
}

TEST(GridNeighbourhood, PointWindowsHoldEveryCellWithinTheDistance) {
  std::uint64_t seed = 1;
  for (const auto& l : layouts2()) check_point_windows(l, seed++);
  for (const auto& l : layouts3()) check_point_windows(l, seed++);
}

// Stencils: for every cell, the images it lists are exactly the (cell, whole
// periods) pairs whose box lies closer than the distance to the centre cell's
// box (gaps measured between the boxes' faces), each once; on a box only
// cells inside. any() visits the same cells in the same order, and the
// interior shortcut agrees with the wrapped path.
template <int D>
void check_stencils(const Layout<D>& l) {
  const GridNeighbourhood<D> hood(l.domain, l.cells);
  double widest = 0.0;
  for (int a = 0; a < D; ++a) widest = std::max(widest, hood.edge(a));
  for (const double r : {0.37 * widest, 1.13 * widest, 2.71 * widest, 0.6 * l.domain.extent(0)}) {
    const auto stencil = hood.stencil_within(r);
    for (std::size_t k = 1; k < stencil.steps.size(); ++k)
      EXPECT_LE(hood.gap2(stencil.steps[k - 1]), hood.gap2(stencil.steps[k])) << "nearest first";
    for (const auto& c : all_cells<D>(l.cells)) {
      const std::size_t cell = hood.index(c);
      using Image = std::pair<std::size_t, std::array<int, D>>;
      std::multiset<Image> listed;
      std::vector<std::size_t> order;
      hood.for_each_image(stencil, c, cell, [&](std::size_t index, const std::array<int, D>& periods) {
        listed.insert({index, periods});
        order.push_back(index);
      });
      std::vector<std::size_t> any_order;
      EXPECT_FALSE(hood.any(stencil, c, cell, [&](std::size_t index) {
        any_order.push_back(index);
        return false;
      }));
      EXPECT_EQ(any_order, order);
      std::multiset<Image> expected;
      std::array<int, D> K{};  // periods to try along each axis
      for (int a = 0; a < D; ++a) K[a] = l.domain.periodic ? 2 + static_cast<int>(r / l.domain.extent(a)) : 0;
      for (const auto& x : all_cells<D>(l.cells)) {
        std::array<int, D> k;
        for (int a = 0; a < D; ++a) k[a] = -K[a];
        while (true) {
          bool self = true;
          double gap2 = 0.0;
          for (int a = 0; a < D; ++a) {
            // Faces of the two boxes along this axis, in cells.
            const int u = x[a] + k[a] * l.cells[a];
            const double gap = std::max({0.0, (u - (c[a] + 1)) * hood.edge(a), (c[a] - (u + 1)) * hood.edge(a)});
            gap2 += gap * gap;
            self = self && u == c[a];
          }
          if (!self && gap2 < r * r) expected.insert({hood.index(x), k});
          int a = 0;
          while (a < D && ++k[a] > K[a]) {
            k[a] = -K[a];
            ++a;
          }
          if (a == D) break;
        }
      }
      ASSERT_EQ(listed, expected) << describe(l) << " r " << r << " cell " << cell;
    }
  }
}

TEST(GridNeighbourhood, StencilsListEveryImageWithinTheDistance) {
  for (const auto& l : layouts2()) check_stencils(l);
  for (const auto& l : layouts3()) check_stencils(l);
}

TEST(GridNeighbourhood, FilterKeepsTheOrder) {
  const GridNeighbourhood<2> hood(Domain<2>::unit(true), {10, 10});
  const auto all = hood.stencil_within(0.25);
  const auto axis = hood.filter(all, [](const std::array<int, 2>& s) { return s[1] == 0; });
  std::vector<std::array<int, 2>> expected;
  for (const auto& s : all.steps)
    if (s[1] == 0) expected.push_back(s);
  EXPECT_EQ(axis.steps, expected);
  ASSERT_EQ(axis.linear.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_EQ(axis.linear[k], expected[k][0]);
  EXPECT_EQ(axis.reach[1], 0);
}

TEST(GridNeighbourhood, WrapCountsWholePeriods) {
  const GridNeighbourhood<2> hood(Domain<2>::torus({0, 0}, {1, 1}), {3, 1});
  for (int u = -10; u <= 10; ++u) {
    int periods = 99;
    const int w = hood.wrap(u, 0, periods);
    EXPECT_GE(w, 0);
    EXPECT_LT(w, 3);
    EXPECT_EQ(w + 3 * periods, u);
    EXPECT_EQ(hood.wrap(u, 1, periods), 0);
    EXPECT_EQ(periods, u);
  }
}

// The Grid built on it, on the thin and short layouts above: every neighbour
// query equals the all-pairs answer.
template <int D>
void check_grid(const Domain<D>& domain, double radius, std::uint64_t seed) {
  const PointSet<D> points = white_noise<D>({300}, domain, seed);
  Grid<D> grid = Grid<D>::for_radius(domain, radius);
  for (const auto& p : points) grid.insert(p);
  Rng rng(seed + 1);
  for (int q = 0; q < 100; ++q) {
    const Point<D> p = uniform_point(rng, domain);
    for (const double r : {0.5 * radius, radius, 3.3 * radius}) {
      std::vector<int> found, expected;
      grid.for_each_within(p, r, [&](std::int32_t i, double) {
        found.push_back(i);
        return true;
      });
      for (std::size_t i = 0; i < points.size(); ++i)
        if (domain.distance2(p, points[i]) <= r * r) expected.push_back(static_cast<int>(i));
      std::sort(found.begin(), found.end());
      EXPECT_EQ(found, expected) << domain << " r " << r;
    }
  }
}

TEST(GridNeighbourhood, GridOnThinBoxesAndShortTori) {
  for (const bool torus : {false, true}) {
    const auto make2 = [&](Point<2> lo, Point<2> hi) {
      return torus ? Domain<2>::torus(lo, hi) : Domain<2>::box(lo, hi);
    };
    check_grid<2>(make2({0, 0}, {1, 0.003}), 0.05, 1);  // one cell across
    check_grid<2>(make2({0, 0}, {1, 0.06}), 0.05, 2);   // two cells across
    check_grid<2>(make2({0, 0}, {0.04, 0.09}), 0.05, 3);
    const auto make3 = [&](Point<3> lo, Point<3> hi) {
      return torus ? Domain<3>::torus(lo, hi) : Domain<3>::box(lo, hi);
    };
    check_grid<3>(make3({0, 0, 0}, {1, 0.01, 0.3}), 0.1, 4);
  }
}

}  // namespace
}  // namespace pds

namespace pds {
namespace {

// An axis 1e-140 wide under a radius of 0.1 (found by the generation
// fuzzer: the reach overflowed an int). A box needs no cell beyond its own,
// so the samplers work; a torus would need 10^139 images and is refused.
TEST(GridNeighbourhood, AxesFarThinnerThanTheDistance) {
  const Point<2> lo{{0.0, 0.0}}, hi{{1e-140, 1.0}};
  // Bridson's annulus rarely lands in so thin a box (it is not maximal);
  // ebeida fills it: about one sample per radius along the long axis.
  EXPECT_GE(bridson<2>({.radius = 0.1}, Domain<2>::box(lo, hi), 1).size(), 1u);
  EXPECT_GE(ebeida<2>({.radius = 0.1}, Domain<2>::box(lo, hi), 1).size(), 6u);
  EXPECT_THROW(bridson<2>({.radius = 0.1}, Domain<2>::torus(lo, hi), 1), InvalidArgument);
  EXPECT_THROW(ebeida<2>({.radius = 0.1}, Domain<2>::torus(lo, hi), 1), InvalidArgument);
}

}  // namespace
}  // namespace pds
