#include "pds/analysis/maximality.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pds/analysis/distance.h"
#include "pds/analysis/relative_radius.h"
#include "pds/samplers/random.h"
#include "pds/samplers/regular.h"

namespace pds {
namespace {

// Brute-force covering radius in 2D: the largest distance from a point of the
// domain to its nearest sample. The maximum is attained at a Voronoi vertex
// (circumcentre of three samples), where a Voronoi edge (pair bisector) meets
// the boundary, or at a corner; so the maximum over all such candidates of
// the nearest-sample distance is exact. On a torus, the samples' periodic
// images in the 3x3 neighbouring tiles are used.
double covering_radius_2d(const PointSet<2>& points, const Domain<2>& domain) {
  PointSet<2> sites = points;
  if (domain.periodic)
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        if (dx || dy)
          for (const auto& p : points) sites.push_back({p[0] + dx * domain.extent(0), p[1] + dy * domain.extent(1)});
  auto nearest = [&](Point<2> q) {
    if (domain.periodic)
      q = domain.wrap(q);
    else if (!(q[0] >= domain.lo[0] && q[0] <= domain.hi[0] && q[1] >= domain.lo[1] && q[1] <= domain.hi[1]))
      return 0.0;  // outside the closed box: not a candidate
    double best = INFINITY;
    for (const auto& p : points) best = std::min(best, domain.distance2(p, q));
    return std::sqrt(best);
  };
  double worst = 0;
  const std::size_t n = points.size(), m = sites.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j)
      for (std::size_t k = j + 1; k < m; ++k) {
        const auto &a = sites[i], &b = sites[j], &c = sites[k];
        const double d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
        if (std::abs(d) < 1e-14) continue;
        const double a2 = a[0] * a[0] + a[1] * a[1], b2 = b[0] * b[0] + b[1] * b[1], c2 = c[0] * c[0] + c[1] * c[1];
        worst = std::max(worst, nearest({(a2 * (b[1] - c[1]) + b2 * (c[1] - a[1]) + c2 * (a[1] - b[1])) / d,
                                         (a2 * (c[0] - b[0]) + b2 * (a[0] - c[0]) + c2 * (b[0] - a[0])) / d}));
      }
  if (!domain.periodic) {
    for (double x : {domain.lo[0], domain.hi[0]})
      for (double y : {domain.lo[1], domain.hi[1]}) worst = std::max(worst, nearest({x, y}));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        // Bisector of a and b: points q with (q - mid) . (b - a) = 0.
        const auto &a = points[i], &b = points[j];
        const double mx = 0.5 * (a[0] + b[0]), my = 0.5 * (a[1] + b[1]), ux = b[0] - a[0], uy = b[1] - a[1];
        for (double x : {domain.lo[0], domain.hi[0]})
          if (uy != 0) worst = std::max(worst, nearest({x, my - (x - mx) * ux / uy}));
        for (double y : {domain.lo[1], domain.hi[1]})
          if (ux != 0) worst = std::max(worst, nearest({mx - (y - my) * uy / ux, y}));
      }
  }
  return worst;
}

TEST(Maximality, AgreesWithTheBruteForceCoveringRadius2D) {
  for (bool torus : {false, true})
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const auto domain = torus ? Domain<2>::torus({0, 0}, {1, 1.5}) : Domain<2>::box({-1, 0}, {1, 1});
      const PointSet<2> points = white_noise<2>({14}, domain, seed);
      const double cover = covering_radius_2d(points, domain);
      const auto above = check_maximality(points, domain, cover * (1 + 1e-6));
      EXPECT_TRUE(above.maximal) << domain << " seed " << seed << " cover " << cover;
      EXPECT_EQ(above.tolerance, 0.0);
      const auto below = check_maximality(points, domain, cover * (1 - 1e-6));
      EXPECT_FALSE(below.maximal) << domain << " seed " << seed;
      ASSERT_TRUE(below.gap.has_value());
      EXPECT_TRUE(domain.contains(*below.gap) || !domain.periodic);
      EXPECT_GT(below.gap_distance, cover * (1 - 1e-6));
      EXPECT_LE(below.gap_distance, cover);
    }
}

TEST(Maximality, RegularGridIsCoveredExactlyAtHalfTheCellDiagonal) {
  // Cell centres of an n^D grid: every point is within half a cell diagonal,
  // and the cell corners are exactly that far.
  for (bool torus : {false, true}) {
    const auto d2 = Domain<2>::unit(torus);
    const auto g2 = regular<2>({{20, 20, 1}}, d2);
    const double c2 = std::sqrt(2.0) / 2 / 20;
    EXPECT_TRUE(check_maximality(g2, d2, c2 * (1 + 1e-6)).maximal);
    EXPECT_FALSE(check_maximality(g2, d2, c2 * (1 - 1e-6)).maximal);
    const auto d3 = Domain<3>::unit(torus);
    const auto g3 = regular<3>({{6, 6, 6}}, d3);
    const double c3 = std::sqrt(3.0) / 2 / 6;
    EXPECT_TRUE(check_maximality(g3, d3, c3 * (1 + 1e-6)).maximal);
    EXPECT_FALSE(check_maximality(g3, d3, c3 * (1 - 1e-6)).maximal);
  }
}

TEST(Maximality, ExactTangencyIsReportedWithItsTolerance) {
  // At exactly the covering radius the corners touch the circles: the check
  // cannot prove it either way below its tolerance and says so.
  const auto domain = Domain<2>::unit(true);
  const auto grid = regular<2>({{4, 4, 1}}, domain);
  const auto result = check_maximality(grid, domain, std::sqrt(2.0) / 8, 1e-6);
  EXPECT_TRUE(result.maximal);
  EXPECT_EQ(result.tolerance, 1e-6);
}

TEST(Maximality, WitnessIsFartherThanTheRadiusFromEverySample3D) {
  const auto domain = Domain<3>::unit(false);
  const auto points = white_noise<3>({300}, domain, 9);
  const auto result = check_maximality(points, domain, 0.12);
  ASSERT_FALSE(result.maximal);
  ASSERT_TRUE(result.gap.has_value());
  for (const auto& p : points) EXPECT_GT(domain.distance2(p, *result.gap), 0.12 * 0.12);
  EXPECT_TRUE(check_maximality(points, domain, 2.0).maximal);
}

// The checkerboard lattice D_n (integer points with an even coordinate sum)
// on the torus [0, 2k)^n, which it tiles: minimum distance sqrt 2, covering
// radius 1 in 4D and sqrt(n)/2 from 4D up (the deep hole (1/2, ..., 1/2)).
// With `half`, E8 = D8 and D8 + (1/2, ..., 1/2): covering radius 1.
template <int D>
PointSet<D> checkerboard(int k, bool half = false) {
  PointSet<D> points;
  std::array<int, D> c{};
  while (true) {
    int sum = 0;
    for (int v : c) sum += v;
    if (sum % 2 == 0)
      for (double shift : half ? std::vector<double>{0.0, 0.5} : std::vector<double>{0.0}) {
        Point<D> p;
        for (int i = 0; i < D; ++i) p[i] = c[i] + shift;
        points.push_back(p);
      }
    int a = 0;
    while (a < D && ++c[a] == 2 * k) c[a++] = 0;
    if (a == D) break;
  }
  return points;
}

template <int D>
Domain<D> torus_of(double side) {
  Point<D> lo, hi;
  lo.fill(0.0);
  hi.fill(side);
  return Domain<D>::torus(lo, hi);
}

// Maximal exactly between the covering radius and the minimum distance
// (sqrt 2); a point removed leaves a hole of radius sqrt 2, found.
template <int D>
void check_lattice(PointSet<D> points, const Domain<D>& domain, double covering, double radius) {
  {
    const auto mx = check_maximality(points, domain, radius);
    EXPECT_TRUE(mx.maximal);
    EXPECT_EQ(mx.tolerance, 0.0);
    EXPECT_FALSE(mx.budget_exhausted);
    EXPECT_FALSE(check_maximality(points, domain, 0.97 * covering).maximal);
    points.erase(points.begin() + static_cast<std::ptrdiff_t>(points.size() / 3));
    const auto holed = check_maximality(points, domain, radius);
    ASSERT_FALSE(holed.maximal);
    ASSERT_TRUE(holed.gap.has_value());
    for (const auto& p : points) EXPECT_GT(domain.distance2(p, *holed.gap), radius * radius);
  }
}

TEST(RelativeRadius, DensestLatticesHaveOne) {
  // D4 and E8 are the densest packings in 4D and 8D: rho = 1 (Conway & Sloane).
  const auto d4 = checkerboard<4>(2);
  const auto t4 = torus_of<4>(4.0);
  EXPECT_NEAR(relative_radius(min_distance(d4, t4).distance, t4.volume(), d4.size(), 4), 1.0, 1e-12);
  const auto e8 = checkerboard<8>(1, true);
  const auto t8 = torus_of<8>(2.0);
  EXPECT_NEAR(relative_radius(min_distance(e8, t8).distance, t8.volume(), e8.size(), 8), 1.0, 1e-12);
  // D5 is the densest lattice in 5D too.
  const auto d5 = checkerboard<5>(2);
  const auto t5 = torus_of<5>(4.0);
  EXPECT_NEAR(relative_radius(min_distance(d5, t5).distance, t5.volume(), d5.size(), 5), 1.0, 1e-12);
}

TEST(Maximality, LatticeD4) { check_lattice(checkerboard<4>(2), torus_of<4>(4.0), 1.0, 1.2); }
TEST(Maximality, LatticeD5) {
  check_lattice(checkerboard<5>(2), torus_of<5>(4.0), std::sqrt(5.0) / 2, 0.5 * (std::sqrt(5.0) / 2 + std::sqrt(2.0)));
}
// In 8D the cells needed grow as (r / (r - covering radius))^8: a radius
// near the minimum distance keeps the proof to seconds (1.21 takes 40 s).
TEST(Maximality, LatticeE8) { check_lattice(checkerboard<8>(1, true), torus_of<8>(2.0), 1.0, 1.39); }

TEST(Maximality, OneDimensionAndTheBudget) {
  const auto domain = Domain<1>::unit(false);
  const PointSet<1> points{{{0.1}}, {{0.3}}, {{0.5}}, {{0.7}}, {{0.9}}};
  EXPECT_TRUE(check_maximality(points, domain, 0.1 + 1e-9).maximal);
  EXPECT_FALSE(check_maximality(points, domain, 0.1 - 1e-9).maximal);
  // A budget too small to decide: maximal only up to the cells left whole.
  const auto mx = check_maximality(checkerboard<5>(2), torus_of<5>(4.0), 1.2, 0.0, 50);
  EXPECT_TRUE(mx.maximal);
  EXPECT_TRUE(mx.budget_exhausted);
  EXPECT_GT(mx.tolerance, 0.0);
}

TEST(Maximality, EmptyOrSparseSetsAreNotMaximal) {
  EXPECT_FALSE(check_maximality(PointSet<2>{}, Domain<2>::unit(), 0.1).maximal);
  // Total disk area below the domain's: certain without subdividing.
  EXPECT_FALSE(check_maximality(white_noise<2>({10}, Domain<2>::unit(), 1), Domain<2>::unit(), 0.1).maximal);
  EXPECT_THROW(check_maximality(PointSet<2>{{0.5, 0.5}}, Domain<2>::unit(), 0.0), InvalidArgument);
  EXPECT_THROW(check_maximality(PointSet<2>{{0.5, 0.5}}, Domain<2>::unit(), NAN), InvalidArgument);
}

}  // namespace
}  // namespace pds
