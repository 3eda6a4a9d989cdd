#include "pds/samplers/multi_class.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pds/analysis/spectrum.h"
#include "pds/error.h"

namespace pds {
namespace {

TEST(MultiClass, MatrixFollowsTheUnionsDensities) {
  // Radii halving from class to class, given out of order.
  const std::vector<double> radii = {0.1, 0.4, 0.2};
  const std::vector<double> m = multi_class_matrix(radii, 2);
  const auto at = [&](int c, int j) { return m[static_cast<std::size_t>(c * 3 + j)]; };
  for (int c = 0; c < 3; ++c) EXPECT_EQ(at(c, c), radii[static_cast<std::size_t>(c)]);
  for (int c = 0; c < 3; ++c)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(at(c, j), at(j, c));
  // 0.4 with 0.2: (0.4^-2 + 0.2^-2)^-1/2; anything with 0.1: all three.
  EXPECT_NEAR(at(1, 2), 1 / std::sqrt(6.25 + 25), 1e-15);
  EXPECT_NEAR(at(0, 1), 1 / std::sqrt(6.25 + 25 + 100), 1e-15);
  EXPECT_NEAR(at(0, 2), at(0, 1), 1e-15);
  // Equal radii: the union is twice as dense.
  const std::vector<double> twin = multi_class_matrix({0.1, 0.1}, 3);
  EXPECT_NEAR(twin[1], 0.1 / std::cbrt(2.0), 1e-15);
  EXPECT_THROW(multi_class_matrix({}, 2), InvalidArgument);
  EXPECT_THROW(multi_class_matrix({0.1, 0.0}, 2), InvalidArgument);
}

TEST(MultiClass, EveryPairKeepsItsClassesRadius) {
  for (bool torus : {false, true}) {
    const Domain<2> domain = Domain<2>::unit(torus);
    MultiClassParams params;
    params.radii = {0.02, 0.04, 0.08};
    const MultiClassSet<2> set = multi_class(params, domain, 3);
    const std::vector<double> m = multi_class_matrix(params.radii, 2);
    ASSERT_EQ(set.points.size(), set.classes.size());
    std::size_t bad = 0;
    std::vector<std::size_t> count(3, 0);
    for (std::size_t i = 0; i < set.points.size(); ++i) {
      ASSERT_TRUE(domain.contains(set.points[i]));
      ++count[set.classes[i]];
      for (std::size_t j = 0; j < i; ++j) {
        const double r = m[set.classes[i] * 3 + set.classes[j]];
        bad += domain.distance2(set.points[i], set.points[j]) < r * r;
      }
    }
    EXPECT_EQ(bad, 0u);
    // Counts about in proportion to r^-2: 16 : 4 : 1.
    EXPECT_NEAR(static_cast<double>(count[0]) / count[2], 16.0, 16.0 * 0.35);
    EXPECT_NEAR(static_cast<double>(count[1]) / count[2], 4.0, 4.0 * 0.35);
    EXPECT_EQ(set.points, multi_class(params, domain, 3).points);
    EXPECT_NE(set.points, multi_class(params, domain, 4).points);
  }
}

TEST(MultiClass, AGivenMatrixIsHonouredAndChecked) {
  // Cross distance 0.05, larger than both radii: the classes keep farther
  // apart from each other than within themselves.
  const Domain<2> domain = Domain<2>::unit(true);
  MultiClassParams params;
  params.radii = {0.02, 0.03};
  params.matrix = {0.02, 0.05, 0.05, 0.03};
  const MultiClassSet<2> set = multi_class(params, domain, 5);
  std::size_t bad = 0;
  double closest_cross = INFINITY;
  for (std::size_t i = 0; i < set.points.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      const double r = params.matrix[set.classes[i] * 2 + set.classes[j]];
      const double d2 = domain.distance2(set.points[i], set.points[j]);
      bad += d2 < r * r;
      if (set.classes[i] != set.classes[j]) closest_cross = std::min(closest_cross, std::sqrt(d2));
    }
  EXPECT_EQ(bad, 0u);
  EXPECT_GE(closest_cross, 0.05);
  EXPECT_GT(set.points.size(), 300u);
  params.matrix = {0.02, 0.05, 0.04, 0.03};  // not symmetric
  EXPECT_THROW(multi_class(params, domain, 1), InvalidArgument);
  params.matrix = {0.02, 0.05, 0.05};  // not 2 x 2
  EXPECT_THROW(multi_class(params, domain, 1), InvalidArgument);
  params.matrix = {0.025, 0.05, 0.05, 0.03};  // diagonal not the radii
  EXPECT_THROW(multi_class(params, domain, 1), InvalidArgument);
  params.matrix = {0.02, 0.0, 0.0, 0.03};  // not a radius
  EXPECT_THROW(multi_class(params, domain, 1), InvalidArgument);
}

// Blue noise: each class alone and the union have little power at low
// frequencies (white noise has 1 everywhere), averaged over a few sets. The
// union's band reaches higher: a union of classes placed independently keeps
// each class's low band but has about twice this power at 0.3-0.6 (0.34
// against 0.16 when measured), so the test sees the cross-class radii.
TEST(MultiClass, EachClassAndTheUnionAreBlueNoise) {
  const Domain<2> domain = Domain<2>::unit(true);
  MultiClassParams params;
  params.radii = {0.03, 0.03, 0.06};
  std::vector<std::vector<PointSet<2>>> by_class(4);  // the three classes, then the union
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const MultiClassSet<2> set = multi_class(params, domain, seed);
    std::vector<PointSet<2>> parts(4);
    for (std::size_t i = 0; i < set.points.size(); ++i) {
      parts[set.classes[i]].push_back(set.points[i]);
      parts[3].push_back(set.points[i]);
    }
    for (int c = 0; c < 4; ++c) by_class[static_cast<std::size_t>(c)].push_back(parts[static_cast<std::size_t>(c)]);
  }
  // Mean power over nu in (lo, hi), nu in units of the mean spacing.
  const auto band = [&](const std::vector<PointSet<2>>& sets, double lo, double hi) {
    const RadialSpectrum radial = radial_average(periodogram<2>(sets, domain, {.max_frequency = 32}));
    double sum = 0;
    int n = 0;
    for (std::size_t b = 0; b < radial.frequency.size(); ++b)
      if (radial.frequency[b] > lo && radial.frequency[b] < hi) {
        sum += radial.power[b];
        ++n;
      }
    EXPECT_GT(n, 2);
    return sum / n;
  };
  for (int c = 0; c < 3; ++c) EXPECT_LT(band(by_class[static_cast<std::size_t>(c)], 0.05, 0.5), 0.5) << "class " << c;
  EXPECT_LT(band(by_class[3], 0.05, 0.3), 0.15);
  EXPECT_LT(band(by_class[3], 0.3, 0.6), 0.25);
}

}  // namespace
}  // namespace pds
