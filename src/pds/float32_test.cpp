#include "pds/float32.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pds/analysis/distance.h"
#include "pds/error.h"
#include "pds/rng.h"

namespace pds {
namespace {

TEST(Float32Spacing, IsTheGapAtTheLargestCoordinate) {
  EXPECT_EQ(float32_spacing({0, 0}, {1, 1}), std::ldexp(1.0, -23));
  EXPECT_EQ(float32_spacing({1e6, -3}, {1e6 + 10, 0}), 0.0625);
  EXPECT_EQ(float32_spacing({-1e6 - 10, 0}, {-1e6, 1}), 0.0625);  // magnitude, not value
  EXPECT_THROW(float32_spacing({0}, {1e39}), InvalidArgument);
  EXPECT_THROW(float32_spacing({1e6 + 0.01}, {1e6 + 0.05}), InvalidArgument);
}

TEST(Float32SamplingRadius, InflatesByTwoDisplacementsAndRefusesCoarseSpacing) {
  const double r = float32_sampling_radius(1.0, 2, 1e-4);
  EXPECT_GE(r, 1.0 + 2 * std::sqrt(2.0) * 1e-4);
  EXPECT_LE(r, 1.0 + 2 * std::sqrt(2.0) * 1e-4 + 1e-11);
  EXPECT_GT(float32_sampling_radius(1.0, 2, 1e-4, 1), r);
  EXPECT_THROW(float32_sampling_radius(1.0, 2, 1e-2), InvalidArgument);
}

TEST(RoundToFloat32, RoundsToNearestAndPullsBackInside) {
  const double hi = 1e6 + 1;  // a float32 value
  PointCloud cloud{1, {1e6 + 0.04, std::nextafter(hi, 0.0), 1e6 + 0.5}};
  round_to_float32(cloud, {1e6}, {hi});
  EXPECT_EQ(cloud.coords[0], 1e6 + 0.0625);  // the nearest float
  EXPECT_EQ(cloud.coords[1], hi - 0.0625);   // rounded onto hi, pulled back
  EXPECT_EQ(cloud.coords[2], 1e6 + 0.5);
  // A lower bound between floats: the smallest float above it.
  PointCloud low{1, {1e6 + 0.01}};
  round_to_float32(low, {1e6 + 0.01}, {hi});
  EXPECT_EQ(low.coords[0], 1e6 + 0.0625);
}

TEST(FindPairCloserThan, AgreesWithAllPairs) {
  Rng rng(3);
  for (const bool torus : {false, true})
    for (int trial = 0; trial < 20; ++trial) {
      PointSet<3> points(300);
      for (auto& p : points)
        for (auto& x : p) x = rng.uniform();
      PointCloud cloud = PointCloud::from(points);
      const Domain<3> domain = torus ? Domain<3>::unit(true) : Domain<3>::unit(false);
      const double nearest = min_distance_brute_force(points, domain).distance;
      ClosePair pair;
      // Either side of the nearest pair (its distance is a rounded square root).
      EXPECT_FALSE(find_pair_closer_than(cloud, {0, 0, 0}, {1, 1, 1}, torus, nearest * (1 - 1e-12)));
      ASSERT_TRUE(find_pair_closer_than(cloud, {0, 0, 0}, {1, 1, 1}, torus, nearest * (1 + 1e-12), &pair));
      EXPECT_EQ(pair.distance, nearest);
    }
}

}  // namespace
}  // namespace pds
