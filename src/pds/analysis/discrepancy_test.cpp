#include "pds/analysis/discrepancy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pds/error.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

/// The L2-star discrepancy by integrating the squared local discrepancy
/// exactly, cell by cell of the grid that the points' coordinates cut the
/// unit cube into: on a cell the count A is constant and
///   integral (A/N - prod y)^2 = (A/N)^2 vol - 2 (A/N) prod int y + prod int y^2.
/// Independent of Warnock's formula; O(N^(D+1)).
template <int D>
double l2_star_brute_force(const PointSet<D>& points, const Domain<D>& domain) {
  std::array<std::vector<double>, D> cuts;
  std::vector<std::array<double, D>> u;
  for (const auto& p : points) {
    std::array<double, D> q;
    for (int a = 0; a < D; ++a) q[a] = (p[a] - domain.lo[a]) / domain.extent(a);
    u.push_back(q);
  }
  for (int a = 0; a < D; ++a) {
    cuts[a] = {0.0, 1.0};
    for (const auto& q : u) cuts[a].push_back(q[a]);
    std::sort(cuts[a].begin(), cuts[a].end());
  }
  const double n = static_cast<double>(points.size());
  double total = 0;
  std::array<std::size_t, D> cell{};
  while (true) {
    double vol = 1, m1 = 1, m2 = 1;
    std::array<double, D> mid;
    for (int a = 0; a < D; ++a) {
      const double lo = cuts[a][cell[a]], hi = cuts[a][cell[a] + 1];
      vol *= hi - lo;
      m1 *= (hi * hi - lo * lo) / 2;
      m2 *= (hi * hi * hi - lo * lo * lo) / 3;
      mid[a] = 0.5 * (lo + hi);
    }
    if (vol > 0) {
      double count = 0;  // points in [0, y) for y inside the cell: u < y everywhere there means u <= lo
      for (const auto& q : u) {
        bool in = true;
        for (int a = 0; a < D; ++a) in = in && q[a] < mid[a];
        count += in;
      }
      const double f = count / n;
      total += f * f * vol - 2 * f * m1 + m2;
    }
    int a = 0;
    while (a < D && ++cell[a] == cuts[a].size() - 1) cell[a++] = 0;
    if (a == D) break;
  }
  return std::sqrt(total);
}

/// D* by its definition over the critical corners: every corner y with each
/// coordinate a point's coordinate or 1, every point tested against it,
/// open boxes for vol - A/N and closed ones for A/N - vol. O(N^(D+1)).
template <int D>
double star_brute_force(const PointSet<D>& points) {
  std::array<std::vector<double>, D> grid;
  for (int a = 0; a < D; ++a) {
    for (const auto& p : points) grid[a].push_back(p[a]);
    grid[a].push_back(1.0);
  }
  const double n = static_cast<double>(points.size());
  double best = 0;
  std::array<std::size_t, D> index{};
  while (true) {
    double vol = 1;
    for (int a = 0; a < D; ++a) vol *= grid[a][index[a]];
    int open = 0, closed = 0;
    for (const auto& p : points) {
      bool o = true, c = true;
      for (int a = 0; a < D; ++a) {
        o = o && p[a] < grid[a][index[a]];
        c = c && p[a] <= grid[a][index[a]];
      }
      open += o;
      closed += c;
    }
    best = std::max({best, vol - open / n, closed / n - vol});
    int a = 0;
    while (a < D && ++index[a] == grid[a].size()) index[a++] = 0;
    if (a == D) break;
  }
  return best;
}

TEST(StarDiscrepancy, SweepMatchesTheDefinition) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto points = white_noise<2>({60}, Domain<2>::unit(), seed);
    EXPECT_NEAR(star_discrepancy(points, Domain<2>::unit()), star_brute_force(points), 1e-14) << seed;
    const auto points3 = white_noise<3>({15}, Domain<3>::unit(), seed);
    EXPECT_NEAR(star_discrepancy(points3, Domain<3>::unit()), star_brute_force(points3), 1e-14) << seed;
  }
  // Shared coordinates (ties between points, and points on the grid lines).
  PointSet<2> ties;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j) ties.push_back({{i / 5.0, (j % 2) / 4.0 + 0.5 * (i % 2)}});
  EXPECT_NEAR(star_discrepancy(ties, Domain<2>::unit()), star_brute_force(ties), 1e-14);
}

TEST(L2StarDiscrepancy, MatchesBruteForceIntegration) {
  const auto box2 = Domain<2>::box({-1, 2}, {3, 2.5});
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto points = white_noise<2>({25}, box2, seed);
    EXPECT_NEAR(l2_star_discrepancy(points, box2), l2_star_brute_force(points, box2), 1e-12);
  }
  const auto cube = Domain<3>::unit();
  const auto points3 = white_noise<3>({12}, cube, 9);
  EXPECT_NEAR(l2_star_discrepancy(points3, cube), l2_star_brute_force(points3, cube), 1e-12);
}

TEST(Discrepancy, TinySetsByHand) {
  const auto unit = Domain<2>::unit();
  // One point at the centre: T^2 = 1/9 - (1/2)(3/4)^2 + (1/2)^2.
  const PointSet<2> centre{{{0.5, 0.5}}};
  EXPECT_NEAR(l2_star_discrepancy(centre, unit), std::sqrt(1.0 / 9 - 0.28125 + 0.25), 1e-15);
  // D*: the closed box [0, 1/2]^2 holds the point with volume 1/4: 3/4.
  EXPECT_NEAR(star_discrepancy(centre, unit), 0.75, 1e-15);
  // The 2 x 2 grid at quarters: sum_i prod (1 - u^2) = (15/16 + 7/16)^2,
  // sum_ij prod (1 - max) = (3/4 + 1/4 + 1/4 + 1/4)^2.
  const PointSet<2> grid{{{0.25, 0.25}}, {{0.75, 0.25}}, {{0.25, 0.75}}, {{0.75, 0.75}}};
  EXPECT_NEAR(l2_star_discrepancy(grid, unit),
              std::sqrt(1.0 / 9 - 0.5 / 4 * std::pow(22.0 / 16, 2) + std::pow(1.5, 2) / 16), 1e-15);
  // D*: the closed box [0, 3/4]^2 holds all four points with volume 9/16:
  // 7/16. (Open boxes give at most 5/16: [0, 3/4)^2 holds one point.)
  EXPECT_NEAR(star_discrepancy(grid, unit), 7.0 / 16, 1e-15);
}

TEST(StarDiscrepancy, BoundsEveryBoxAndTheL2Norm) {
  // D* is the supremum of |A/N - vol| over anchored boxes: no box may exceed
  // it, and it is at least the root mean square (the L2-star discrepancy).
  const auto domain = Domain<2>::box({0, 0}, {2, 1});
  const auto points = white_noise<2>({40}, domain, 3);
  const double d = star_discrepancy(points, domain);
  EXPECT_GE(d, l2_star_discrepancy(points, domain));
  Rng rng(4);
  double best = 0;
  for (int t = 0; t < 20000; ++t) {
    const double y0 = rng.uniform(), y1 = rng.uniform();
    int count = 0;
    for (const auto& p : points) count += p[0] / 2 < y0 && p[1] < y1;
    best = std::max(best, std::abs(count / 40.0 - y0 * y1));
  }
  EXPECT_LE(best, d + 1e-15);
  // Random corners come close to the supremum (within 1/N here).
  EXPECT_GT(best, d - 1.0 / 40);
  // 3D, the single centre point: the closed box [0, 1/2]^3 gives 1 - 1/8.
  EXPECT_NEAR(star_discrepancy(PointSet<3>{{{0.5, 0.5, 0.5}}}, Domain<3>::unit()), 0.875, 1e-15);
}

TEST(Discrepancy, RejectsBadInput) {
  EXPECT_THROW(l2_star_discrepancy(PointSet<2>{}, Domain<2>::unit()), InvalidArgument);
  EXPECT_THROW(star_discrepancy(PointSet<2>{}, Domain<2>::unit()), InvalidArgument);
  EXPECT_THROW(l2_star_discrepancy(PointSet<2>{{{1.5, 0.5}}}, Domain<2>::unit()), InvalidArgument);
  EXPECT_FALSE(star_discrepancy_feasible(100000, 2));
  EXPECT_TRUE(star_discrepancy_feasible(9000, 2));
  EXPECT_THROW(star_discrepancy(white_noise<2>({20000}, Domain<2>::unit(), 1), Domain<2>::unit()), InvalidArgument);
}

}  // namespace
}  // namespace pds
