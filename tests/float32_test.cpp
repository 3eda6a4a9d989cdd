// float32 output through the registry: every method that promises a minimum
// distance, in its dimensions up to 3, on a box and a torus, near 0 and at
// offsets where float32 spacings are coarse (1e3, 1e6), at radii a little
// above the smallest float32 accepts, so that plain rounding does bite. Each
// set is checked by the all-pairs oracle on its float32 coordinates.

#include "pds/float32.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "pds/analysis/distance.h"
#include "pds/error.h"
#include "pds/registry.h"

namespace pds {
namespace {

struct Outcome {
  std::string failure;  // empty when the set keeps every promise
  bool plain_rounding_broke = false;
};

// The oracle on a float32 request, and whether rounding the float64 set of
// the same request (unsafe, the old way) would have put a pair closer than r.
template <int D>
Outcome check(const Method& m, GenerateRequest request) {
  const Domain<D> domain = request.domain<D>();
  const double r = *request.radius;
  request.float32 = true;
  const PointSet<D> points = generate(m.name, request).as<D>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!domain.contains(points[i])) return {"point " + std::to_string(i) + " outside the domain"};
    for (int k = 0; k < D; ++k)
      if (static_cast<double>(static_cast<float>(points[i][k])) != points[i][k])
        return {"coordinate of point " + std::to_string(i) + " is not a float32 value"};
  }
  const MinDistance closest = min_distance_brute_force(points, domain);
  if (!(closest.distance >= r))
    return {"points " + std::to_string(closest.i) + " and " + std::to_string(closest.j) + " at " +
            std::to_string(closest.distance) + " < r"};
  if (request.lo[0] < 1e6) return {};  // the offset where plain rounding is checked
  request.float32 = false;
  PointSet<D> plain = generate(m.name, request).as<D>();
  for (auto& p : plain)
    for (auto& x : p) x = static_cast<float>(x);
  return {"", !(min_distance_brute_force(plain, domain).distance >= r)};
}

TEST(Float32, EveryMinimumDistanceMethodKeepsTheRadiusAfterRounding) {
  int cases = 0, bitten = 0;
  for (const Method& m : methods()) {
    if (!m.min_distance || !m.takes_radius) continue;
    for (int dim = 1; dim <= 3; ++dim) {
      if (!m.dims.contains(dim)) continue;
      // Extents in radii giving a few hundred points.
      const double sides = dim == 1 ? 300 : dim == 2 ? 20 : 7;
      for (const bool torus : {false, true}) {
        for (const double offset : {0.0, 1e3, 1e6}) {
          GenerateRequest request;
          request.dim = dim;
          request.torus = torus;
          request.seed = 7;
          // 5% above the smallest radius float32 takes at this magnitude
          // (the extent is far below the offset, except at 0).
          const double far = offset == 0 ? 1.0 : offset * 1.01;
          const double spacing = float32_spacing(std::vector<double>(dim, offset), std::vector<double>(dim, far));
          const double r_min = 2 * std::sqrt(dim) * spacing / kFloat32MaxInflation;
          const double r = offset == 0 ? 1.0 / sides : 1.05 * r_min;
          request.radius = r;
          request.lo.assign(dim, offset);
          request.hi.assign(dim, offset + r * sides);
          if (offset == 0) request.hi.assign(dim, 1.0);
          const std::string where = m.name + " " + std::to_string(dim) + "D " + (torus ? "torus" : "box") +
                                    " at offset " + std::to_string(offset) + " radius " + std::to_string(r);
          Outcome outcome;
          visit_dim<1, 3>(dim, [&](auto d) { outcome = check<decltype(d)::value>(m, request); });
          EXPECT_EQ(outcome.failure, "") << where;
          ++cases;
          bitten += outcome.plain_rounding_broke;
        }
      }
    }
  }
  std::printf("[ float32  ] %d requests, plain rounding broke the radius in %d\n", cases, bitten);
  EXPECT_GT(cases, 30);
  // The radii are chosen so that rounding a float64 set is not enough.
  EXPECT_GT(bitten, 0) << "no case where plain rounding broke the radius: the test has no teeth";
}

TEST(Float32, PointsNearTheUpperBoundStayInside) {
  // float32 values are 0.0625 apart in [1e6, 1e6 + 1): a point in the last
  // 1/32 rounds onto hi; none may stay there.
  GenerateRequest request;
  request.lo = {1e6, 1e6};
  request.hi = {1e6 + 1, 1e6 + 1};
  request.count = 2000;
  const Domain<2> domain = request.domain<2>();
  int onto_hi = 0;
  for (const auto& p : generate("random", request).as<2>()) onto_hi += static_cast<float>(p[0]) == 1e6 + 1;
  EXPECT_GT(onto_hi, 20);  // plain rounding would leave these outside
  request.float32 = true;
  for (const auto& p : generate("random", request).as<2>()) ASSERT_TRUE(domain.contains(p)) << p;
}

TEST(Float32, RefusesWhatFloat32CannotHold) {
  GenerateRequest request;
  request.lo = {1e6, 1e6};
  request.hi = {1e6 + 100, 1e6 + 100};
  request.radius = 10;  // the spacing there is 0.0625: radius 17.7 or more
  request.float32 = true;
  try {
    generate("bridson", request);
    FAIL() << "accepted a radius below float32's resolution";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("float32: radius 10 is too small"), std::string::npos) << e.what();
  }
  request.radius = 20;
  EXPECT_NO_THROW(generate("bridson", request));
  request.lo = {1e6 + 0.01, 0};  // no float32 in [1e6 + 0.01, 1e6 + 0.05)
  request.hi = {1e6 + 0.05, 1};
  request.radius.reset();
  request.count = 10;
  EXPECT_THROW(generate("random", request), InvalidArgument);
  request.lo = {0, 0};
  request.hi = {1e39, 1};  // beyond float32's range
  EXPECT_THROW(generate("random", request), InvalidArgument);
}

}  // namespace
}  // namespace pds
