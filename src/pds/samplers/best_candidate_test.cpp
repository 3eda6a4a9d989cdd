#include "pds/samplers/best_candidate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pds/analysis/distance.h"
#include "pds/analysis/relative_radius.h"
#include "pds/error.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

template <int D>
void expect_reported_distances_exact(const Domain<D>& domain, const BestCandidateParams& params) {
  const auto run = best_candidate_run(params, domain, 21);
  ASSERT_EQ(run.points.size(), run.distance.size());
  EXPECT_TRUE(std::isinf(run.distance[0]));
  for (std::size_t i = 1; i < run.points.size(); ++i) {
    double nearest2 = INFINITY;
    for (std::size_t j = 0; j < i; ++j) nearest2 = std::min(nearest2, domain.distance2(run.points[i], run.points[j]));
    ASSERT_EQ(run.distance[i], std::sqrt(nearest2)) << "sample " << i << " of " << domain;
  }
}

TEST(BestCandidate, ReportedDistancesAreTheExactNearestEarlierSample) {
  // Every nearest-sample query of the accelerated search, checked against all
  // earlier samples, across the regime switch at m*i = 256.
  BestCandidateParams params;
  params.m = 1;
  for (bool torus : {false, true}) {
    params.count = 1500;
    expect_reported_distances_exact(Domain<2>{{-1, 0}, {1, 0.75}, torus}, params);
    params.count = 700;
    expect_reported_distances_exact(Domain<3>{{0, 0, 0}, {1, 0.5, 0.8}, torus}, params);
  }
}

TEST(BestCandidate, EarlyRoundsAreTheLiteralFarthestOfMTimesICandidates) {
  // While m*i < 256 the candidates are exactly m*i uniform points of stream
  // (seed, i): recompute them and the farthest by brute force.
  const auto domain = Domain<2>::unit(true);
  BestCandidateParams params;
  params.count = 60;
  params.m = 4;
  const auto points = best_candidate(params, domain, 8);
  for (std::uint64_t i = 1; i < 60; ++i) {
    Rng rng(8, {i});
    double best2 = -1;
    Point<2> winner{};
    for (std::uint64_t t = 0; t < 4 * i; ++t) {
      const Point<2> c = uniform_point(rng, domain);
      double nearest2 = INFINITY;
      for (std::uint64_t j = 0; j < i; ++j) nearest2 = std::min(nearest2, domain.distance2(c, points[j]));
      if (nearest2 > best2) {
        best2 = nearest2;
        winner = c;
      }
    }
    ASSERT_EQ(points[i], winner) << "round " << i;
  }
}

TEST(BestCandidate, EveryPrefixIsWellSpread) {
  // Progressive: the first n samples alone are a blue-noise set (white noise
  // of that size has relative radius ~0.05, a Bridson prefix is a blob).
  for (bool torus : {false, true}) {
    const auto domain = Domain<2>::unit(torus);
    BestCandidateParams params;
    params.count = 2000;
    const auto points = best_candidate(params, domain, 5);
    for (std::size_t n : {16u, 100u, 500u, 2000u}) {
      const PointSet<2> prefix(points.begin(), points.begin() + n);
      const double rho = relative_radius(min_distance_brute_force(prefix, domain).distance, 1.0, n, 2);
      EXPECT_GT(rho, 0.6) << n << " samples, torus " << torus;
    }
  }
}

TEST(BestCandidate, RadiusAndCount) {
  const auto domain = Domain<3>::unit(true);
  BestCandidateParams params;
  params.radius = 0.15;
  const auto points = best_candidate(params, domain, 2);
  EXPECT_GE(min_distance_brute_force(points, domain).distance, 0.15);
  // Both: exactly the count at that radius, or a clear error.
  params.count = points.size() / 2;
  EXPECT_EQ(best_candidate(params, domain, 2).size(), points.size() / 2);
  params.count = points.size() + 200;  // below the packing bound, above what fits
  try {
    best_candidate(params, domain, 2);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("placed only"), std::string::npos) << e.what();
  }
}

TEST(BestCandidate, RadiusLargerThanTheDomainGivesOnePoint) {
  BestCandidateParams params;
  params.radius = 2.0;
  for (bool torus : {false, true}) EXPECT_EQ(best_candidate(params, Domain<2>::unit(torus), 1).size(), 1u);
}

TEST(BestCandidate, BadParameters) {
  BestCandidateParams params;
  params.count = 10;
  params.m = 0;
  EXPECT_THROW(best_candidate(params, Domain<2>::unit(), 1), InvalidArgument);
  params.m = -2;
  EXPECT_THROW(best_candidate(params, Domain<2>::unit(), 1), InvalidArgument);
  params.m = 1;
  params.count = 0;
  EXPECT_THROW(best_candidate(params, Domain<2>::unit(), 1), InvalidArgument);
  params.count.reset();
  EXPECT_THROW(best_candidate(params, Domain<2>::unit(), 1), InvalidArgument);
  params.radius = 0.0;
  EXPECT_THROW(best_candidate(params, Domain<2>::unit(), 1), InvalidArgument);
  GenerateRequest r;
  r.count = 10;
  r.params = {{"m", 0}};
  EXPECT_THROW(generate("best-candidate", r), InvalidArgument);
  r.params = {{"m", 1.5}};
  EXPECT_THROW(generate("best-candidate", r), InvalidArgument);
  r.params = {{"m", 3}};
  EXPECT_EQ(generate("best-candidate", r).size(), 10u);
}

}  // namespace
}  // namespace pds
