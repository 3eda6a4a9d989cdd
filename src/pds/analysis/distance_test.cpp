#include "pds/analysis/distance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pds/error.h"
#include "pds/rng.h"
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

template <int D>
PointSet<D> uniform_points(std::size_t n, const Domain<D>& domain, std::uint64_t seed) {
  Rng rng(seed);
  PointSet<D> points(n);
  for (auto& p : points)
    for (int k = 0; k < D; ++k) p[k] = domain.lo[k] + rng.uniform() * domain.extent(k);
  return points;
}

TEST(NearestNeighbors, MatchBruteForceInOneToEightDimensions) {
  for (bool torus : {false, true}) {
    check_nearest_neighbors<1>(uniform_points<1>(300, Domain<1>::unit(torus), 1), Domain<1>::unit(torus));
    check_nearest_neighbors<4>(uniform_points<4>(600, Domain<4>::unit(torus), 2), Domain<4>::unit(torus));
    const auto d5 = torus ? Domain<5>::torus({0, 0, 0, 0, 0}, {1, 2, 0.5, 1, 3})
                          : Domain<5>::box({0, 0, 0, 0, 0}, {1, 2, 0.5, 1, 3});
    check_nearest_neighbors<5>(uniform_points<5>(600, d5, 3), d5);
    check_nearest_neighbors<6>(uniform_points<6>(500, Domain<6>::unit(torus), 4), Domain<6>::unit(torus));
    check_nearest_neighbors<7>(uniform_points<7>(500, Domain<7>::unit(torus), 5), Domain<7>::unit(torus));
    check_nearest_neighbors<8>(uniform_points<8>(500, Domain<8>::unit(torus), 6), Domain<8>::unit(torus));
  }
}

TEST(NearestNeighbors, RunTimeDimensionBeyondEight) {
  // 12 dimensions, box and torus, against all pairs; the k-d tree alone.
  const int dim = 12;
  Rng rng(7);
  PointCloud cloud{dim, std::vector<double>(400 * dim)};
  for (double& x : cloud.coords) x = rng.uniform();
  const std::vector<double> lo(dim, 0.0), hi(dim, 1.0);
  for (bool torus : {false, true}) {
    const NearestNeighbors nn = nearest_neighbors(cloud, lo, hi, torus);
    double smallest = INFINITY;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      double best = INFINITY;
      for (std::size_t j = 0; j < cloud.size(); ++j) {
        if (j == i) continue;
        double s = 0;
        for (int k = 0; k < dim; ++k) {
          double d = std::abs(cloud.point(i)[k] - cloud.point(j)[k]);
          if (torus) d = std::min(d, 1.0 - d);
          s += d * d;
        }
        best = std::min(best, s);
      }
      ASSERT_NEAR(nn.distance[i], std::sqrt(best), 1e-15) << "point " << i;
      smallest = std::min(smallest, std::sqrt(best));
    }
    EXPECT_NEAR(min_distance(cloud, lo, hi, torus).distance, smallest, 1e-15);
  }
  // The typed path agrees with the run-time one in 2D.
  const auto p2 = white_noise<2>({300}, Domain<2>::unit(), 8);
  const std::vector<double> lo2{0, 0}, hi2{1, 1};
  EXPECT_EQ(min_distance(PointCloud::from(p2), lo2, hi2, false).distance, min_distance(p2, Domain<2>::unit()).distance);
  EXPECT_THROW(min_distance(cloud, lo2, hi2, false), InvalidArgument);
  PointCloud outside{2, {0.5, 1.5}};
  EXPECT_THROW(min_distance(outside, lo2, hi2, false), InvalidArgument);
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
