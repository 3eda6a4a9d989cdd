#include "pds/samplers/sizing.h"

#include <gtest/gtest.h>

#include "pds/analysis/relative_radius.h"
#include "pds/error.h"
#include "pds/registry.h"
#include "pds/samplers/ebeida.h"
#include "pds/samplers/maximal_darts.h"

namespace pds {
namespace {

TEST(SizeRequest, RadiusOnlyMethodsGetTheRadiusOfThePolicy) {
  for (const Method& m : methods()) {
    GenerateRequest request;
    request.torus = true;
    request.count = 1000;
    request.seed = 1;
    const GenerateRequest sized = size_request(m, request);
    if (m.takes_count) {
      EXPECT_EQ(sized.count, request.count) << m.name;
      EXPECT_FALSE(sized.radius) << m.name;
      continue;
    }
    EXPECT_FALSE(sized.count) << m.name;
    ASSERT_TRUE(sized.radius) << m.name;
    EXPECT_EQ(*sized.radius, radius_for_count(1000, Domain<2>::unit(true), kCountRelativeRadius)) << m.name;
    // Maximal sets reach a relative radius above the policy's, so about the
    // count or more (up to (0.90 / 0.75)^2 = 1.44 times it).
    const std::size_t n = generate(m.name, sized).size();
    EXPECT_GE(n, 1000u) << m.name;
    EXPECT_LE(n, 1500u) << m.name;
  }
}

TEST(SizeRequest, GivenRadiusOrNoCountIsLeftAlone) {
  const Method& ebeida = find_method("ebeida");
  GenerateRequest request;
  request.radius = 0.05;
  request.count = 10;
  EXPECT_EQ(size_request(ebeida, request).radius, 0.05);
  EXPECT_EQ(size_request(ebeida, request).count, 10u);  // generate() then says it takes no count
  EXPECT_FALSE(size_request(ebeida, GenerateRequest{}).radius);
}

// Axes shorter than the radius count as the radius: the only change from
// the volume, so sizing elsewhere keeps its figures.
TEST(SizingVolume, AxesShorterThanTheRadiusCountAsTheRadius) {
  EXPECT_EQ(sizing_volume(Domain<2>::box({0, 0}, {2, 0.5}), 0.1), 1.0);
  EXPECT_EQ(sizing_volume(Domain<2>::box({0, 0}, {2, 0.5}), 1.0), 2.0);
  EXPECT_EQ(sizing_volume(Domain<3>::box({0, 0, 0}, {1000, 1e-6, 1e-6}), 0.01), 1000 * 0.01 * 0.01);
  EXPECT_EQ(sizing_volume(Domain<3>::torus({0, 0, 0}, {1, 1, 1e-3}), 0.01), 0.01);
  // The samplers' own budgets use it too, whatever the registry checked.
  const auto tube = Domain<3>::box({0, 0, 0}, {1000, 1e-6, 1e-6});
  EXPECT_THROW(ebeida<3>({.radius = 0.01, .max_points = 1500}, tube, 1), InvalidArgument);
  EXPECT_THROW(maximal_darts<3>({.radius = 0.01, .max_points = 1500}, tube, 1), InvalidArgument);
  // A count in a thin box: the radius grows until the box's length sizes it
  // (rho 0.75 of the densest packing: 100 points on a line of 100 are 1.5 apart).
  const double r = radius_for_count(100, Domain<3>::box({0, 0, 0}, {100, 1e-6, 1e-6}), 0.75);
  EXPECT_GT(r, 0.5);
  EXPECT_LT(r, 2.0);
  EXPECT_EQ(radius_for_count(100, Domain<2>::unit(), 0.75), 2.0 * 0.75 * max_packing_radius(1.0, 100, 2));
  // Past the longest axis nothing is left to size by: the volume's answer
  // stands (one point in the 8D unit box; the fixed point has none there).
  EXPECT_EQ(radius_for_count(1, Domain<8>::unit(), 0.75), 2.0 * 0.75 * max_packing_radius(1.0, 1, 8));
  EXPECT_LE(radius_for_count(1, Domain<3>::box({0, 0, 0}, {2, 1e-3, 1e-3}), 0.75), 2.0);
}

}  // namespace
}  // namespace pds
