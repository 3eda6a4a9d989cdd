#include "pds/analysis/pair_correlation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pds/error.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

/// Standard deviation of the estimate for uniform points: the kernel-weighted
/// count of the N^2/2 unordered pairs is close to Poisson, so
/// var(g)/g^2 = integral k^2 / (pairs/V * s_D r^(D-1)) = (3 / 5h) / (N^2/(2V) 2 pi r) in 2D.
double white_noise_sd(double r, double h, double n, double sets) {
  return std::sqrt(0.6 / h / (n * n / 2.0 * 2.0 * std::numbers::pi * r) / sets);
}

void expect_near_one(const PairCorrelation& g, double n, const char* where) {
  int checked = 0;
  for (std::size_t i = 0; i < g.r.size(); ++i) {
    if (g.r[i] < g.bandwidth) continue;  // few pairs there; the bound below is for r >= h
    EXPECT_NEAR(g.g[i], 1.0, 5 * white_noise_sd(g.r[i], g.bandwidth, n, g.sets)) << where << " r=" << g.r[i];
    ++checked;
  }
  EXPECT_GT(checked, 150);
}

TEST(PairCorrelation, WhiteNoiseIsNearOneOnTheTorusAndInTheBox) {
  const std::size_t n = 2048;
  for (bool periodic : {true, false}) {
    const auto domain = Domain<2>::unit(periodic);
    std::vector<PointSet<2>> sets;
    for (std::uint64_t s = 0; s < 4; ++s) sets.push_back(white_noise<2>({n}, domain, 40 + s));
    const PairCorrelation g = pair_correlation<2>(sets, domain);
    EXPECT_NEAR(g.mean_spacing, std::sqrt(1.0 / n), 1e-15);
    EXPECT_NEAR(g.bandwidth, 0.1 * g.mean_spacing, 1e-15);
    EXPECT_NEAR(g.r.back(), 2.5 * g.mean_spacing, 1e-15);
    // In the box, leaving out the translation correction would bias g by
    // about -4r/(pi L) = -7% at r = 2.5 spacings, beyond these bounds.
    expect_near_one(g, n, periodic ? "torus" : "box");
  }
}

TEST(PairCorrelation, TinySetsByHand) {
  // The 2 x 2 grid at quarters on the unit torus: each point has two
  // neighbours at 0.5 (the diagonal ones, at 0.707, are beyond reach), so the
  // ordered pair sum is 8 k_h(r - 0.5), and with N(N-1)/V = 12 and
  // I(r) = r (the kernel lies within s >= 0 and is symmetric):
  //   g(r) = 8 k_h(r - 0.5) / (12 * 2 pi * r).
  const std::vector<PointSet<2>> grid{{{{0.25, 0.25}}, {{0.75, 0.25}}, {{0.25, 0.75}}, {{0.75, 0.75}}}};
  const PairCorrelation g =
      pair_correlation<2>(grid, Domain<2>::unit(true), {.r_max = 0.5, .bandwidth = 0.1, .steps = 10});
  ASSERT_EQ(g.r.size(), 10u);
  EXPECT_NEAR(g.r[8], 0.45, 1e-15);
  EXPECT_NEAR(g.g[8], 8 * 7.5 * 0.75 / (12 * 2 * std::numbers::pi * 0.45), 1e-12);
  EXPECT_NEAR(g.g[9], 8 * 7.5 / (12 * 2 * std::numbers::pi * 0.5), 1e-12);
  EXPECT_EQ(g.g[5], 0.0);  // r = 0.3: no pair within h
  // Two points 0.5 apart along x in the unit box: translation weight
  // 1 / ((1 - 0.5) (1 - 0)) = 2, N(N-1)/V = 2, so g(0.5) = 2 * 2 * 7.5 / (2 * 2 pi * 0.5).
  const std::vector<PointSet<2>> pair{{{{0.25, 0.5}}, {{0.75, 0.5}}}};
  const PairCorrelation b =
      pair_correlation<2>(pair, Domain<2>::unit(false), {.r_max = 0.5, .bandwidth = 0.1, .steps = 10});
  EXPECT_NEAR(b.g[9], 2 * 2 * 7.5 / (2 * 2 * std::numbers::pi * 0.5), 1e-12);
}

TEST(PairCorrelation, ThreeDimensionsOnTheTorus) {
  // The same estimator with s_D r^2: white noise is near 1 in 3D too, within
  // 5 standard deviations (var = (3/5h) / (N^2/2 * 4 pi r^2)).
  const std::size_t n = 4096;
  const auto domain = Domain<3>::unit(true);
  const std::vector<PointSet<3>> sets{white_noise<3>({n}, domain, 5)};
  const PairCorrelation g = pair_correlation<3>(sets, domain);
  for (std::size_t i = 0; i < g.r.size(); ++i) {
    if (g.r[i] < 5 * g.bandwidth) continue;
    const double sd = std::sqrt(0.6 / g.bandwidth / (n * n / 2.0 * 4 * std::numbers::pi * g.r[i] * g.r[i]));
    EXPECT_NEAR(g.g[i], 1.0, 5 * sd) << g.r[i];
  }
}

TEST(PairCorrelation, RejectsBadInput) {
  const std::vector<PointSet<2>> sets{white_noise<2>({100}, Domain<2>::unit(true), 1)};
  EXPECT_THROW(pair_correlation<2>(sets, Domain<2>::unit(true), {.r_max = 0.6}), InvalidArgument);
  EXPECT_THROW(pair_correlation<2>(sets, Domain<2>::unit(true), {.bandwidth = -1}), InvalidArgument);
  EXPECT_THROW(pair_correlation<2>(sets, Domain<2>::unit(true), {.steps = 0}), InvalidArgument);
  const std::vector<PointSet<2>> lonely{{{{0.5, 0.5}}}};
  EXPECT_THROW(pair_correlation<2>(lonely, Domain<2>::unit(true)), InvalidArgument);
  const std::vector<PointSet<2>> outside{{{{0.5, 0.5}}, {{1.5, 0.5}}}};
  EXPECT_THROW(pair_correlation<2>(outside, Domain<2>::unit(true)), InvalidArgument);
}

}  // namespace
}  // namespace pds
