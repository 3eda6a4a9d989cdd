#include "pds/samplers/ebeida.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "nn_statistics.h"
#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"
#include "pds/analysis/relative_radius.h"
#include "pds/error.h"
#include "pds/progress.h"
#include "pds/samplers/jones.h"
#include "set_checks.h"

namespace pds {
namespace {

template <int D>
void check_set(double r) {
  for (bool torus : {false, true}) {
    const auto domain = testing_stats::offset_domain<D>(torus);
    const auto points = ebeida<D>({r}, domain, 5);
    ASSERT_GT(points.size(), 1000u);
    EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, r));
    // Maximal dart throwing packs to rho ~0.77 in 2D and ~0.80 in 3D; a box
    // packs denser (samples at a face have fewer neighbours).
    const double rho = relative_radius(r, domain.volume(), points.size(), D);
    EXPECT_GT(rho, D == 2 ? 0.74 : 0.78) << domain;
    EXPECT_LT(rho, D == 2 ? 0.80 : 0.87) << domain;
    if (torus) {
      // The saturation coverage of random sequential adsorption, disks of
      // diameter r: 0.547069 in 2D (Hinrichsen, Feder, Jossang 1986) and
      // 0.384131 in 3D (Torquato, Uche, Stillinger 2006); the count spread at
      // these sizes is under 1%.
      const double ball = D == 2 ? M_PI / 4.0 * r * r : M_PI / 6.0 * r * r * r;
      const double coverage = static_cast<double>(points.size()) * ball / domain.volume();
      EXPECT_NEAR(coverage, D == 2 ? 0.547069 : 0.384131, 0.03 * coverage) << domain;
    }
    EXPECT_EQ(points, ebeida<D>({r}, domain, 5));
    EXPECT_NE(points, ebeida<D>({r}, domain, 6));
  }
}

TEST(Ebeida, MinimumDistanceMaximalInsideAndReproducible2D) { check_set<2>(0.02); }
TEST(Ebeida, MinimumDistanceMaximalInsideAndReproducible3D) { check_set<3>(0.07); }

// A level's sub-cell codes take 4 bytes while they fit 32 bits (levels 1-16
// in 2D) and 16 past that. With seeds 33, 39, 48, 54 and 57 (of 150 tried)
// this set keeps a real gap open past level 16 and places a sample there:
// codes cut to 32 bits at those levels lose it (the set comes out one sample
// short and not maximal). All five, so that a change of the random streams
// leaves some seed that reaches that deep.
TEST(Ebeida, CodesPastSixteenLevelsFinishMaximal) {
  const double r = 0.004;
  const auto torus = Domain<2>::torus({0.0, 0.0}, {0.5, 0.5});
  for (const std::uint64_t seed : {33, 39, 48, 54, 57}) {
    const auto points = ebeida<2>({r}, torus, seed);
    ASSERT_GT(points.size(), 10000u);
    EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, torus, r)) << "seed " << seed;
  }
}

// Tiny domains: a torus of a few cells (neighbour offsets wrap onto the same
// cells) and a radius larger than the domain (one sample covers it).
TEST(Ebeida, SmallDomains) {
  for (bool torus : {false, true}) {
    const auto domain = Domain<2>::unit(torus);
    const auto points = ebeida<2>({0.3}, domain, 3);
    EXPECT_GE(min_distance_brute_force(points, domain).distance, 0.3);
    EXPECT_TRUE(check_maximality(points, domain, 0.3).maximal);
    const auto one = ebeida<2>({2.0}, domain, 3);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_TRUE(domain.contains(one[0]));
  }
}

// Unbiased: the process is maximal dart throwing exactly, so it must match
// Jones's sampler (each sample uniform over the free area, run to
// saturation) within statistical error: count, nearest-neighbour distances
// and the whole radially averaged power spectrum (annuli 1-47, Welch t each).
TEST(Ebeida, MatchesMaximalDartThrowing) {
  const double r = 0.02;
  const auto domain = Domain<2>::unit(true);
  testing_stats::Realisations e, j;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    e.add(ebeida<2>({r}, domain, seed), domain, r, true);
    j.add(jones({r}, domain, 100 + seed), domain, r, true);
  }
  EXPECT_LT(std::abs(testing_stats::welch_t(e.count, j.count)), testing_stats::kMaxT);
  EXPECT_LT(std::abs(testing_stats::welch_t(e.mean_over_r, j.mean_over_r)), testing_stats::kMaxT);
  EXPECT_LT(std::abs(testing_stats::welch_t(e.fraction_near, j.fraction_near)), testing_stats::kMaxT);
  EXPECT_LT(testing_stats::max_spectrum_t(e.spectrum, j.spectrum, 47), testing_stats::kMaxSpectrumT);
}

// Tori with a period under 2r (several images of one sample within r of a
// cell) or near 2.33r in 3D (a cell holding the point half a period from a
// sample): each of these once refined for ever, memory growing without end.
TEST(Ebeida, ShortPeriodsFinishMaximal) {
  const auto torus2 = [](double x, double y) { return Domain<2>::torus({{0.0, 0.0}}, {{x, y}}); };
  const auto torus3 = [](double x, double y, double z) { return Domain<3>::torus({{0.0, 0.0, 0.0}}, {{x, y, z}}); };
  for (const auto& [r, domain] : {std::pair{0.5, torus2(0.9, 100)}, std::pair{0.5, torus2(0.6, 100)},
                                  std::pair{33.2, torus2(2.68, 22806)}, std::pair{0.5, torus2(0.15, 30)}}) {
    const auto points = ebeida<2>({r}, domain, 1);
    EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, r));
  }
  for (const auto& [r, domain] : {std::pair{0.01, torus3(1, 0.005, 1)}, std::pair{0.5, torus3(4, 4, 1.165)},
                                  std::pair{0.5, torus3(4, 4, 2)}, std::pair{0.5, torus3(0.4, 0.7, 5)}}) {
    const auto points = ebeida<3>({r}, domain, 1);
    EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, r));
  }
}

// Boxes far thinner than r along some axes: splitting those axes with the
// others doubled the open sub-cells each level until the cap stopped the run
// (the first box below: 81,920 sub-cells at level 7). They now wait until
// the other axes' sub-cells are as thin, and the sets are maximal.
TEST(Ebeida, ThinBoxesFinishMaximal) {
  const double r = 0.01;
  const auto tube = Domain<3>::box({{0.0, 0.0, 0.0}}, {{100.0, 1e-4, 1e-4}});
  const auto in_tube = ebeida<3>({r}, tube, 1);
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(in_tube, tube, r));
  EXPECT_NEAR(static_cast<double>(in_tube.size()), 0.7476 * 100.0 / r, 150.0);  // Renyi's parking constant
  const auto slab = Domain<3>::box({{0.0, 0.0, 0.0}}, {{0.5, 0.5, 1e-6}});
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(ebeida<3>({r}, slab, 2), slab, r));
  const auto strip = Domain<2>::box({{-3.0, 5.0}}, {{-2.0, 5.0 + 1e-7}});
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(ebeida<2>({r}, strip, 3), strip, r));
  const auto thin4 = Domain<4>::box({{0.0, 0.0, 0.0, 0.0}}, {{1.0, 0.5, 1e-5, 1e-3}});
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(ebeida<4>({0.05}, thin4, 4), thin4, 0.05));
}

// Five dimensions: darts drawn in sequence from the list of open sub-cells,
// samples in a grid of edge r. On the torus the count is that of random
// sequential adsorption at saturation: hyperspheres of diameter r fill
// 0.1707761 of 5D space (Zhang & Torquato, Phys. Rev. E 88, 053312, 2013);
// five seeds measured 0.1684-0.1716 at this size (about 600 points).
TEST(Ebeida, FiveDimensionsMinimumDistanceMaximalAndSaturated) {
  const double r = 0.28;
  const Domain<5> torus{{{-0.5, 0.0, 2.0, -3.0, 1.0}}, {{0.5, 1.0, 3.0, -2.0, 2.0}}, true};
  const auto points = ebeida<5>({r}, torus, 5);
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, torus, r));
  const double ball = std::pow(M_PI, 2.5) / std::tgamma(3.5) * std::pow(0.5 * r, 5);
  const double coverage = static_cast<double>(points.size()) * ball / torus.volume();
  EXPECT_NEAR(coverage, 0.1707761, 0.025 * 0.1707761) << points.size() << " points";
  const Domain<5> box{{{-0.5, 0.0, 2.0, -3.0, 1.0}}, {{0.2, 0.7, 2.7, -2.3, 1.7}}, false};
  const auto in_box = ebeida<5>({r}, box, 5);
  ASSERT_GT(in_box.size(), 100u);
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(in_box, box, r));
  EXPECT_EQ(in_box, ebeida<5>({r}, box, 5));
  EXPECT_NE(in_box, ebeida<5>({r}, box, 6));
  // A box thin along two axes: those wait before they are split.
  const auto thin = Domain<5>::box({{0.0, 0.0, 0.0, 0.0, 0.0}}, {{1.0, 0.6, 1e-4, 0.5, 1e-6}});
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(ebeida<5>({0.1}, thin, 2), thin, 0.1));
}

// Past 5D the run is exact but slow (docs/dimensions.md): small sets (tens to
// hundreds of samples), a box off the origin with unequal edges and its
// torus, each checked against every pair and by the exact maximality
// analysis; the seed checks once, in 6D (the same template code in all).
template <int D>
void check_high_dimensional(double box_r, double torus_r, std::size_t at_least, bool check_seeds = false) {
  Domain<D> box;
  for (int a = 0; a < D; ++a) {
    box.lo[a] = -0.5 + 0.1 * a;
    box.hi[a] = box.lo[a] + 1.0 + 0.02 * a;
  }
  const auto in_box = ebeida<D>({box_r}, box, 5);
  EXPECT_GT(in_box.size(), at_least);
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(in_box, box, box_r));
  if (check_seeds) {
    EXPECT_EQ(in_box, ebeida<D>({box_r}, box, 5));
    EXPECT_NE(in_box, ebeida<D>({box_r}, box, 6));
  }
  Domain<D> torus = box;
  torus.periodic = true;
  const auto on_torus = ebeida<D>({torus_r}, torus, 5);
  EXPECT_GT(on_torus.size(), 2u);
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(on_torus, torus, torus_r));
}

TEST(Ebeida, SixDimensionsMinimumDistanceMaximalInsideAndReproducible) {
  check_high_dimensional<6>(0.6, 0.7, 150, true);
}
TEST(Ebeida, SevenDimensionsMinimumDistanceMaximalInside) { check_high_dimensional<7>(0.8, 0.85, 100); }
TEST(Ebeida, EightDimensionsMinimumDistanceMaximalInside) { check_high_dimensional<8>(1.1, 1.05, 50); }

// The 5D loop reports samples placed, monotone, the same points with and
// without a listener, and stops when asked.
TEST(Ebeida, FiveDimensionsReportProgressAndStop) {
  const Domain<5> torus = Domain<5>::unit(true);
  EbeidaParams params{0.4};
  std::vector<double> done;
  params.progress.report = [&](double d, double) {
    done.push_back(d);
    return true;
  };
  const auto points = ebeida<5>(params, torus, 2);
  ASSERT_GE(done.size(), 10u);
  EXPECT_TRUE(std::is_sorted(done.begin(), done.end()));
  EXPECT_EQ(points, ebeida<5>({0.4}, torus, 2));
  int calls = 0;
  params.progress.report = [&](double, double) { return ++calls < 5; };
  EXPECT_THROW(ebeida<5>(params, torus, 2), Cancelled);
}

TEST(Ebeida, RejectsBadInput) {
  const auto domain = Domain<2>::unit();
  EXPECT_THROW(ebeida<2>({0.0}, domain, 1), InvalidArgument);
  EXPECT_THROW(ebeida<2>({-0.1}, domain, 1), InvalidArgument);
  EXPECT_THROW(ebeida<2>({std::numeric_limits<double>::quiet_NaN()}, domain, 1), InvalidArgument);
  EXPECT_THROW(ebeida<2>({1e-6}, domain, 1), InvalidArgument);  // over the default point budget
  // Coordinates so large that rounding is a sizeable part of the radius.
  const auto far = Domain<2>::box({{1e12, 1e12}}, {{1e12 + 1.0, 1e12 + 1.0}});
  EXPECT_THROW(ebeida<2>({1e-3}, far, 1), InvalidArgument);
  // 5D: more grid cells than 4 GiB of sub-cells could serve, refused before allocation.
  EbeidaParams tiny{0.02};
  tiny.max_points = std::uint64_t{1} << 50;
  EXPECT_THROW(ebeida<5>(tiny, Domain<5>::unit(), 1), InvalidArgument);
  // 8D: 6^8 cells (1.7 million) at r = 0.5 on the unit cube, past the bound.
  EXPECT_THROW(ebeida<8>({0.5}, Domain<8>::unit(), 1), InvalidArgument);
}

}  // namespace
}  // namespace pds
