#include "pds/samplers/maximal_darts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "nn_statistics.h"
#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"
#include "pds/analysis/relative_radius.h"
#include "pds/error.h"
#include "pds/samplers/ebeida.h"
#include "set_checks.h"

namespace pds {
namespace {

template <int D>
PointSet<D> run(double r, const Domain<D>& domain, std::uint64_t seed, int threads = 1) {
  return maximal_darts<D>({r, threads}, domain, seed);
}

template <int D>
void check_set(double r) {
  for (bool torus : {false, true}) {
    const auto domain = testing_stats::offset_domain<D>(torus);
    const auto points = run<D>(r, domain, 5);
    ASSERT_GT(points.size(), 1000u);
    EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, r));
    const double rho = relative_radius(r, domain.volume(), points.size(), D);
    EXPECT_GT(rho, D == 2 ? 0.74 : 0.78) << domain;
    EXPECT_LT(rho, D == 2 ? 0.80 : 0.87) << domain;
    if (torus) {
      // Saturation coverage of random sequential adsorption, disks of
      // diameter r: 0.547069 in 2D (Hinrichsen, Feder, Jossang 1986), 0.384131
      // in 3D (Torquato, Uche, Stillinger 2006).
      const double ball = D == 2 ? M_PI / 4.0 * r * r : M_PI / 6.0 * r * r * r;
      const double coverage = static_cast<double>(points.size()) * ball / domain.volume();
      EXPECT_NEAR(coverage, D == 2 ? 0.547069 : 0.384131, 0.03 * coverage) << domain;
    }
    // Same seed, same bytes, for any thread count (a chunk may decide another
    // chunk's darts; 4 threads: SameBytesForEveryThreadCount).
    EXPECT_EQ(points, run<D>(r, domain, 5, 3));
    EXPECT_NE(points, run<D>(r, domain, 6));
  }
}

TEST(MaximalDarts, MinimumDistanceMaximalInsideAndReproducible2D) { check_set<2>(0.01); }
TEST(MaximalDarts, MinimumDistanceMaximalInsideAndReproducible3D) { check_set<3>(0.06); }

// Many chunks and a multi-threaded run on a grid large enough that every
// chunk boundary has conflicting darts on both sides.
TEST(MaximalDarts, SameBytesForEveryThreadCount) {
  const auto domain = Domain<2>::unit(true);
  const auto one = run<2>(0.003, domain, 11, 1);
  EXPECT_GT(one.size(), 70000u);
  EXPECT_EQ(one, run<2>(0.003, domain, 11, 4));
  EXPECT_GE(min_distance(one, domain).distance, 0.003);
}

// Open sub-cells are kept as siblings of one parent while their codes fit 14
// bits an axis (2D), one by one past that. This set's last sub-cells close at
// level 18 (measured), so both forms and the switch between them run, and
// the set must come out maximal (sets of a few thousand points end by level
// 12, all in the first form).
TEST(MaximalDarts, SubCellsPastFourteenLevelsFinishMaximal) {
  const auto domain = Domain<2>::unit(true);
  const auto points = run<2>(0.006, domain, 1);
  EXPECT_GT(points.size(), 19000u);
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, 0.006));
}

// Boxes far thinner than r along some axes (as Ebeida.ThinBoxesFinishMaximal):
// the thin axes wait to be split, the sets are maximal, and the thread count
// still does not change a byte.
TEST(MaximalDarts, ThinBoxesFinishMaximal) {
  const double r = 0.01;
  const auto tube = Domain<3>::box({{0.0, 0.0, 0.0}}, {{100.0, 1e-4, 1e-4}});
  const auto in_tube = run<3>(r, tube, 1);
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(in_tube, tube, r));
  EXPECT_NEAR(static_cast<double>(in_tube.size()), 0.7476 * 100.0 / r, 150.0);  // Renyi's parking constant
  EXPECT_EQ(in_tube, run<3>(r, tube, 1, 3));
  const auto slab = Domain<3>::box({{0.0, 0.0, 0.0}}, {{0.5, 0.5, 1e-6}});
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(run<3>(r, slab, 2), slab, r));
  const auto strip = Domain<2>::box({{-3.0, 5.0}}, {{-2.0, 5.0 + 1e-7}});
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(run<2>(r, strip, 3), strip, r));
}

// Unbiased: the process is maximal dart throwing exactly, so it must match
// ebeida (the same process by another evaluation order, itself tested against
// Jones's sampler) within statistical error: count, nearest-neighbour
// distances and the radially averaged power (annuli 1-47, Welch t each).
TEST(MaximalDarts, MatchesMaximalDartThrowing) {
  const double r = 0.02;
  const auto domain = Domain<2>::unit(true);
  testing_stats::Realisations m, e;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    m.add(run<2>(r, domain, seed), domain, r, true);
    e.add(ebeida<2>({r}, domain, 100 + seed), domain, r, true);
  }
  EXPECT_LT(std::abs(testing_stats::welch_t(m.count, e.count)), testing_stats::kMaxT);
  EXPECT_LT(std::abs(testing_stats::welch_t(m.mean_over_r, e.mean_over_r)), testing_stats::kMaxT);
  EXPECT_LT(std::abs(testing_stats::welch_t(m.fraction_near, e.fraction_near)), testing_stats::kMaxT);
  EXPECT_LT(testing_stats::max_spectrum_t(m.spectrum, e.spectrum, 47), testing_stats::kMaxSpectrumT);
}

// Tiny domains (a box of one cell, a radius larger than the domain) and tori
// too short for the grid's stencil (handed to ebeida).
TEST(MaximalDarts, SmallDomainsAndShortPeriods) {
  for (bool torus : {false, true}) {
    const auto domain = Domain<2>::unit(torus);
    const auto points = run<2>(0.3, domain, 3);
    EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, 0.3));
    const auto one = run<2>(2.0, domain, 3);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_TRUE(domain.contains(one[0]));
  }
  const auto thin = Domain<2>::torus({{0.0, 0.0}}, {{0.9, 100}});
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(run<2>(0.5, thin, 1), thin, 0.5));
  const auto thin3 = Domain<3>::torus({{0.0, 0.0, 0.0}}, {{4, 4, 1.165}});
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(run<3>(0.5, thin3, 1), thin3, 0.5));
  const auto flat = Domain<3>::box({{0.0, 0.0, 0.0}}, {{3, 3, 0.01}});
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(run<3>(0.1, flat, 1), flat, 0.1));
}

TEST(MaximalDarts, RejectsBadInput) {
  const auto domain = Domain<2>::unit();
  EXPECT_THROW(run<2>(0.0, domain, 1), InvalidArgument);
  EXPECT_THROW(run<2>(-0.1, domain, 1), InvalidArgument);
  EXPECT_THROW(run<2>(std::numeric_limits<double>::quiet_NaN(), domain, 1), InvalidArgument);
  EXPECT_THROW(run<2>(1e-6, domain, 1), InvalidArgument);  // over the default point budget
  EXPECT_THROW(run<2>(0.1, domain, 1, -1), InvalidArgument);
  const auto far = Domain<2>::box({{1e12, 1e12}}, {{1e12 + 1.0, 1e12 + 1.0}});
  EXPECT_THROW(run<2>(1e-3, far, 1), InvalidArgument);
}

}  // namespace
}  // namespace pds
