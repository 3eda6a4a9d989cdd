#include "pds/analysis/report.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pds/analysis/relative_radius.h"
#include "pds/error.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

// An n x n grid at cell centres of the unit square: spacing h = 1/n, exact in
// binary for n a power of two, covering radius h / sqrt(2) (the cell corners,
// box or torus alike).
PointSet<2> grid(int n) {
  PointSet<2> points;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) points.push_back({(i + 0.5) / n, (j + 0.5) / n});
  return points;
}

TEST(AnalysisReport, RegularGridExactDistancesBoxAndTorus) {
  for (bool torus : {false, true}) {
    const Domain<2> domain = Domain<2>::unit(torus);
    const PointSet<2> points = grid(8);
    const AnalysisReport r = analyze(points, domain);
    EXPECT_EQ(r.count, 64u);
    EXPECT_EQ(r.dim, 2);
    EXPECT_EQ(r.torus, torus);
    EXPECT_EQ(r.lo, (std::vector<double>{0, 0}));
    EXPECT_EQ(r.hi, (std::vector<double>{1, 1}));
    EXPECT_EQ(r.min_distance, 0.125);
    ASSERT_TRUE(r.min_distance_pair);
    const auto [i, j] = *r.min_distance_pair;
    EXPECT_LT(i, j);
    EXPECT_EQ(std::sqrt(domain.distance2(points[i], points[j])), 0.125);
    EXPECT_EQ(r.mean_nn_distance, 0.125);
    EXPECT_DOUBLE_EQ(r.relative_radius, 0.0625 / max_packing_radius(1.0, 64, 2));
    EXPECT_NEAR(r.relative_radius, 0.9306, 1e-4);  // a square grid's rho (Lagae & Dutre 2008)
    EXPECT_FALSE(r.radius);
    EXPECT_FALSE(r.maximality);
    EXPECT_EQ(r.sets, 1u);
    EXPECT_DOUBLE_EQ(r.rho_min, r.relative_radius);
    ASSERT_TRUE(r.spectrum);
    EXPECT_EQ(r.spectrum->max_frequency, 128);
    EXPECT_TRUE(r.spectrum_note.empty());
    ASSERT_TRUE(r.pcf);
    EXPECT_GT(r.pcf->peak_g, 1.0);
  }
}

TEST(AnalysisReport, GridIsMaximalAtItsCoveringRadiusAndNotBelow) {
  const double h = 0.125, cover = h / std::sqrt(2.0);
  for (bool torus : {false, true}) {
    const Domain<2> domain = Domain<2>::unit(torus);
    const PointSet<2> points = grid(8);

    const AnalysisReport at_spacing = analyze(points, domain, {.radius = h});
    EXPECT_TRUE(at_spacing.min_distance_holds);
    ASSERT_TRUE(at_spacing.maximality);
    EXPECT_TRUE(at_spacing.maximality->maximal);
    EXPECT_FALSE(at_spacing.maximality->gap);

    const AnalysisReport above = analyze(points, domain, {.radius = cover * (1 + 1e-6)});
    EXPECT_TRUE(above.maximality->maximal) << "torus " << torus;

    const AnalysisReport below = analyze(points, domain, {.radius = cover * (1 - 1e-6)});
    ASSERT_TRUE(below.maximality);
    EXPECT_FALSE(below.maximality->maximal) << "torus " << torus;
    ASSERT_TRUE(below.maximality->gap);
    EXPECT_EQ(below.maximality->gap->size(), 2u);
    EXPECT_GT(below.maximality->gap_distance, cover * (1 - 1e-6));
    EXPECT_LE(below.maximality->gap_distance, cover * (1 + 1e-12));

    const AnalysisReport too_far = analyze(points, domain, {.radius = h * 1.01});
    EXPECT_FALSE(too_far.min_distance_holds);
    EXPECT_TRUE(too_far.maximality->maximal);
  }
}

TEST(AnalysisReport, SeveralSetsFirstSetFieldsAndMeans) {
  const Domain<2> domain = Domain<2>::unit(true);
  const std::vector<PointSet<2>> sets{grid(8), white_noise<2>({.count = 100}, domain, 3)};
  const AnalysisReport r = analyze<2>(sets, domain, {.max_frequency = 16});
  EXPECT_EQ(r.count, 64u);
  EXPECT_EQ(r.sets, 2u);
  const AnalysisReport second = analyze(sets[1], domain, {.max_frequency = 16});
  EXPECT_DOUBLE_EQ(r.rho_min, (r.relative_radius + second.rho_min) / 2);
  ASSERT_TRUE(r.spectrum);
  EXPECT_EQ(r.spectrum->max_frequency, 16);
}

TEST(AnalysisReport, SpectrumSkippedBeyondItsWorkUnlessAsked) {
  const Domain<2> domain = Domain<2>::unit(true);
  const PointSet<2> points = grid(4);
  const AnalysisReport skipped = analyze(points, domain, {.spectrum_work = 10});
  EXPECT_FALSE(skipped.spectrum);
  EXPECT_FALSE(skipped.spectrum_note.empty());
  AnalysisCurves curves;
  const AnalysisReport asked =
      analyze<2>(std::span(&points, 1), domain, {.max_frequency = 8, .spectrum = true, .spectrum_work = 10}, &curves);
  ASSERT_TRUE(asked.spectrum);
  ASSERT_TRUE(curves.periodogram && curves.radial && curves.pcf);
  EXPECT_EQ(curves.periodogram->max_frequency, 8);
  EXPECT_EQ(asked.pcf->r_max, curves.pcf->r.back());
}

TEST(AnalysisReport, SmallSetsHaveNoDistances) {
  const Domain<2> domain = Domain<2>::unit();
  const AnalysisReport one = analyze(PointSet<2>{{0.5, 0.5}}, domain);
  EXPECT_EQ(one.count, 1u);
  EXPECT_TRUE(std::isinf(one.min_distance));
  EXPECT_FALSE(one.min_distance_pair);
  EXPECT_TRUE(std::isnan(one.mean_nn_distance));
  EXPECT_TRUE(std::isnan(one.rho_min));
  EXPECT_FALSE(one.pcf);
  const AnalysisReport none = analyze(PointSet<2>{}, domain);
  EXPECT_TRUE(std::isnan(none.max_packing_radius));
  EXPECT_FALSE(none.spectrum);
  EXPECT_TRUE(none.spectrum_note.empty());
  EXPECT_FALSE(none.l2_star_discrepancy);
}

TEST(AnalysisReport, RejectsPointsOutsideAndBadRadii) {
  const Domain<2> domain = Domain<2>::unit();
  EXPECT_THROW(analyze(PointSet<2>{{0.5, 1.0}}, domain), InvalidArgument);
  EXPECT_THROW(analyze(grid(2), domain, {.radius = 0.0}), InvalidArgument);
  EXPECT_THROW(analyze<2>(std::span<const PointSet<2>>(), domain), InvalidArgument);
}

TEST(AnalysisReport, ThreeDimensions) {
  PointSet<3> points;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) points.push_back({(i + 0.5) / 4, (j + 0.5) / 4, (k + 0.5) / 4});
  const AnalysisReport r = analyze(points, Domain<3>::unit(true), {.radius = 0.25});
  EXPECT_EQ(r.dim, 3);
  EXPECT_EQ(r.min_distance, 0.25);
  EXPECT_TRUE(r.min_distance_holds);
  EXPECT_TRUE(r.maximality->maximal);  // covering radius 0.25 * sqrt(3) / 2 < 0.25
  EXPECT_EQ(r.spectrum->max_frequency, 32);
}

}  // namespace
}  // namespace pds
