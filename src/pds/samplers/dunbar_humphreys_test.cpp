#include "pds/samplers/dunbar_humphreys.h"

#include <gtest/gtest.h>

#include "nn_statistics.h"
#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"
#include "pds/error.h"
#include "pds/samplers/jones.h"

namespace pds {
namespace {

Domain<2> test_domain(bool torus) { return Domain<2>{{{0.0, -1.0}}, {{1.25, 0.0}}, torus}; }

TEST(DunbarHumphreys, MinimumDistanceInsideAndMaximalOnBoxAndTorus) {
  const double r = 0.02;  // about 2700 samples
  for (bool torus : {false, true}) {
    const auto domain = test_domain(torus);
    const auto points = dunbar_humphreys({r}, domain, 5);
    ASSERT_GT(points.size(), 2000u);
    EXPECT_GE(min_distance_brute_force(points, domain).distance, r);
    for (const auto& p : points) EXPECT_TRUE(domain.contains(p)) << p;
    const auto mx = check_maximality(points, domain, r);
    EXPECT_TRUE(mx.maximal) << domain << " gap at " << (mx.gap ? *mx.gap : Point<2>{}) << " distance "
                            << mx.gap_distance;
  }
}

TEST(DunbarHumphreys, SameSeedSamePointsOtherSeedOtherPoints) {
  const auto domain = test_domain(false);
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
    const auto domain = test_domain(torus);
    const auto nn = nearest_neighbors(dunbar_humphreys({r}, domain, 9), domain);
    for (double d : nn.distance) {
      EXPECT_GE(d, r);
      EXPECT_LE(d, r * (1.0 + 1e-9));
    }
  }
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

}  // namespace
}  // namespace pds
