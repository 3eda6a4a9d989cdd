#include "pds/samplers/constrained.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "flat_levels.h"
#include "pds/error.h"
#include "pds/polygon.h"
#include "pds/registry.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"
#include "radius_levels.h"

namespace pds {
namespace {

enum class Method { bridson, darts };

template <int D>
PointSet<D> run(Method method, const SamplingConstraints<D>& c, const Domain<D>& domain, std::uint64_t seed,
                double radius = 0.0) {
  if (method == Method::bridson) {
    BridsonParams p;
    p.radius = radius;
    return bridson(p, c, domain, seed);
  }
  DartThrowingParams p;
  p.radius = radius;
  return dart_throwing(p, c, domain, seed);
}

template <int D>
double radius_of(const SamplingConstraints<D>& c, const Point<D>& x, double uniform) {
  return c.radius ? std::clamp(c.radius(x), c.rmin, c.rmax) : uniform;
}

// The all-pairs oracle of the pair rule: every pair with a generated member
// is at least max(r(a), r(b)) apart, in Domain::distance2's arithmetic.
template <int D>
void expect_pair_rule(const PointSet<D>& points, const SamplingConstraints<D>& c, const Domain<D>& domain,
                      double uniform = 0.0) {
  std::vector<double> r(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) r[i] = radius_of(c, points[i], uniform);
  std::size_t bad = 0;
  for (std::size_t i = c.fixed.size(); i < points.size(); ++i) {
    ASSERT_TRUE(domain.contains(points[i])) << points[i];
    for (std::size_t j = 0; j < i; ++j) {
      const double m = std::max(r[i], r[j]);
      if (domain.distance2(points[i], points[j]) < m * m) ++bad;
    }
  }
  EXPECT_EQ(bad, 0u) << domain << ", " << points.size() << " points";
}

// A radial field over the unit square with a ratio of 10 (four radius levels).
SamplingConstraints<2> radial_field(double rmin = 0.005, double rmax = 0.05) {
  SamplingConstraints<2> c;
  c.rmin = rmin;
  c.rmax = rmax;
  c.radius = [=](const Point<2>& x) {
    const double d = std::hypot(x[0] - 0.3, x[1] - 0.4);
    return rmin + (rmax - rmin) * std::min(1.0, d / 0.8);
  };
  return c;
}

TEST(Constrained, PairRuleHoldsForAVariableField2D) {
  for (Method m : {Method::bridson, Method::darts})
    for (bool torus : {false, true}) {
      const auto c = radial_field();
      const Domain<2> domain = Domain<2>::unit(torus);
      const PointSet<2> points = run(m, c, domain, 3);
      ASSERT_GT(points.size(), 500u);
      expect_pair_rule(points, c, domain);
    }
}

TEST(Constrained, PairRuleHoldsAcrossAStepAndIn3D) {
  // A jump from 0.01 to 0.08: the coarse samples border fine ones.
  SamplingConstraints<2> step;
  step.rmin = 0.01;
  step.rmax = 0.08;
  step.radius = [](const Point<2>& x) { return x[0] < 0.5 ? 0.01 : 0.08; };
  for (Method m : {Method::bridson, Method::darts}) {
    const Domain<2> domain{{0, 0}, {1.25, 1}, true};
    expect_pair_rule(run(m, step, domain, 5), step, domain);
  }
  SamplingConstraints<3> c;
  c.rmin = 0.05;
  c.rmax = 0.2;
  c.radius = [](const Point<3>& x) { return 0.05 + 0.15 * x[2]; };
  for (Method m : {Method::bridson, Method::darts})
    for (bool torus : {false, true}) {
      const Domain<3> domain = Domain<3>::unit(torus);
      const PointSet<3> points = run(m, c, domain, 7);
      ASSERT_GT(points.size(), 100u);
      expect_pair_rule(points, c, domain);
    }
}

bool brute_force_conflict(const auto& domain, const auto& stored, const std::vector<double>& radii, const auto& x,
                          double r) {
  for (std::size_t i = 0; i < stored.size(); ++i) {
    const double m = std::max(r, radii[i]);
    if (domain.distance2(x, stored[i]) < m * m) return true;
  }
  return false;
}

// Stores `stored` points with radii log-uniform over [rmin, rmax]
// (conflicting among themselves too, unless `keep_rule`: then a point is
// stored only where brute force finds it free, as the samplers store them),
// then asks about `queries` others with radii drawn the same way: the index
// must agree with brute force, and where it has a cover (flat_levels.h), a
// point it calls covered must conflict whatever its radius (brute force
// with the smallest, rmin). Returns how many queries conflict; `covered`
// receives how many the cover decided.
template <class Index, int D>
int expect_index_matches_brute_force(const Domain<D>& domain, double rmin, double rmax, int stored_count, int queries,
                                     int expected_levels, bool keep_rule = false, int* covered = nullptr) {
  Index index(domain, rmin, rmax);
  EXPECT_EQ(index.levels(), expected_levels);
  Rng rng(17);
  PointSet<D> stored;
  std::vector<double> radii;
  const auto radius = [&] { return rmin * std::pow(rmax / rmin, rng.uniform()); };
  for (int i = 0; i < stored_count; ++i) {
    const Point<D> x = uniform_point(rng, domain);
    const double r = radius();
    if (keep_rule && brute_force_conflict(domain, stored, radii, x, r)) continue;
    stored.push_back(x);
    radii.push_back(r);
    index.insert(stored.back(), radii.back());
  }
  int conflicts = 0;
  for (int q = 0; q < queries; ++q) {
    const Point<D> x = uniform_point(rng, domain);
    const double r = radius();
    bool brute = false;
    for (std::size_t i = 0; i < stored.size(); ++i) {
      const double m = std::max(r, radii[i]);
      brute = brute || domain.distance2(x, stored[i]) < m * m;
    }
    EXPECT_EQ(index.conflicts(x, r), brute) << x << " r " << r;
    if (index.conflicts(x, r) != brute) break;
    conflicts += brute;
    if constexpr (requires { index.covered(index.spot(x)); }) {
      if (index.covered(index.spot(x))) {
        EXPECT_TRUE(brute_force_conflict(domain, stored, radii, x, rmin)) << x << " covered";
        if (covered) ++*covered;
      }
    }
  }
  return conflicts;
}

TEST(Constrained, PairRuleHoldsIn1DAnd5D) {
  SamplingConstraints<1> line;
  line.rmin = 0.001;
  line.rmax = 0.02;
  line.radius = [](const Point<1>& x) { return 0.001 + 0.019 * x[0] * x[0]; };
  SamplingConstraints<5> space;
  space.rmin = 0.25;
  space.rmax = 0.5;
  space.radius = [](const Point<5>& x) { return 0.25 + 0.25 * x[4]; };
  for (Method m : {Method::bridson, Method::darts})
    for (bool torus : {false, true}) {
      const Domain<1> d1 = Domain<1>::unit(torus);
      const PointSet<1> p1 = run(m, line, d1, 6);
      ASSERT_GT(p1.size(), 100u);
      expect_pair_rule(p1, line, d1);
      const Domain<5> d5 = Domain<5>::unit(torus);
      const PointSet<5> p5 = run(m, space, d5, 6);
      ASSERT_GT(p5.size(), 50u);
      expect_pair_rule(p5, space, d5);
    }
}

TEST(Constrained, LevelIndexFindsEveryConflict) {
  for (bool torus : {false, true}) {
    // A ratio of 60 in steps of sqrt(2): 12 levels.
    const int conflicts = expect_index_matches_brute_force<detail::RadiusLevels<2>>(Domain<2>{{-1, 0}, {0.5, 1}, torus},
                                                                                    0.002, 0.12, 150, 3000, 12);
    EXPECT_GT(conflicts, 300);  // both answers are exercised
    EXPECT_LT(conflicts, 2700);
  }
  expect_index_matches_brute_force<detail::RadiusLevels<3>>(Domain<3>::unit(true), 0.01, 0.2, 300, 2000, 9);
}

TEST(Constrained, LevelIndexBeyondItsLastLevel) {
  // A ratio of 10^6 in 1D: more than the 32 levels cover, so the last level
  // holds radii from about 46,000 rmin to rmax; still exact.
  const int conflicts =
      expect_index_matches_brute_force<detail::RadiusLevels<1>>(Domain<1>::unit(true), 1e-6, 1.0, 200, 2000, 32);
  EXPECT_GT(conflicts, 200);
}

// The flat index of 1 to 3 dimensions (flat_levels.h) against brute force:
// points stored as the samplers store them (the rule kept: one a cell, the
// list scan and the other levels' bits decide) and in any way (fixed points:
// cells shared, the overflow index decides too); a box and a torus whose
// bounds hold the origin (where an empty cell's zeros lie), axes a few cells
// long (the margin wraps several times; 7 cells at the coarsest level), a
// constant radius, and more levels than the 32 bits hold. Its cover is
// checked on the way (every covered point conflicts), and must decide many.
TEST(Constrained, FlatIndexFindsEveryConflict) {
  using Flat2 = detail::FlatLevels<2>;
  for (bool torus : {false, true}) {
    const Domain<2> wide{{-1, -0.3}, {0.5, 1}, torus};
    for (bool keep_rule : {false, true}) {
      // 13 levels: in 2D a level spans just under sqrt(2) (2 cell edges).
      int covered = 0;
      const int conflicts = expect_index_matches_brute_force<Flat2>(wide, 0.002, 0.12, keep_rule ? 3000 : 150, 3000, 13,
                                                                    keep_rule, &covered);
      EXPECT_GT(conflicts, 300);
      EXPECT_LT(conflicts, 2900);
      EXPECT_GT(covered, conflicts / 3);
    }
    const Domain<2> narrow{{0, 0}, {1, 0.02}, torus};
    EXPECT_GT(expect_index_matches_brute_force<Flat2>(narrow, 0.0005, 0.006, 2000, 3000, 8, true), 300);
    EXPECT_GT(expect_index_matches_brute_force<Flat2>(wide, 0.01, 0.01, 3000, 3000, 1, true), 300);
    EXPECT_GT(expect_index_matches_brute_force<detail::FlatLevels<3>>(Domain<3>{{-0.5, 0, 0}, {0.5, 1, 1}, torus}, 0.01,
                                                                      0.2, 3000, 2000, 9, true),
              200);
    EXPECT_GT(expect_index_matches_brute_force<detail::FlatLevels<1>>(Domain<1>{{-0.5}, {0.5}, torus}, 1e-6, 1.0, 2000,
                                                                      2000, 32, true),
              200);
  }
}

// Counts in vertical strips follow the integral of 1/r^2 over the strip:
// count_i ~ K * I_i with one constant K for all strips, within a few
// standard deviations (a Poisson disk set's counts vary less than
// Poisson's sqrt(n), so 4 sqrt(n) is generous), and K is the one a
// uniform set of the method has (2 rho^2 / sqrt(3), rho in the method's
// band: 0.70-0.78).
TEST(Constrained, LocalDensityFollowsTheField) {
  const double rmin = 0.006, rmax = 0.024;
  SamplingConstraints<2> c;
  c.rmin = rmin;
  c.rmax = rmax;
  const auto r_of_x = [=](double x) { return rmin + (rmax - rmin) * x; };
  c.radius = [=](const Point<2>& p) { return r_of_x(p[0]); };
  const Domain<2> domain = Domain<2>::unit(false);
  for (Method m : {Method::bridson, Method::darts}) {
    const PointSet<2> points = run(m, c, domain, 21);
    const int strips = 8;
    const double x0 = 0.1, width = 0.1, y0 = 0.1, y1 = 0.9;  // away from the box's faces
    std::vector<double> count(strips, 0.0), integral(strips);
    for (int s = 0; s < strips; ++s) {
      // Integral over the strip of 1/r(x)^2 = (y1 - y0) * [-1/(slope r)] between its ends.
      const double a = x0 + s * width, b = a + width, slope = rmax - rmin;
      integral[s] = (y1 - y0) * (1.0 / r_of_x(a) - 1.0 / r_of_x(b)) / slope;
    }
    for (const auto& p : points)
      if (p[0] >= x0 && p[0] < x0 + strips * width && p[1] >= y0 && p[1] < y1)
        ++count[static_cast<std::size_t>((p[0] - x0) / width)];
    double total_count = 0, total_integral = 0;
    for (int s = 0; s < strips; ++s) {
      total_count += count[s];
      total_integral += integral[s];
    }
    const double k = total_count / total_integral;
    EXPECT_GT(k, 2 * 0.70 * 0.70 / std::sqrt(3.0));
    EXPECT_LT(k, 2 * 0.78 * 0.78 / std::sqrt(3.0));
    for (int s = 0; s < strips; ++s) {
      const double expected = k * integral[s];
      EXPECT_NEAR(count[s], expected, 4 * std::sqrt(expected)) << "strip " << s;
    }
    EXPECT_GT(count[0], 5 * count[strips - 1]);  // the field really varies
  }
}

TEST(Constrained, MaskIsRespectedAndEveryIslandFilled) {
  // Two disjoint discs and a ring: Bridson's front cannot walk from one to
  // another; the restart darts find each.
  SamplingConstraints<2> c;
  const auto in_disc = [](const Point<2>& x, double cx, double cy, double r) {
    return std::hypot(x[0] - cx, x[1] - cy) < r;
  };
  c.inside = [&](const Point<2>& x) {
    return in_disc(x, 0.2, 0.2, 0.1) || in_disc(x, 0.75, 0.7, 0.15) ||
           (in_disc(x, 0.3, 0.75, 0.2) && !in_disc(x, 0.3, 0.75, 0.12));
  };
  const double r = 0.02;
  for (Method m : {Method::bridson, Method::darts}) {
    const Domain<2> domain = Domain<2>::unit(false);
    const PointSet<2> points = run(m, c, domain, 9, r);
    expect_pair_rule(points, c, domain, r);
    int island[3] = {0, 0, 0};
    for (const auto& p : points) {
      ASSERT_TRUE(c.inside(p)) << p;
      island[0] += in_disc(p, 0.2, 0.2, 0.1);
      island[1] += in_disc(p, 0.75, 0.7, 0.15);
      island[2] += in_disc(p, 0.3, 0.75, 0.2);
    }
    // About K area / r^2 each (K ~ 0.6; fewer along the edges).
    EXPECT_GT(island[0], 0.35 * 0.0314 / (r * r));
    EXPECT_GT(island[1], 0.35 * 0.0707 / (r * r));
    EXPECT_GT(island[2], 0.35 * 0.0804 / (r * r));
  }
}

TEST(Constrained, PolygonWithHoleAsMask) {
  Region region;
  region.polygons.push_back({{{{0.1, 0.1}}, {{0.9, 0.1}}, {{0.9, 0.9}}, {{0.1, 0.9}}},
                             {{{{0.3, 0.3}}, {{0.7, 0.3}}, {{0.7, 0.7}}, {{0.3, 0.7}}}}});
  SamplingConstraints<2> c = radial_field(0.01, 0.03);
  c.inside = [&](const Point<2>& x) { return region.contains(x); };
  const Domain<2> domain = Domain<2>::unit(true);
  const PointSet<2> points = run(Method::bridson, c, domain, 4);
  expect_pair_rule(points, c, domain);
  ASSERT_GT(points.size(), 300u);
  for (const auto& p : points) {
    EXPECT_TRUE(p[0] > 0.1 && p[0] < 0.9 && p[1] > 0.1 && p[1] < 0.9) << p;
    EXPECT_FALSE(p[0] > 0.3 && p[0] < 0.7 && p[1] > 0.3 && p[1] < 0.7) << p;
  }
}

TEST(Constrained, FixedPointsComeFirstAndAreFilledAround) {
  const Domain<2> domain = Domain<2>::unit(false);
  const double r = 0.03;
  SamplingConstraints<2> c;
  // Two of them closer than r to each other: kept all the same.
  c.fixed = {Point<2>{{0.5, 0.5}}, Point<2>{{0.51, 0.5}}, Point<2>{{0.1, 0.9}}, Point<2>{{0, 0}}};
  for (Method m : {Method::bridson, Method::darts}) {
    const PointSet<2> points = run(m, c, domain, 12, r);
    ASSERT_GT(points.size(), 400u);
    EXPECT_TRUE(std::equal(c.fixed.begin(), c.fixed.end(), points.begin()));
    expect_pair_rule(points, c, domain, r);
    // Filled: no probe is 2r from every sample (an empty disk of radius 2r).
    Rng rng(5);
    for (int q = 0; q < 2000; ++q) {
      const Point<2> x = uniform_point(rng, domain);
      double nearest = 1e9;
      for (const auto& p : points) nearest = std::min(nearest, domain.distance2(x, p));
      ASSERT_LT(nearest, 4 * r * r) << x;
    }
  }
}

TEST(Constrained, ExtendingASetAddsOnlyWhereThereIsRoom) {
  // A Bridson set on the left half, then the whole square with it fixed.
  const double r = 0.03;
  SamplingConstraints<2> left;
  left.inside = [](const Point<2>& x) { return x[0] < 0.5; };
  const Domain<2> domain = Domain<2>::unit(false);
  SamplingConstraints<2> extend;
  extend.fixed = run(Method::bridson, left, domain, 1, r);
  const PointSet<2> whole = run(Method::bridson, extend, domain, 2, r);
  expect_pair_rule(whole, extend, domain, r);
  std::size_t added_left = 0;
  for (std::size_t i = extend.fixed.size(); i < whole.size(); ++i) added_left += whole[i][0] < 0.5 - r;
  EXPECT_LT(added_left, extend.fixed.size() / 20);  // the left half was already (near) full
  EXPECT_GT(whole.size(), 2 * extend.fixed.size() - extend.fixed.size() / 5);
}

// Bridson's restarts end after kConstrainedRestartDarts darts in a row found
// no room, so a set where a uniform dart still finds room with probability f
// ends that way with probability (1 - f)^10,000: at f = 10^-3, e^-10. Counted
// with 100,000 probe darts against the output, indexed by FlatLevels (which
// FlatIndexFindsEveryConflict checks against brute force). Measured: 0.03-0.04%
// of the probes find room (2D and 3D); with the restarts cut off after the
// first front, 0.18% (2D box) and 0.2% (3D), and a restart aimed at the
// wrong cells would leave whole regions.
template <int D>
void expect_restarts_leave_no_room(const SamplingConstraints<D>& c, const Domain<D>& domain, double radius) {
  BridsonParams params;
  params.radius = radius;
  const PointSet<D> points = bridson(params, c, domain, 5);
  const double rmin = c.radius ? c.rmin : radius, rmax = c.radius ? c.rmax : radius;
  detail::FlatLevels<D> index(domain, rmin, rmax);
  for (const auto& p : points) index.insert(p, radius_of(c, p, radius));
  Rng rng(77);
  int room = 0;
  const int probes = 100'000;
  for (int i = 0; i < probes; ++i) {
    const Point<D> x = uniform_point(rng, domain);
    room += (!c.inside || c.inside(x)) && !index.conflicts(x, radius_of(c, x, radius));
  }
  EXPECT_LT(room, probes / 1000) << D << "D, " << points.size() << " points";
}

TEST(Constrained, RestartsLeaveNoRoomForADart) {
  expect_restarts_leave_no_room<2>(radial_field(0.004, 0.03), Domain<2>::unit(false), 0.0);
  auto ring = radial_field(0.004, 0.03);
  ring.inside = [](const Point<2>& x) { return std::abs(std::hypot(x[0] - 0.5, x[1] - 0.5) - 0.3) < 0.1; };
  expect_restarts_leave_no_room<2>(ring, Domain<2>::unit(true), 0.0);
  SamplingConstraints<3> all3;
  all3.inside = [](const Point<3>&) { return true; };
  expect_restarts_leave_no_room<3>(all3, Domain<3>::unit(true), 0.05);
  SamplingConstraints<1> field1;
  field1.rmin = 1e-4;
  field1.rmax = 1e-3;
  field1.radius = [](const Point<1>& x) { return 1e-4 + 9e-4 * x[0]; };
  expect_restarts_leave_no_room<1>(field1, Domain<1>::unit(false), 0.0);
}

TEST(Constrained, SameSeedSamePoints) {
  const auto c = radial_field(0.02, 0.08);
  for (Method m : {Method::bridson, Method::darts}) {
    const Domain<2> domain = Domain<2>::unit(true);
    EXPECT_EQ(run(m, c, domain, 8), run(m, c, domain, 8));
    EXPECT_NE(run(m, c, domain, 8), run(m, c, domain, 9));
  }
}

TEST(Constrained, InvalidInput) {
  const Domain<2> domain = Domain<2>::unit(false);
  auto c = radial_field();
  c.rmin = 0.2;  // above rmax
  EXPECT_THROW(run(Method::bridson, c, domain, 1), InvalidArgument);
  c = radial_field();
  c.radius = [](const Point<2>&) { return std::nan(""); };
  EXPECT_THROW(run(Method::darts, c, domain, 1), InvalidArgument);
  SamplingConstraints<2> fixed;
  fixed.fixed = {Point<2>{{0.5, 1.0}}};  // hi is outside [lo, hi)
  EXPECT_THROW(run(Method::bridson, fixed, domain, 1, 0.1), InvalidArgument);
  EXPECT_THROW(run(Method::bridson, SamplingConstraints<2>{}, domain, 1, 0.0), InvalidArgument);
  BridsonParams counted;
  counted.radius = 0.1;
  counted.count = 10;
  EXPECT_THROW(bridson(counted, radial_field(), domain, 1), InvalidArgument);
  // A mask nothing satisfies: an empty set, not a hang.
  SamplingConstraints<2> nowhere;
  nowhere.inside = [](const Point<2>&) { return false; };
  EXPECT_TRUE(run(Method::bridson, nowhere, domain, 1, 0.1).empty());
  EXPECT_TRUE(run(Method::darts, nowhere, domain, 1, 0.1).empty());
}

TEST(Constrained, ThroughTheRegistry) {
  GenerateRequest request;
  request.constraints.rmin = 0.02;
  request.constraints.rmax = 0.05;
  request.constraints.radius = [](const double* x) { return 0.02 + 0.03 * x[0]; };
  request.constraints.fixed = PointCloud{2, {0.5, 0.5}};
  request.seed = 3;
  for (const char* method : {"bridson", "dart-throwing"}) {
    const PointCloud cloud = generate(method, request);
    ASSERT_GT(cloud.size(), 100u);
    EXPECT_EQ(cloud.coords[0], 0.5);
    SamplingConstraints<2> c = request.constraints.typed(Domain<2>::unit());
    expect_pair_rule(cloud.as<2>(), c, Domain<2>::unit());
  }
  EXPECT_THROW(generate("sobol", request), InvalidArgument);
  GenerateRequest with_radius = request;
  with_radius.radius = 0.1;
  EXPECT_THROW(generate("bridson", with_radius), InvalidArgument);
  GenerateRequest counted = request;
  counted.count = 10;
  EXPECT_THROW(generate("bridson", counted), InvalidArgument);
  GenerateRequest wrong_dim = request;
  wrong_dim.constraints.fixed = PointCloud{3, {0.5, 0.5, 0.5}};
  EXPECT_THROW(generate("bridson", wrong_dim), InvalidArgument);
  GenerateRequest rounded = request;
  rounded.float32 = true;  // would move the fixed points
  EXPECT_THROW(generate("dart-throwing", rounded), InvalidArgument);
  // Memory is estimated at rmin (the densest the field can be).
  const double at_rmin = peak_memory_estimate(find_method("bridson"), request);
  GenerateRequest uniform;
  uniform.radius = 0.02;
  EXPECT_GT(at_rmin, 0.0);
  EXPECT_GE(at_rmin, peak_memory_estimate(find_method("bridson"), uniform));
}

TEST(Constrained, DartThrowingReportsProgressAndStops) {
  auto c = radial_field(0.01, 0.05);
  DartThrowingParams params;
  double last = -1, total = 0;
  params.progress.report = [&](double done, double of) {
    EXPECT_GE(done, last);
    last = done;
    total = of;
    return true;
  };
  const Domain<2> domain = Domain<2>::unit(false);
  const PointSet<2> points = dart_throwing(params, c, domain, 1);
  EXPECT_EQ(last, total);  // the last report is (total, total)
  // Reporting changes nothing.
  EXPECT_EQ(points, dart_throwing(DartThrowingParams{}, c, domain, 1));
  params.progress.report = [](double done, double) { return done < 10; };
  EXPECT_THROW(dart_throwing(params, c, domain, 1), Cancelled);
}

// Bridson under a field and a mask: monotone reports ending at the total,
// many of them, not stuck near 0 or at the total for most of the run (the
// total estimates the room the mask and the field leave), the same bytes.
TEST(Constrained, BridsonReportsProgressAndStops) {
  auto c = radial_field(0.005, 0.05);
  c.inside = [](const Point<2>& x) { return x[0] + x[1] < 1.5; };
  BridsonParams params;
  std::vector<double> reports;
  double total = 0;
  params.progress.report = [&](double done, double of) {
    if (!reports.empty()) {
      EXPECT_GE(done, reports.back());
    }
    reports.push_back(done);
    total = of;
    return true;
  };
  const Domain<2> domain = Domain<2>::unit(false);
  const PointSet<2> points = bridson(params, c, domain, 1);
  ASSERT_GE(reports.size(), 10u);
  EXPECT_EQ(reports.back(), total);
  // The last report before the finish is a fair part of the total: the
  // estimate is within a factor 2 of the count.
  EXPECT_GT(static_cast<double>(points.size()), 0.5 * total);
  EXPECT_LT(static_cast<double>(points.size()), 2.0 * total);
  EXPECT_EQ(points, bridson(BridsonParams{}, c, domain, 1));
  params.progress.report = [](double done, double) { return done < 10; };
  EXPECT_THROW(bridson(params, c, domain, 1), Cancelled);
}

}  // namespace
}  // namespace pds
