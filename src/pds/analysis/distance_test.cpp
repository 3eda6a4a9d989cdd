#include "pds/analysis/distance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pds/samplers/random.h"

namespace pds {
namespace {

template <int D>
void check_nearest_neighbors(const PointSet<D>& points, const Domain<D>& domain) {
  const NearestNeighbors nn = nearest_neighbors(points, domain);
  for (std::size_t i = 0; i < points.size(); ++i) {
    double best = INFINITY;
    for (std::size_t j = 0; j < points.size(); ++j)
      if (j != i) best = std::min(best, domain.distance2(points[i], points[j]));
    ASSERT_EQ(nn.distance[i], std::sqrt(best)) << "point " << i << " in " << domain;
    ASSERT_EQ(domain.distance2(points[i], points[nn.index[i]]), best);
  }
  const MinDistance fast = min_distance(points, domain), brute = min_distance_brute_force(points, domain);
  EXPECT_EQ(fast.distance, brute.distance);
  EXPECT_EQ(std::sqrt(domain.distance2(points[fast.i], points[fast.j])), brute.distance);
}

TEST(NearestNeighbors, MatchBruteForceOnWhiteNoise) {
  for (bool torus : {false, true}) {
    check_nearest_neighbors<2>(white_noise<2>({700}, Domain<2>::unit(torus), 1), Domain<2>::unit(torus));
    check_nearest_neighbors<3>(white_noise<3>({700}, Domain<3>::unit(torus), 2), Domain<3>::unit(torus));
    const auto wide = Domain<2>{{-3, 0}, {5, 0.25}, torus};
    check_nearest_neighbors<2>(white_noise<2>({500}, wide, 3), wide);
  }
}

TEST(NearestNeighbors, MatchBruteForceOnClusteredSets) {
  // Most points in a tiny corner, a few far away: the search radius must grow.
  for (bool torus : {false, true}) {
    const auto domain = Domain<2>::unit(torus);
    PointSet<2> points = white_noise<2>({300}, Domain<2>::box({0.001, 0.001}, {0.01, 0.01}), 4);
    points.push_back({0.9, 0.9});
    points.push_back({0.5, 0.999});
    check_nearest_neighbors<2>(points, domain);
  }
}

TEST(MinDistance, FindsThePairAcrossTheSeamOnlyOnATorus) {
  const PointSet<2> points{{0.001, 0.5}, {0.999, 0.5}, {0.5, 0.2}};
  EXPECT_NEAR(min_distance(points, Domain<2>::unit(true)).distance, 0.002, 1e-15);
  EXPECT_NEAR(min_distance(points, Domain<2>::unit(false)).distance, std::hypot(0.499, 0.3), 1e-15);
}

TEST(MinDistance, HandlesDuplicatesAndTinySets) {
  EXPECT_EQ(min_distance(PointSet<2>{{0.3, 0.3}, {0.3, 0.3}, {0.9, 0.1}}, Domain<2>::unit()).distance, 0.0);
  EXPECT_TRUE(std::isinf(min_distance(PointSet<2>{{0.3, 0.3}}, Domain<2>::unit()).distance));
  EXPECT_TRUE(std::isinf(min_distance(PointSet<3>{}, Domain<3>::unit()).distance));
}

}  // namespace
}  // namespace pds
