// Scalloped regions (the data structure of Dunbar & Humphreys 2006) against an
// independent oracle: along each ray from the sample, the free radii are the
// interval r..2r minus the chord of every neighbour's disk and minus what lies
// beyond each wall, found by elementary ray-circle and ray-line geometry; the
// area is the integral over the angle of (b^2 - a^2) / 2 over those
// intervals, by a fine midpoint rule. The region under test builds the same
// set from closed-form primitives and sector splitting, so the two share no
// formula.
#include "scalloped_region.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "pds/rng.h"

namespace pds::detail::dh {
namespace {

constexpr double kPi = std::numbers::pi;

/// A region's recipe: the annulus r..2r, minus the disks of radius r at
/// `disks` (offsets from the sample), minus the half-planes beyond `walls`
/// (h, psi): {x : x . (cos psi, sin psi) > h}.
struct Recipe {
  double r = 1.0;
  std::vector<std::array<double, 2>> walls;
  std::vector<std::array<double, 2>> disks;

  ScallopedRegion build() const {
    ScallopedRegion region;
    region.reset(r);
    // Walls first, then disks nearest first, as the sampler does.
    for (const auto& [h, psi] : walls) region.remove_beyond_wall(h, psi);
    auto sorted = disks;
    std::sort(sorted.begin(), sorted.end(),
              [](const auto& a, const auto& b) { return std::hypot(a[0], a[1]) < std::hypot(b[0], b[1]); });
    for (const auto& [cx, cy] : sorted) region.remove_disk(cx, cy, r);
    return region;
  }

  /// The free radii along the ray at angle theta, clipped to [lo, hi].
  std::vector<std::pair<double, double>> free_radii(double theta, double lo, double hi) const {
    std::vector<std::pair<double, double>> free{{std::max(r, lo), std::min(2.0 * r, hi)}};
    if (free[0].first >= free[0].second) return {};
    const auto remove = [&](double a, double b) {
      std::vector<std::pair<double, double>> next;
      for (const auto& [x, y] : free) {
        if (b <= x || a >= y) {
          next.push_back({x, y});
          continue;
        }
        if (a > x) next.push_back({x, a});
        if (b < y) next.push_back({b, y});
      }
      free.swap(next);
    };
    const double ex = std::cos(theta), ey = std::sin(theta);
    for (const auto& [h, psi] : walls) {
      const double c = std::cos(theta - psi);
      if (c > 0.0) remove(h / c, INFINITY);
    }
    for (const auto& [cx, cy] : disks) {
      const double along = cx * ex + cy * ey, across = cx * ey - cy * ex;
      if (std::abs(across) < r) {
        const double half = std::sqrt(r * r - across * across);
        remove(along - half, along + half);
      }
    }
    return free;
  }

  /// The area of the region within angles [t0, t1] and radii [lo, hi], by the
  /// midpoint rule over `steps` angles.
  double area(double t0 = 0.0, double t1 = 2.0 * kPi, double lo = 0.0, double hi = INFINITY, int steps = 200000) const {
    const double dt = (t1 - t0) / steps;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i)
      for (const auto& [a, b] : free_radii(t0 + (i + 0.5) * dt, lo, hi)) sum += 0.5 * (b * b - a * a);
    return sum * dt;
  }

  /// How far the point (theta, rho) lies outside the region (0 inside).
  double outside_by(double theta, double rho) const {
    const double x = rho * std::cos(theta), y = rho * std::sin(theta);
    double worst = std::max({0.0, r - rho, rho - 2.0 * r});
    for (const auto& [h, psi] : walls) worst = std::max(worst, x * std::cos(psi) + y * std::sin(psi) - h);
    for (const auto& [cx, cy] : disks) worst = std::max(worst, r - std::hypot(x - cx, y - cy));
    return worst;
  }
};

/// A random recipe as the sampler meets them: 0-2 axis walls at distance
/// (0, 2r), up to `max_disks` neighbours at r..3r from the sample and from
/// each other at least r apart, on the sample's side of the walls.
Recipe random_recipe(Rng& rng, double r, int max_disks) {
  Recipe recipe;
  recipe.r = r;
  const int walls = static_cast<int>(rng.below(3));
  const double first_wall = static_cast<double>(rng.below(4));
  for (int w = 0; w < walls; ++w)  // adjacent walls (a box corner) or one
    recipe.walls.push_back({rng.uniform(0.05 * r, 2.0 * r), 0.5 * kPi * std::fmod(first_wall + w, 4.0)});
  const int want = 1 + static_cast<int>(rng.below(static_cast<std::uint64_t>(max_disks)));
  for (int attempt = 0; attempt < 200 && static_cast<int>(recipe.disks.size()) < want; ++attempt) {
    const double angle = rng.uniform(0.0, 2.0 * kPi), d = rng.uniform(r, 3.0 * r);
    const std::array<double, 2> c{d * std::cos(angle), d * std::sin(angle)};
    bool ok = true;
    for (const auto& [h, psi] : recipe.walls) ok = ok && c[0] * std::cos(psi) + c[1] * std::sin(psi) <= h;
    for (const auto& o : recipe.disks) ok = ok && std::hypot(c[0] - o[0], c[1] - o[1]) >= r;
    if (ok) recipe.disks.push_back(c);
  }
  return recipe;
}

/// Simpson's rule for f over [a, b] with n (even) intervals.
template <class F>
double simpson(F f, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return sum * h / 3.0;
}

// The closed-form primitive of radius^2 / 2 against Simpson's rule on the
// curve's own radius, for neighbour circles (near and far crossing), the
// annulus circles and walls, away from the tangent directions (where the
// integrand's slope is infinite and Simpson converges slowly). Measured
// agreement 1.2e-13 r^2; tolerance 1e-11 r^2.
TEST(ScallopedRegion, CurvePrimitiveIsTheSweptArea) {
  Rng rng(11);
  for (int trial = 0; trial < 400; ++trial) {
    const double r = trial % 2 ? 1.0 : 1e-3;
    const double angle = rng.uniform(-kPi, kPi);
    Curve curve;
    double half;
    switch (trial % 4) {
      case 0:
      case 1: {  // a neighbour's circle at distance r..3r
        const double d = rng.uniform(r, 3.0 * r);
        curve = Curve::circle(d * std::cos(angle), d * std::sin(angle), r, trial % 4 == 0 ? -1.0 : 1.0);
        half = std::asin(r / d);
        break;
      }
      case 2:  // a wall at distance (0, 2r)
        curve = Curve::wall(rng.uniform(0.05 * r, 2.0 * r), angle);
        half = 0.45 * kPi;
        break;
      default:  // an annulus circle
        curve = Curve::circle(0.0, 0.0, (1.0 + static_cast<double>(rng.below(2))) * r, 1.0);
        half = kPi;
        break;
    }
    const double centre = curve.line ? curve.psi : curve.phi;
    const double t0 = centre + rng.uniform(-0.95, 0.95) * half, t1 = centre + rng.uniform(-0.95, 0.95) * half;
    const double exact = curve.primitive(t1) - curve.primitive(t0);
    const double numeric = simpson(
        [&](double t) {
          const double rho = curve.radius(t);
          return 0.5 * rho * rho;
        },
        t0, t1, 4000);
    EXPECT_NEAR(exact, numeric, 1e-11 * r * r) << "trial " << trial << ", angles " << t0 << ".." << t1;
  }
}

// A region's exact area against the ray quadrature, over 300 random regions
// with walls and 1-8 neighbours. The quadrature's own error (square-root
// kinks at the tangents) was at most 1.5e-8 of the annulus, 3 pi r^2, with
// 2 10^5 angles (the first 20 regions) and 1.2e-6 with 2 10^4 (the rest);
// the tolerances are 1e-6 and 2e-5 of the annulus.
TEST(ScallopedRegion, ExactAreaMatchesRayQuadrature) {
  Rng rng(12);
  int empty = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double r = trial % 3 == 0 ? 1e-2 : 1.0;
    const Recipe recipe = random_recipe(rng, r, 8);
    const ScallopedRegion region = recipe.build();
    const double annulus = 3.0 * kPi * r * r;
    const double numeric = recipe.area(0.0, 2.0 * kPi, 0.0, INFINITY, trial < 20 ? 200000 : 20000);
    const double tolerance = (trial < 20 ? 1e-6 : 2e-5) * annulus;
    if (region.empty()) {
      ++empty;
      EXPECT_LT(numeric, tolerance) << "trial " << trial;
      continue;
    }
    EXPECT_NEAR(region.area(), numeric, tolerance)
        << "trial " << trial << ": " << recipe.walls.size() << " walls, " << recipe.disks.size() << " disks, "
        << region.sectors() << " sectors";
  }
  EXPECT_LT(empty, 30);  // most regions keep some area
}

// position() is the inverse of cdf(): (u, v) -> (theta, rho) -> (u, v), and
// every position lies in the region (the oracle, to rounding). Measured
// round-trip errors: 2.7e-12 in u, 1.6e-13 in v.
TEST(ScallopedRegion, InverseCdfRoundTripsAndStaysInside) {
  Rng rng(13);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double r = trial % 2 ? 1.0 : 1e-3;
    const Recipe recipe = random_recipe(rng, r, 8);
    const ScallopedRegion region = recipe.build();
    if (region.empty()) continue;
    for (int k = 0; k < 200; ++k) {
      const double u = rng.uniform(1e-6, 1.0 - 1e-6), v = rng.uniform(1e-6, 1.0 - 1e-6);
      const auto [theta, rho] = region.position(u, v);
      EXPECT_LE(recipe.outside_by(theta, rho), 1e-9 * r) << "trial " << trial << " u " << u << " v " << v;
      const auto back = region.cdf(theta, rho);
      ASSERT_TRUE(back.has_value()) << "trial " << trial << " u " << u << " v " << v;
      EXPECT_NEAR(back->first, u, 1e-9) << "trial " << trial << " v " << v;
      EXPECT_NEAR(back->second, v, 1e-6) << "trial " << trial << " u " << u;
      ++checked;
    }
  }
  EXPECT_GT(checked, 30000);
}

// Draws through sample() land in the region, and are uniform over it:
// counts in 16 angular x 2 radial cells (split at 1.5 r) against the oracle's
// areas of those cells, chi-square below mean + 6 standard deviations.
TEST(ScallopedRegion, SamplesAreUniformOverTheRegion) {
  Rng rng(14);
  int regions = 0;
  for (int trial = 0; regions < 8; ++trial) {
    const Recipe recipe = random_recipe(rng, 1.0, 4);
    const ScallopedRegion region = recipe.build();
    if (region.empty() || region.area() < 0.5) continue;
    ++regions;
    constexpr int kAngles = 16, kDraws = 40000;
    std::array<int, 2 * kAngles> counts{};
    for (int k = 0; k < kDraws; ++k) {
      const auto [theta, rho] = region.sample(rng);
      ASSERT_LE(recipe.outside_by(theta, rho), 1e-9) << "trial " << trial;
      const double t = std::fmod(theta + 2.0 * kPi, 2.0 * kPi);
      ++counts[static_cast<std::size_t>(std::min(kAngles - 1, static_cast<int>(t / (2.0 * kPi) * kAngles)) * 2 +
                                        (rho >= 1.5))];
    }
    const double total = recipe.area();
    double chi2 = 0.0;
    int cells = 0;
    for (int a = 0; a < kAngles; ++a)
      for (int b = 0; b < 2; ++b) {
        const double t0 = 2.0 * kPi * a / kAngles, t1 = 2.0 * kPi * (a + 1) / kAngles;
        const double expected = kDraws * recipe.area(t0, t1, b ? 1.5 : 0.0, b ? INFINITY : 1.5, 4000) / total;
        const int seen = counts[static_cast<std::size_t>(a * 2 + b)];
        if (expected < 5.0) {
          EXPECT_LT(seen, 5.0 + 6.0 * std::sqrt(5.0)) << "trial " << trial << " cell " << a << "," << b;
          continue;
        }
        chi2 += (seen - expected) * (seen - expected) / expected;
        ++cells;
      }
    const double dof = cells - 1;
    EXPECT_LT(chi2, dof + 6.0 * std::sqrt(2.0 * dof)) << "trial " << trial << ", " << cells << " cells";
  }
}

// Removing a disk never adds area, and a disk beyond 3r changes nothing.
TEST(ScallopedRegion, RemovingOnlyShrinks) {
  ScallopedRegion region;
  region.reset(1.0);
  EXPECT_NEAR(region.area(), 3.0 * kPi, 1e-12);
  region.remove_disk(3.0, 0.0, 1.0);
  EXPECT_NEAR(region.area(), 3.0 * kPi, 1e-12);
  Rng rng(15);
  double before = region.area();
  for (int k = 0; k < 6; ++k) {
    const double angle = rng.uniform(0.0, 2.0 * kPi), d = rng.uniform(1.0, 3.0);
    region.remove_disk(d * std::cos(angle), d * std::sin(angle), 1.0);
    if (region.empty()) break;
    EXPECT_LE(region.area(), before + 1e-12);
    before = region.area();
  }
}

}  // namespace
}  // namespace pds::detail::dh
