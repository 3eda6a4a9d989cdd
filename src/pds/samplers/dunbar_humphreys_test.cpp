#include "pds/samplers/dunbar_humphreys.h"

#include <gtest/gtest.h>

#include <cmath>

#include "nn_statistics.h"
#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"
#include "pds/analysis/spectrum.h"
#include "pds/error.h"
#include "pds/samplers/jones.h"
#include "set_checks.h"

namespace pds {
namespace {

TEST(DunbarHumphreys, MinimumDistanceInsideAndMaximalOnBoxAndTorus) {
  const double r = 0.02;  // about 2700 samples
  for (bool torus : {false, true}) {
    const auto domain = testing_stats::offset_domain<2>(torus);
    const auto points = dunbar_humphreys({r}, domain, 5);
    ASSERT_GT(points.size(), 2000u);
    EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, r));
  }
}

// Boxes less than a cell thick: the grid has one row of cells much thinner
// than they are wide, so the window's reach is per axis (before, the thin
// axis set both and boundary sampling stopped with "neighbour window wider
// than planned").
TEST(DunbarHumphreys, BoxesThinnerThanACellStayExactAndMaximal) {
  const double r = 0.002;
  for (double thickness : {0.001, 0.0005, 0.0014}) {
    const Domain<2> domain = Domain<2>::box({{0.0, 0.0}}, {{0.3, thickness}});
    for (int variant : {0, 1, 2}) {
      DunbarHumphreysParams params{r};
      params.variant = variant;
      const auto points = dunbar_humphreys(params, domain, 3);
      ASSERT_GT(points.size(), 0.3 / (2.0 * r)) << "variant " << variant;
      EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, r)) << "variant " << variant;
    }
  }
}

// Tori only a few radii wide, where the neighbour window covers a whole axis:
// the nearest images must still be used there (before that was handled, such
// tori looped or exhausted memory).
TEST(DunbarHumphreys, SmallToriStayExactAndMaximal) {
  const Domain<2> domain{{{0.0, 0.0}}, {{1.0, 1.3}}, true};
  for (double r : {0.24, 0.22, 0.2, 0.18, 0.16, 0.13, 0.11}) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const auto points = dunbar_humphreys({r}, domain, seed);
      EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, r)) << "seed " << seed;
    }
  }
}

TEST(DunbarHumphreys, SameSeedSamePointsOtherSeedOtherPoints) {
  const auto domain = testing_stats::offset_domain<2>(false);
  EXPECT_EQ(dunbar_humphreys({0.03}, domain, 3), dunbar_humphreys({0.03}, domain, 3));
  EXPECT_NE(dunbar_humphreys({0.03}, domain, 3), dunbar_humphreys({0.03}, domain, 4));
}

TEST(DunbarHumphreys, RejectsBadInput) {
  EXPECT_THROW(dunbar_humphreys({-1.0}, Domain<2>::unit(), 1), InvalidArgument);
  EXPECT_THROW(dunbar_humphreys({INFINITY}, Domain<2>::unit(), 1), InvalidArgument);
  EXPECT_THROW(dunbar_humphreys({0.3}, Domain<2>::unit(true), 1), InvalidArgument);     // period < 4 radius
  EXPECT_THROW(dunbar_humphreys({1e-7, 1000}, Domain<2>::unit(), 1), InvalidArgument);  // over the budget
}

// Boundary sampling places every sample on its parent's circle, so every
// nearest-neighbour distance is the circle radius, r (1 + 1e-10).
TEST(DunbarHumphreys, EverySampleHasANeighbourAtExactlyTheRadius) {
  const double r = 0.03;
  for (bool torus : {false, true}) {
    const auto domain = testing_stats::offset_domain<2>(torus);
    const auto nn = nearest_neighbors(dunbar_humphreys({r}, domain, 9), domain);
    for (double d : nn.distance) {
      EXPECT_GE(d, r);
      EXPECT_LE(d, r * (1.0 + 1e-9));
    }
  }
}

// Isotropy on the torus: the averaged periodogram has as much power on the
// axes as off them at low frequencies (|k| <= 16 cycles per period). From a
// single seed the front met itself along two axis-parallel lines of the
// torus, and the axes carried 2.0-2.15 times the power of the other
// frequencies (0.081 against 0.040 over 8 sets of ~2200 samples; three seed
// ranges alike); from 16 seeds 1.03-1.11 (four seed ranges). The 64 axis
// frequencies (32 independent, P(-k) = P(k)) averaged over 8 sets have a
// relative spread of about 6%, so the bound 1.3 sits 5 spreads above 1 and
// far below the one-seed ratio.
TEST(DunbarHumphreys, NoCrossAlongTheAxesOfTheTorusSpectrum) {
  const auto domain = Domain<2>::unit(true);
  std::vector<PointSet<2>> sets;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) sets.push_back(dunbar_humphreys({0.02}, domain, seed));
  const int k = 16;
  const Periodogram p = periodogram<2>(sets, domain, {.max_frequency = k});
  double axis = 0.0, off = 0.0;
  int n_axis = 0, n_off = 0;
  for (int ky = -k; ky <= k; ++ky)
    for (int kx = -k; kx <= k; ++kx) {
      if ((kx == 0 && ky == 0) || kx * kx + ky * ky > k * k) continue;
      if (kx == 0 || ky == 0) {
        axis += p.at(kx, ky);
        ++n_axis;
      } else {
        off += p.at(kx, ky);
        ++n_off;
      }
    }
  const double ratio = (axis / n_axis) / (off / n_off);
  EXPECT_LT(ratio, 1.3) << "axis power " << axis / n_axis << ", off-axis " << off / n_off;
  EXPECT_GT(ratio, 0.75) << "axis power " << axis / n_axis << ", off-axis " << off / n_off;
}

// The bias the paper accepts for speed: boundary sampling packs more samples
// than maximal dart throwing (Jones's sampler, the unbiased reference at
// saturation). Measured ratio 1.24 (docs/dunbar-humphreys.md); the test asks
// for a difference far beyond the seed-to-seed spread.
TEST(DunbarHumphreys, DenserThanMaximalDartThrowing) {
  const double r = 0.02;
  const auto domain = Domain<2>::unit(true);
  std::vector<double> dh, dart;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    dh.push_back(double(dunbar_humphreys({r}, domain, seed).size()));
    dart.push_back(double(jones({r}, domain, seed).size()));
  }
  EXPECT_GT(testing_stats::welch_t(dh, dart), 20.0);
}

// What the sector variants guarantee on a set of some 2000 samples: the
// minimum distance (all pairs), every sample inside, and no uncovered point
// (sectors narrower than 1e-12 rad are dropped: gaps under 1e-11 r).
void expect_maximal_poisson_disk(const PointSet<2>& points, const Domain<2>& domain, double r) {
  ASSERT_GT(points.size(), 2000u);
  EXPECT_GE(min_distance_brute_force(points, domain).distance, r);
  for (const auto& p : points) EXPECT_TRUE(domain.contains(p)) << p;
  const auto mx = check_maximality(points, domain, r, 1e-9 * r);
  EXPECT_TRUE(mx.maximal) << domain << " gap at " << (mx.gap ? *mx.gap : Point<2>{}) << " distance " << mx.gap_distance;
}

// Variant 1, the paper's scalloped sectors over the annulus r..2r.
DunbarHumphreysParams sectors(double r) {
  DunbarHumphreysParams params{r};
  params.variant = 1;
  return params;
}

TEST(DunbarHumphreysSectors, MinimumDistanceInsideAndMaximalOnBoxAndTorus) {
  const double r = 0.02;  // about 2300 samples
  for (bool torus : {false, true}) {
    const auto domain = testing_stats::offset_domain<2>(torus);
    const auto points = dunbar_humphreys(sectors(r), domain, 5);
    expect_maximal_poisson_disk(points, domain, r);
  }
}

TEST(DunbarHumphreysSectors, SameSeedSamePointsOtherSeedOtherPoints) {
  const auto domain = testing_stats::offset_domain<2>(true);
  EXPECT_EQ(dunbar_humphreys(sectors(0.03), domain, 3), dunbar_humphreys(sectors(0.03), domain, 3));
  EXPECT_NE(dunbar_humphreys(sectors(0.03), domain, 3), dunbar_humphreys(sectors(0.03), domain, 4));
  EXPECT_NE(dunbar_humphreys(sectors(0.03), domain, 3), dunbar_humphreys({0.03}, domain, 3));
}

TEST(DunbarHumphreysSectors, RejectsBadInput) {
  EXPECT_THROW(dunbar_humphreys(sectors(0.17), Domain<2>::unit(true), 1), InvalidArgument);  // period <= 6 radius
  EXPECT_NO_THROW(dunbar_humphreys(sectors(0.16), Domain<2>::unit(true), 1));
  DunbarHumphreysParams bad{0.05};
  bad.variant = 3;
  EXPECT_THROW(dunbar_humphreys(bad, Domain<2>::unit(), 1), InvalidArgument);
}

// Against maximal dart throwing (Jones's sampler, random sequential adsorption
// to saturation), 10 + 10 seeds on the unit torus. Each front sample's region
// is uniform and exact, but the paper fills one front sample's annulus
// completely before moving on, which is not the order of dart throwing:
// measured 5.6% more samples (t = 30) and nearest neighbours closer to r
// (mean 1.034 r against 1.054 r, t = -36); docs/dunbar-humphreys.md. The test
// pins down what holds: the low-frequency spectrum (annuli 1-30, below the
// blue-noise ring) matches dart throwing's; density and nearest-neighbour
// distances differ beyond statistical error, in that direction; and the set is
// far closer to dart throwing than boundary sampling (which packs 25% more).
TEST(DunbarHumphreysSectors, ComparedWithMaximalDartThrowing) {
  const double r = 0.02;
  const auto domain = Domain<2>::unit(true);
  std::vector<double> n_sectors, n_dart, n_boundary, nn_sectors, nn_dart;
  std::vector<std::vector<double>> spectra_sectors, spectra_dart;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const auto s = dunbar_humphreys(sectors(r), domain, seed);
    const auto j = jones({r}, domain, 100 + seed);
    n_sectors.push_back(double(s.size()));
    n_dart.push_back(double(j.size()));
    n_boundary.push_back(double(dunbar_humphreys({r}, domain, seed).size()));
    nn_sectors.push_back(testing_stats::summarize(s, domain, r).mean_over_r);
    nn_dart.push_back(testing_stats::summarize(j, domain, r).mean_over_r);
    spectra_sectors.push_back(testing_stats::radial_power(s, domain, 48));
    spectra_dart.push_back(testing_stats::radial_power(j, domain, 48));
  }
  EXPECT_LT(testing_stats::max_spectrum_t(spectra_sectors, spectra_dart, 30), testing_stats::kMaxSpectrumT);
  EXPECT_GT(testing_stats::welch_t(n_sectors, n_dart), testing_stats::kMaxT);
  EXPECT_LT(testing_stats::welch_t(nn_sectors, nn_dart), -testing_stats::kMaxT);
  EXPECT_LT(testing_stats::welch_t(n_sectors, n_boundary), -20.0);
}

// Variant 2, the scalloped sectors with the next sample drawn uniformly over
// the union of all front regions.
DunbarHumphreysParams global_sectors(double r) {
  DunbarHumphreysParams params{r};
  params.variant = 2;
  return params;
}

TEST(DunbarHumphreysGlobalSectors, MinimumDistanceInsideAndMaximalOnBoxAndTorus) {
  const double r = 0.02;  // about 2200 samples
  for (bool torus : {false, true}) {
    const auto domain = testing_stats::offset_domain<2>(torus);
    const auto points = dunbar_humphreys(global_sectors(r), domain, 5);
    expect_maximal_poisson_disk(points, domain, r);
  }
}

TEST(DunbarHumphreysGlobalSectors, SameSeedSamePointsOtherSeedOtherPoints) {
  const auto domain = testing_stats::offset_domain<2>(false);
  EXPECT_EQ(dunbar_humphreys(global_sectors(0.03), domain, 3), dunbar_humphreys(global_sectors(0.03), domain, 3));
  EXPECT_NE(dunbar_humphreys(global_sectors(0.03), domain, 3), dunbar_humphreys(global_sectors(0.03), domain, 4));
  EXPECT_THROW(dunbar_humphreys(global_sectors(0.17), Domain<2>::unit(true), 1), InvalidArgument);
}

// Against maximal dart throwing (Jones's sampler), 10 + 10 seeds on the unit
// torus: density, mean nearest-neighbour distance, fraction of neighbours
// below 1.1 r, and every annulus of the radial power spectrum agree within
// statistical error (measured t: -1.5, 0.1, -1.1, largest annulus 4.8).
TEST(DunbarHumphreysGlobalSectors, MatchesMaximalDartThrowing) {
  const double r = 0.02;
  const auto domain = Domain<2>::unit(true);
  testing_stats::Realisations sectors, dart;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    sectors.add(dunbar_humphreys(global_sectors(r), domain, seed), domain, r, true);
    dart.add(jones({r}, domain, 100 + seed), domain, r, true);
  }
  EXPECT_LT(std::abs(testing_stats::welch_t(sectors.count, dart.count)), testing_stats::kMaxT);
  EXPECT_LT(std::abs(testing_stats::welch_t(sectors.mean_over_r, dart.mean_over_r)), testing_stats::kMaxT);
  EXPECT_LT(std::abs(testing_stats::welch_t(sectors.fraction_near, dart.fraction_near)), testing_stats::kMaxT);
  EXPECT_LT(testing_stats::max_spectrum_t(sectors.spectrum, dart.spectrum), testing_stats::kMaxSpectrumT);
}

}  // namespace
}  // namespace pds
