#include "pds/samplers/best_candidate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <tuple>
#include <vector>

#include "pds/analysis/distance.h"
#include "pds/analysis/relative_radius.h"
#include "pds/error.h"
#include "pds/grid.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"
#include "pds/registry.h"

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

// Rounds 1..n-1 of best_candidate() recomputed by brute force: the m*i
// uniform points of stream (seed, i) and the farthest of them from all
// earlier samples.
template <int D>
void expect_literal_rounds(const Domain<D>& domain, std::uint64_t n, int m, std::uint64_t seed) {
  BestCandidateParams params;
  params.count = n;
  params.m = m;
  const auto points = best_candidate(params, domain, seed);
  ASSERT_EQ(points.size(), n);
  for (std::uint64_t i = 1; i < n; ++i) {
    Rng rng(seed, {i});
    double best2 = -1;
    Point<D> winner{};
    for (std::uint64_t t = 0; t < static_cast<std::uint64_t>(m) * i; ++t) {
      const Point<D> c = uniform_point(rng, domain);
      double nearest2 = INFINITY;
      for (std::uint64_t j = 0; j < i; ++j) nearest2 = std::min(nearest2, domain.distance2(c, points[j]));
      if (nearest2 > best2) {
        best2 = nearest2;
        winner = c;
      }
    }
    ASSERT_EQ(points[i], winner) << D << "D, round " << i;
  }
}

TEST(BestCandidate, EarlyRoundsAreTheLiteralFarthestOfMTimesICandidates) {
  // While m*i < 256 the candidates are exactly m*i uniform points.
  expect_literal_rounds(Domain<2>::unit(true), 60, 4, 8);
}

TEST(BestCandidate, FromFourDimensionsEveryRoundIsLiteral) {
  // Past 3D every round draws exactly m*i candidates, and the grid's pruned
  // walk (reject when a sample lies within the best so far, else an exact
  // nearest search) must pick the very candidate brute force picks.
  expect_literal_rounds(Domain<4>{{-1, 0, 0, 0}, {1, 1, 0.5, 1}, false}, 150, 4, 3);
  expect_literal_rounds(Domain<6>::unit(true), 120, 4, 5);
  expect_literal_rounds(Domain<8>::unit(false), 100, 3, 7);
}

// Mitchell's method taken literally: sample i+1 is the farthest of exactly
// m*i uniform candidates (stream (seed, 999, i)), with exact nearest-sample
// distances from a grid. Returns the distance at which each sample was placed.
template <int D>
std::vector<double> literal_best_candidate(std::size_t n, int m, const Domain<D>& domain, std::uint64_t seed) {
  const double spacing = std::pow(domain.volume() / static_cast<double>(n), 1.0 / D);
  Grid<D> grid(domain, spacing);
  std::vector<double> distance{INFINITY};
  {
    Rng rng(seed, {999, 0});
    grid.insert(uniform_point(rng, domain));
  }
  for (std::uint64_t i = 1; i < n; ++i) {
    Rng rng(seed, {999, i});
    double best2 = -1.0;
    Point<D> winner{};
    for (std::uint64_t t = 0; t < static_cast<std::uint64_t>(m) * i; ++t) {
      const Point<D> c = uniform_point(rng, domain);
      if (best2 >= 0.0 && grid.any_closer_than(c, std::sqrt(best2))) continue;
      double nearest2 = INFINITY;
      for (double r = std::max(std::sqrt(std::max(best2, 0.0)), spacing); nearest2 == INFINITY; r *= 2.0)
        grid.for_each_within(c, r, [&](std::int32_t, double d2) {
          nearest2 = std::min(nearest2, d2);
          return true;
        });
      if (nearest2 > best2) {
        best2 = nearest2;
        winner = c;
      }
    }
    grid.insert(winner);
    distance.push_back(std::sqrt(best2));
  }
  return distance;
}

struct MeanAndError {
  double mean, error;  // the mean over seeds and its standard error
};

MeanAndError mean_and_error(const std::vector<double>& v) {
  double sum = 0.0, sum2 = 0.0;
  for (double x : v) sum += x;
  const double mean = sum / static_cast<double>(v.size());
  for (double x : v) sum2 += (x - mean) * (x - mean);
  return {mean, std::sqrt(sum2 / static_cast<double>(v.size() - 1) / static_cast<double>(v.size()))};
}

// Over `seeds` runs of n samples, two statistics of the placement distances
// of the library and of the literal method must agree within 4 standard
// errors of their difference (measured in the run): the mean of
// i^(1/D) x distance over the second half of the rounds (the typical gap
// filled) and the final minimum distance (the smallest gap filled).
template <int D>
void expect_same_distribution_as_literal(const Domain<D>& domain, std::size_t n, int seeds) {
  std::vector<double> lib_mean, lit_mean, lib_min, lit_min;
  auto summarise = [&](const std::vector<double>& d, std::vector<double>& means, std::vector<double>& mins) {
    double sum = 0.0, least = INFINITY;
    for (std::size_t i = n / 2; i < n; ++i) sum += d[i] * std::pow(static_cast<double>(i), 1.0 / D);
    for (std::size_t i = 1; i < n; ++i) least = std::min(least, d[i]);
    means.push_back(sum / static_cast<double>(n - n / 2));
    mins.push_back(least);
  };
  BestCandidateParams params;
  params.count = n;
  for (int seed = 1; seed <= seeds; ++seed) {
    summarise(best_candidate_run(params, domain, static_cast<std::uint64_t>(seed)).distance, lib_mean, lib_min);
    summarise(literal_best_candidate(n, params.m, domain, static_cast<std::uint64_t>(seed)), lit_mean, lit_min);
  }
  for (const auto& [name, lib, lit] : {std::tuple{"mean of i^(1/D) x distance", lib_mean, lit_mean},
                                       std::tuple{"minimum distance", lib_min, lit_min}}) {
    const MeanAndError a = mean_and_error(lib), b = mean_and_error(lit);
    const double sigma = std::hypot(a.error, b.error);
    EXPECT_GT(sigma, 0.0);
    EXPECT_LT(std::abs(a.mean - b.mean), 4.0 * sigma) << name << " on " << domain << ": library " << a.mean << " +- "
                                                      << a.error << ", literal " << b.mean << " +- " << b.error;
    std::cout << "[ stat     ] " << name << " on " << domain << ": library " << a.mean << " +- " << a.error
              << ", literal " << b.mean << " +- " << b.error << "\n";
  }
}

TEST(BestCandidate, SameDistributionAsTheLiteralMethod) {
  // From m*i = 256 on, the library draws a Poisson number of candidates and
  // skips most of them; the samples it places must be distributed as in
  // Mitchell's method with exactly m*i candidates a round (m = 10), in 2D on
  // a torus and in 3D in a box. With these seeds the standard errors are
  // about 0.04% of the mean gap and 0.15-0.2% of the minimum distance, so a
  // bias of about a per cent is caught (drawing a fixed number of candidates
  // a round, or skipping part of the domain, shifts both by far more).
  expect_same_distribution_as_literal(Domain<2>::unit(true), 400, 50);
  expect_same_distribution_as_literal(Domain<3>{{0, 0, 0}, {1, 0.8, 0.6}, false}, 250, 40);
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
  // More leaf cells than the budget: refused at once, not after hours.
  params.radius = 1e-6;
  EXPECT_THROW(best_candidate(params, Domain<2>::unit(), 1), InvalidArgument);
  params.radius.reset();
  params.count = 1'000'000'000;
  EXPECT_THROW(best_candidate(params, Domain<3>::unit(), 1), InvalidArgument);
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
