#include "pds/samplers/dart_throwing.h"

#include <gtest/gtest.h>

#include "pds/analysis/distance.h"
#include "pds/analysis/relative_radius.h"
#include "pds/error.h"
#include "pds/samplers/sizing.h"
#include "pds/registry.h"

namespace pds {
namespace {

template <int D>
void expect_all_pairs_equals_grid(const Domain<D>& domain, DartThrowingParams params, std::uint64_t seed) {
  params.all_pairs = true;
  const PointSet<D> literal = dart_throwing(params, domain, seed);
  params.all_pairs = false;
  const PointSet<D> grid = dart_throwing(params, domain, seed);
  ASSERT_GT(literal.size(), 50u);
  EXPECT_EQ(literal, grid) << domain << " radius " << params.radius;
}

TEST(DartThrowing, AllPairsAndGridAcceptTheSameSamples) {
  DartThrowingParams params;
  params.radius = 0.05;
  params.max_failures = 3000;  // run to (near) exhaustion
  for (bool torus : {false, true}) {
    expect_all_pairs_equals_grid(Domain<2>::unit(torus), params, 11);
    expect_all_pairs_equals_grid(Domain<2>{{-1, 0}, {0.5, 0.7}, torus}, params, 12);
    params.radius = 0.12;
    expect_all_pairs_equals_grid(Domain<3>{{0, 0, 0}, {1, 0.8, 1.3}, torus}, params, 13);
    params.radius = 0.05;
  }
  DartThrowingParams counted;
  counted.radius = 0.03;
  counted.count = 500;
  expect_all_pairs_equals_grid(Domain<2>::unit(true), counted, 14);
}

TEST(DartThrowing, CountGivesExactlyThatManyAtTheRadius) {
  const auto domain = Domain<3>::unit(true);
  DartThrowingParams params;
  params.count = 1000;
  params.radius = radius_for_count(1000, domain, kDartCountRho);
  const PointSet<3> points = dart_throwing(params, domain, 5);
  ASSERT_EQ(points.size(), 1000u);
  const MinDistance md = min_distance_brute_force(points, domain);
  EXPECT_GE(md.distance, params.radius);
  EXPECT_GE(relative_radius(md.distance, 1.0, 1000, 3), kDartCountRho);
}

TEST(DartThrowing, RadiusOnlyStopsAtTheFailureBound) {
  // A small bound stops early; a larger one packs more: the bound is what ends
  // the loop, and the result is what was placed.
  const auto domain = Domain<2>::unit(true);
  DartThrowingParams params;
  params.radius = 0.03;
  params.max_failures = 10;
  const auto early = dart_throwing(params, domain, 3);
  params.max_failures = 0;
  const auto full = dart_throwing(params, domain, 3);
  EXPECT_LT(early.size(), full.size());
  EXPECT_TRUE(std::equal(early.begin(), early.end(), full.begin()));  // same stream, a prefix
  EXPECT_EQ(default_dart_failures(domain, 0.03), kDartMinFailures);
  EXPECT_GT(default_dart_failures(domain, 0.001), kDartMinFailures);
}

TEST(DartThrowing, RadiusLargerThanTheDomainGivesOnePoint) {
  DartThrowingParams params;
  params.radius = 5.0;
  for (bool torus : {false, true}) {
    const auto points = dart_throwing(params, Domain<2>::unit(torus), 1);
    ASSERT_EQ(points.size(), 1u);
    EXPECT_TRUE(Domain<2>::unit(torus).contains(points[0]));
  }
  params.count = 1;
  EXPECT_EQ(dart_throwing(params, Domain<3>::unit(), 1).size(), 1u);
  params.count = 2;
  EXPECT_THROW(dart_throwing(params, Domain<3>::unit(), 1), InvalidArgument);
}

TEST(DartThrowing, CountThatCannotFitIsRejected) {
  DartThrowingParams params;
  params.radius = 0.1;
  params.count = 200;  // above the densest-packing bound (~139 in the unit square)
  try {
    dart_throwing(params, Domain<2>::unit(), 1);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("cannot fit"), std::string::npos) << e.what();
  }
  // Below the packing bound but far above what random darts can place: the
  // failure bound ends the loop and the error says how many were placed.
  params.count = 110;
  params.max_failures = 2000;
  try {
    dart_throwing(params, Domain<2>::unit(true), 1);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("placed only"), std::string::npos) << e.what();
  }
}

TEST(DartThrowing, BadRadiusAndCount) {
  DartThrowingParams params;
  for (double r : {0.0, -1.0, double(NAN), double(INFINITY)}) {
    params.radius = r;
    EXPECT_THROW(dart_throwing(params, Domain<2>::unit(), 1), InvalidArgument) << r;
  }
  params.radius = 0.1;
  params.count = 0;
  EXPECT_THROW(dart_throwing(params, Domain<2>::unit(), 1), InvalidArgument);
  EXPECT_THROW(radius_for_count(0, Domain<2>::unit(), 0.7), InvalidArgument);
  EXPECT_THROW(radius_for_count(10, Domain<2>::unit(), 0.0), InvalidArgument);
  EXPECT_THROW(radius_for_count(10, Domain<2>::unit(), 1.5), InvalidArgument);
}

TEST(DartThrowing, RadiusForCountInvertsTheRelativeRadius) {
  const auto domain = Domain<2>::box({0, 0}, {2, 3});
  const double r = radius_for_count(5000, domain, 0.7);
  EXPECT_NEAR(relative_radius(r, domain.volume(), 5000, 2), 0.7, 1e-12);
  const auto cube = Domain<3>::box({0, 0, 0}, {1, 2, 0.5});
  EXPECT_NEAR(relative_radius(radius_for_count(777, cube, 0.6), cube.volume(), 777, 3), 0.6, 1e-12);
}

TEST(DartThrowing, RegistryParameters) {
  GenerateRequest r;
  r.radius = 0.05;
  r.params = {{"all-pairs", 1}};
  const PointCloud literal = generate("dart-throwing", r);
  r.params = {};
  EXPECT_EQ(generate("dart-throwing", r), literal);
  r.params = {{"all-pairs", 2}};
  EXPECT_THROW(generate("dart-throwing", r), InvalidArgument);
  r.params = {{"rho", 0}};
  EXPECT_THROW(generate("dart-throwing", r), InvalidArgument);
  r.params = {};
  r.radius.reset();
  r.count = 300;
  EXPECT_EQ(generate("dart-throwing", r).size(), 300u);
  r.radius = 0.2;  // at most ~35 fit
  EXPECT_THROW(generate("dart-throwing", r), InvalidArgument);
}

}  // namespace
}  // namespace pds
