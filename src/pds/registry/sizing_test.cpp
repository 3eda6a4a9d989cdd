#include "pds/samplers/sizing.h"

#include <gtest/gtest.h>

#include "pds/registry.h"

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

}  // namespace
}  // namespace pds
