#include "pds/analysis/discrepancy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "pds/error.h"
#include "pds/parallel.h"
#include "pds/progress.h"
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

// Uniform random points in any dimension (the samplers' white noise is
// instantiated for the plane and space only).
template <int D>
PointSet<D> uniform_points(std::size_t n, const Domain<D>& domain, std::uint64_t seed) {
  Rng rng(seed);
  PointSet<D> points(n);
  for (auto& p : points)
    for (int k = 0; k < D; ++k) p[k] = domain.lo[k] + rng.uniform() * domain.extent(k);
  return points;
}

// Points of a Kronecker sequence, x_ik = frac((i + 1) sqrt(p_k)), which
// NumPy computes to the same doubles (one product, one subtraction).
PointCloud kronecker(std::size_t n, int dim) {
  static constexpr int kPrimes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37};
  PointCloud cloud{dim, {}};
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < dim; ++k) {
      const double v = static_cast<double>(i + 1) * std::sqrt(static_cast<double>(kPrimes[k]));
      cloud.coords.push_back(v - std::floor(v));
    }
  return cloud;
}

// scipy.stats.qmc.discrepancy(kronecker(n, d), method=m) for m = L2-star, CD,
// WD, MD, computed once with SciPy 1.10.1 (Debian's python3-scipy):
//   x[i, k] = (i + 1) * sqrt(p_k) - floor(...); repr(qmc.discrepancy(x, method=m))
// python/tests/test_analysis.py compares with SciPy itself.
struct SciPyReference {
  std::size_t n;
  int dim;
  double l2_star, cd, wd, md;
};
constexpr SciPyReference kSciPy[] = {
    {64, 1, 0.010071956091196191, 0.0001014442995002085, 0.00011015756671639565, 0.00010580093309631167},
    {64, 3, 0.017906536444515925, 0.0013659044491265426, 0.0019263403790326095, 0.0023361292988739457},
    {100, 10, 0.002447945390009849, 0.030466102625993585, 0.15873075575536078, 0.5908331313236488},
    {257, 5, 0.008251642741613456, 0.0013449361400879045, 0.002266521147612721, 0.003586170960197421},
};

TEST(Discrepancy, EqualsSciPyInAnyDimension) {
  for (const auto& ref : kSciPy) {
    const PointCloud x = kronecker(ref.n, ref.dim);
    const double expected[] = {ref.l2_star, ref.cd, ref.wd, ref.md};
    for (std::size_t m = 0; m < kDiscrepancyMethods.size(); ++m) {
      const double got = discrepancy(x, kDiscrepancyMethods[m]);
      EXPECT_NEAR(got, expected[m], 1e-12 * expected[m])
          << discrepancy_method_name(kDiscrepancyMethods[m]) << ", " << ref.n << " points in " << ref.dim << "D";
    }
  }
}

TEST(Discrepancy, ClosedFormsForOnePoint) {
  // One point at the centre of [0, 1]: CD^2 = 13/12 - 2 + 1 = 1/12,
  // MD^2 = 19/12 - 10/3 + 15/8 = 1/8, T^2 = 1/3 - 3/4 + 1/2 = 1/12; for any
  // single point WD^2 = (3/2)^D - (4/3)^D.
  const PointCloud centre{1, {0.5}};
  EXPECT_NEAR(discrepancy(centre, DiscrepancyMethod::Centered), 1.0 / 12, 1e-15);
  EXPECT_NEAR(discrepancy(centre, DiscrepancyMethod::Mixture), 1.0 / 8, 1e-15);
  EXPECT_NEAR(discrepancy(centre, DiscrepancyMethod::L2Star), std::sqrt(1.0 / 12), 1e-15);
  for (int d : {1, 4, 9}) {
    const PointCloud one{d, std::vector<double>(static_cast<std::size_t>(d), 0.3)};
    EXPECT_NEAR(discrepancy(one, DiscrepancyMethod::WrapAround), std::pow(1.5, d) - std::pow(4.0 / 3.0, d), 1e-13);
  }
}

TEST(Discrepancy, TypedL2StarIsTheRunTimeOneAndScalingIsDocumented) {
  const auto domain = Domain<3>::box({-1, 0, 2}, {1, 4, 2.5});
  const auto points = white_noise<3>({200}, domain, 5);
  const PointCloud cloud = PointCloud::from(points);
  const std::vector<double> lo(domain.lo.begin(), domain.lo.end()), hi(domain.hi.begin(), domain.hi.end());
  EXPECT_EQ(l2_star_discrepancy(points, domain), discrepancy(cloud, lo, hi, DiscrepancyMethod::L2Star));
  PointCloud unit = cloud;
  for (std::size_t k = 0; k < unit.coords.size(); ++k)
    unit.coords[k] = (unit.coords[k] - lo[k % 3]) / (hi[k % 3] - lo[k % 3]);
  for (const auto m : kDiscrepancyMethods) EXPECT_EQ(discrepancy(cloud, lo, hi, m), discrepancy(unit, m));
}

TEST(Discrepancy, SameBitsForAnyThreadCount) {
  const PointCloud x = kronecker(700, 7);
  for (const auto m : kDiscrepancyMethods) {
    double one, four;
    {
      ThreadLimit limit(1);
      one = discrepancy(x, m);
    }
    {
      ThreadLimit limit(4);
      four = discrepancy(x, m);
    }
    EXPECT_EQ(one, four) << discrepancy_method_name(m);
  }
}

TEST(Discrepancy, RunTimeNamesAndBadInput) {
  for (const auto m : kDiscrepancyMethods) EXPECT_EQ(parse_discrepancy_method(discrepancy_method_name(m)), m);
  EXPECT_THROW(parse_discrepancy_method("cd"), InvalidArgument);
  EXPECT_THROW(discrepancy(PointCloud{2, {}}, DiscrepancyMethod::Centered), InvalidArgument);
  EXPECT_THROW(discrepancy(PointCloud{2, {0.5, 1.5}}, DiscrepancyMethod::Centered), InvalidArgument);
  EXPECT_THROW(discrepancy(PointCloud{2, {0.5, NAN}}, DiscrepancyMethod::WrapAround), InvalidArgument);
  // The closed cube, as SciPy: 1 is accepted.
  EXPECT_NO_THROW(discrepancy(PointCloud{2, {1.0, 0.0}}, DiscrepancyMethod::Mixture));
  const std::vector<double> lo{0, 0}, hi{2, 2};
  EXPECT_THROW(discrepancy(PointCloud{2, {0.5, 2.5}}, lo, hi, DiscrepancyMethod::Centered), InvalidArgument);
  EXPECT_THROW(discrepancy(PointCloud{3, {0.5, 0.5, 0.5}}, lo, hi, DiscrepancyMethod::Centered), InvalidArgument);
}

// 1,100 points: two blocks of rows (953 and 147), each heard; the same
// double with and without a callback, and a stop between blocks cancels.
TEST(Discrepancy, ReportsRowsDoneWithinOneMeasureAndCanBeStopped) {
  const PointCloud x = kronecker(1100, 3);
  for (const DiscrepancyMethod method : kDiscrepancyMethods) {
    std::vector<std::pair<double, double>> reports;
    const Progress progress{[&](double done, double total) {
      reports.emplace_back(done, total);
      return true;
    }};
    const double with = discrepancy(x, method, progress);
    EXPECT_EQ(with, discrepancy(x, method)) << discrepancy_method_name(method);
    ASSERT_EQ(reports.size(), 3u) << discrepancy_method_name(method);  // 0, then after each block
    for (std::size_t i = 0; i < reports.size(); ++i) {
      EXPECT_EQ(reports[i].second, 1100.0);
      if (i > 0) {
        EXPECT_GT(reports[i].first, reports[i - 1].first);
      }
    }
    EXPECT_EQ(reports[1].first, 953.0);
    EXPECT_EQ(reports.back().first, 1100.0);
    const Progress stop{[](double done, double) { return done < 900; }};
    EXPECT_THROW(discrepancy(x, method, stop), Cancelled) << discrepancy_method_name(method);
  }
}

TEST(Discrepancy, TypedInstancesUpToEightDimensions) {
  // Star >= L2-star (a supremum over the boxes against their root mean square).
  const auto d5 = Domain<5>::unit();
  const auto p5 = uniform_points<5>(12, d5, 2);
  EXPECT_GE(star_discrepancy(p5, d5), l2_star_discrepancy(p5, d5));
  const auto d8 = Domain<8>::unit();
  const auto p8 = uniform_points<8>(300, d8, 2);
  const PointCloud c8 = PointCloud::from(p8);
  EXPECT_EQ(l2_star_discrepancy(p8, d8), discrepancy(c8, DiscrepancyMethod::L2Star));
  const auto d1 = Domain<1>::unit();
  const auto p1 = uniform_points<1>(50, d1, 2);
  EXPECT_GE(star_discrepancy(p1, d1), l2_star_discrepancy(p1, d1));
}

}  // namespace
}  // namespace pds
