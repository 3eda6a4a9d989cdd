// One suite over every registered method x {box, torus} x {2D, 3D}: the
// properties every method promises, checked against brute-force oracles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"
#include "pds/registry.h"

namespace pds {
namespace {

struct Case {
  std::string method;
  int dim;
  bool torus;
  bool by_radius;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.method << " " << c.dim << "D " << (c.torus ? "torus" : "box") << (c.by_radius ? " --radius" : " --count");
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string name = info.param.method + "_" + std::to_string(info.param.dim) + "d_" +
                     (info.param.torus ? "torus" : "box") + (info.param.by_radius ? "_radius" : "_count");
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

std::vector<Case> all_cases(bool radius_only = false) {
  std::vector<Case> cases;
  for (const Method& m : methods())
    for (int dim : m.dims)
      for (bool torus : {false, true}) {
        if (m.takes_count && !radius_only) {
          cases.push_back({m.name, dim, torus, false});
        }
        if (m.takes_radius) {
          cases.push_back({m.name, dim, torus, true});
        }
      }
  return cases;
}

class Conformance : public ::testing::TestWithParam<Case> {
 protected:
  GenerateRequest request(std::uint64_t seed) const {
    const Case& c = GetParam();
    GenerateRequest r;
    r.dim = c.dim;
    r.torus = c.torus;
    // A non-unit domain catches code that assumes [0, 1).
    r.lo.assign(c.dim, -0.5);
    r.hi.assign(c.dim, 0.5);
    r.hi[0] = 1.5;
    if (c.by_radius) {
      r.radius = c.dim == 2 ? 0.04 : 0.15;
    } else {
      r.count = c.dim == 2 ? 800 : 512;
    }
    r.seed = seed;
    return r;
  }
};

TEST_P(Conformance, PointsAreInsideTheDomainAndCountsAreRight) {
  const GenerateRequest r = request(1);
  const PointCloud cloud = generate(GetParam().method, r);
  ASSERT_EQ(cloud.dim, r.dim);
  if (r.count) {
    EXPECT_EQ(cloud.size(), *r.count);
  }
  EXPECT_GT(cloud.size(), 0u);
  visit_dim(r.dim, [&](auto d) {
    constexpr int D = decltype(d)::value;
    const Domain<D> domain = r.domain<D>();
    for (const auto& p : cloud.as<D>()) EXPECT_TRUE(domain.contains(p)) << p << " outside " << domain;
    return 0;
  });
}

TEST_P(Conformance, SameSeedSameBytesOtherSeedOtherPoints) {
  const Method& m = find_method(GetParam().method);
  const PointCloud a = generate(m.name, request(7)), b = generate(m.name, request(7));
  EXPECT_EQ(a, b);
  if (!m.deterministic) {
    EXPECT_NE(a, generate(m.name, request(8)));
  }
}

class RadiusConformance : public Conformance {};

TEST_P(RadiusConformance, RadiusHoldsBetweenEveryPairAndMaximalityWhereClaimed) {
  const Method& m = find_method(GetParam().method);
  const GenerateRequest r = request(3);
  const PointCloud cloud = generate(m.name, r);
  visit_dim(r.dim, [&](auto d) {
    constexpr int D = decltype(d)::value;
    const Domain<D> domain = r.domain<D>();
    const auto points = cloud.as<D>();
    const MinDistance brute = min_distance_brute_force(points, domain);
    EXPECT_GE(brute.distance, *r.radius) << "points " << brute.i << " and " << brute.j << " too close";
    if (m.maximal) {
      const auto mx = check_maximality(points, domain, *r.radius);
      EXPECT_TRUE(mx.maximal) << "uncovered point " << (mx.gap ? *mx.gap : Point<D>{}) << " at distance "
                              << mx.gap_distance;
    }
    return 0;
  });
}

INSTANTIATE_TEST_SUITE_P(Registry, Conformance, ::testing::ValuesIn(all_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(Registry, RadiusConformance, ::testing::ValuesIn(all_cases(true)), case_name);

}  // namespace
}  // namespace pds
