#include "pds/portable_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace pds {
namespace {

// Distance in units in the last place between two finite positive doubles.
double ulps(double a, double b) {
  std::int64_t x, y;
  std::memcpy(&x, &a, 8);
  std::memcpy(&y, &b, 8);
  return static_cast<double>(x > y ? x - y : y - x);
}

TEST(PortableMath, NegLogWithinFourUlpOfLibm) {
  Rng rng(1);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    // Uniform, then spread over many binades.
    const double u =
        i % 2 ? uniform_open_from_bits(rng.next()) : std::ldexp(uniform_open_from_bits(rng.next()), -(i % 1000));
    if (u == 1.0) continue;
    worst = std::max(worst, ulps(neg_log(u), -std::log(u)));
  }
  EXPECT_LE(worst, 4.0);
  EXPECT_EQ(neg_log(1.0), 0.0);
  EXPECT_EQ(neg_log(0.5), std::log(2.0));
}

// The stated bounds, by range of x.
TEST(PortableMath, ExpNegWithinTheStatedUlpOfLibm) {
  Rng rng(2);
  struct Range {
    double hi, bound;
  };
  for (const Range range : {Range{0.0625, 4.0}, Range{1.0, 64.0}, Range{64.0, 4096.0}, Range{700.0, 65536.0}}) {
    double worst = 0.0;
    for (int i = 0; i < 100000; ++i) {
      const double x = rng.uniform() * range.hi;
      worst = std::max(worst, ulps(exp_neg(x), std::exp(-x)));
      worst = std::max(worst, ulps(portable_exp(x), std::exp(x)));
      worst = std::max(worst, ulps(portable_exp(-x), std::exp(-x)));
    }
    EXPECT_LE(worst, range.bound) << "x up to " << range.hi;
  }
  EXPECT_EQ(exp_neg(0.0), 1.0);
}

TEST(PortableMath, ErfWithinFourQuadrillionthsOfLibm) {
  double worst = 0.0;
  for (int i = -20000; i <= 20000; ++i) {
    const double x = i * 0.0004 + 1e-7 * (i % 7);  // -8 to 8, off the grid of round numbers
    worst = std::max(worst, std::abs(portable_erf(x) - std::erf(x)));
  }
  EXPECT_LT(worst, 4e-15);
  EXPECT_EQ(portable_erf(0.0), 0.0);
  EXPECT_EQ(portable_erf(-1.5), -portable_erf(1.5));
  EXPECT_NEAR(portable_erf(2.0), 0.99532226501895273, 1e-15);
}

TEST(PortableMath, ExpNegTableWithinFourUlpOfLibm) {
  double worst = 0.0;
  for (int i = 0; i <= 699000; ++i) {
    const double x = i * 0.001 + 1e-7 * (i % 11);
    const double want = std::exp(-x), got = exp_neg_table(x);
    worst = std::max(worst, std::abs(got - want) / (want * std::numeric_limits<double>::epsilon()));
  }
  EXPECT_LT(worst, 4.0);
  EXPECT_EQ(exp_neg_table(0.0), 1.0);
  EXPECT_EQ(exp_neg_table(1000.0), 0.0);
}

TEST(PortableMath, UniformsFromBits) {
  EXPECT_EQ(uniform_from_bits(0), 0.0);
  EXPECT_LT(uniform_from_bits(~std::uint64_t{0}), 1.0);
  EXPECT_GT(uniform_open_from_bits(0), 0.0);
  EXPECT_EQ(uniform_open_from_bits(~std::uint64_t{0}), 1.0);
  Rng a(3), b(3);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(uniform_from_bits(a.next()), b.uniform());
}

// Poisson(1) and Poisson(lambda) by inversion: the probabilities of the
// first counts within sampling error of e^-lambda lambda^k / k!, and the
// means and variances within a few standard errors.
TEST(PortableMath, PoissonCountsHaveTheirDistribution) {
  Rng rng(4);
  const int n = 400000;
  double sum = 0.0, sum2 = 0.0;
  int zeros = 0;
  for (int i = 0; i < n; ++i) {
    const int k = poisson_one(rng.uniform());
    sum += k;
    sum2 += double(k) * k;
    zeros += k == 0;
  }
  EXPECT_NEAR(sum / n, 1.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(sum2 / n - (sum / n) * (sum / n), 1.0, 10.0 / std::sqrt(n));
  EXPECT_NEAR(double(zeros) / n, std::exp(-1.0), 5.0 * std::sqrt(0.25 / n));
  for (const double mean : {0.3, 7.5, 64.0, 150.0}) {
    double s = 0.0, s2 = 0.0;
    const int m = 100000;
    for (int i = 0; i < m; ++i) {
      const double k = static_cast<double>(poisson(mean, rng));
      s += k;
      s2 += k * k;
    }
    const double mu = s / m, var = s2 / m - mu * mu;
    EXPECT_NEAR(mu, mean, 5.0 * std::sqrt(mean / m)) << mean;
    EXPECT_NEAR(var / mean, 1.0, 0.05) << mean;
  }
  // poisson_above_zero continues the inversion past 0.
  const double p0 = exp_neg(2.0);
  EXPECT_EQ(poisson_above_zero(p0, 2.0, p0), 1u);
  EXPECT_EQ(poisson_above_zero(p0 + 2.0 * p0 - 1e-15, 2.0, p0), 1u);
  EXPECT_EQ(poisson_above_zero(p0 + 2.0 * p0 + 1e-12, 2.0, p0), 2u);
}

}  // namespace
}  // namespace pds
