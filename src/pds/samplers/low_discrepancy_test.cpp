// The digit machinery shared by the sequences, and the property that defines
// them as a family: an L2-star discrepancy far below that of white noise.

#include "pds/samplers/low_discrepancy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "pds/error.h"
#include "pds/samplers/halton.h"
#include "pds/samplers/hammersley.h"
#include "pds/samplers/latin_hypercube.h"
#include "pds/samplers/random.h"
#include "pds/samplers/sobol.h"
#include "stratification.h"

namespace pds {
namespace {

TEST(LowDiscrepancy, DigitScalesCoverThirtyTwoBits) {
  EXPECT_EQ(DigitScale<2>::digits, 32);
  EXPECT_EQ(DigitScale<3>::digits, 21);  // 3^20 < 2^32 <= 3^21
  EXPECT_EQ(DigitScale<5>::digits, 14);
  EXPECT_EQ(DigitScale<3>::scale, 10460353203u);
}

TEST(LowDiscrepancy, RadicalInverseMirrorsTheDigits) {
  // 11 = 102 in base 3 -> 0.201 = 2/3 + 0/9 + 1/27 = 19/27.
  EXPECT_EQ(radical_inverse<3>(11), 19.0 / 27.0);
  // 6 = 110 in base 2 -> 0.011 = 3/8.
  EXPECT_EQ(radical_inverse<2>(6), 0.375);
  EXPECT_EQ(radical_inverse<5>(0), 0.0);
  EXPECT_LT(radical_inverse<3>(0xffffffffu), 1.0);
}

// The run-time odometer (fill_radical_inverses) against the compile-time
// digit arithmetic, one index at a time, for every scrambling.
template <unsigned B>
double direct(std::uint32_t index, Scramble scramble, std::uint64_t key) {
  const std::uint64_t r = reverse_digits<B>(index);
  const DigitPermutation<B> perm(key);
  switch (scramble) {
    case Scramble::none:
      return radical_inverse<B>(index);
    case Scramble::permute_digits:
      return digits_to_unit<B>(perm.apply(r), perm.tail());
    case Scramble::owen:
      return owen_scramble<B>(r, key);
  }
  return -1;
}

void expect_walk_matches_direct(std::uint32_t first, int steps, std::uint64_t seed) {
  const BoxMap unit(CloudBox::unit(3));
  for (Scramble s : {Scramble::none, Scramble::permute_digits, Scramble::owen}) {
    std::vector<double> out(static_cast<std::size_t>(steps) * 3);
    fill_radical_inverses(first, static_cast<std::uint64_t>(steps), 3, 0, s, RadicalRounding::correct, seed, 1, unit,
                          out.data());
    for (int i = 0; i < steps; ++i) {
      const auto index = static_cast<std::uint32_t>(first + i);
      ASSERT_EQ(out[3 * i + 0], direct<2>(index, s, scramble_key(seed, 1, 0))) << "base 2 index " << index;
      ASSERT_EQ(out[3 * i + 1], direct<3>(index, s, scramble_key(seed, 1, 1))) << "base 3 index " << index;
      ASSERT_EQ(out[3 * i + 2], direct<5>(index, s, scramble_key(seed, 1, 2))) << "base 5 index " << index;
    }
  }
}

TEST(LowDiscrepancy, WalkMatchesDirectComputation) {
  expect_walk_matches_direct(0, 5000, 1);
  // Long carries, starts inside a block, up to the last index.
  expect_walk_matches_direct(0xffffffffu - 3000, 3001, 4);
  expect_walk_matches_direct(1234567, 2000, 5);
}

TEST(LowDiscrepancy, PrimeBasesAreTheFirstPrimes) {
  EXPECT_EQ(nth_prime(0), 2u);
  EXPECT_EQ(nth_prime(7), 19u);
  EXPECT_EQ(nth_prime(999), 7919u);
  EXPECT_EQ(nth_prime(kRadixPrimes - 1), 104729u);
  EXPECT_THROW(nth_prime(kRadixPrimes), InvalidArgument);
}

TEST(LowDiscrepancy, LargeBasesStayExactAndScrambledDigitsStayBalanced) {
  // Axis 999 (base 7919), unscrambled and correctly rounded: i / 7919 for i < 7919.
  const int dim = 1000;
  const std::uint64_t n = 7919;
  const BoxMap unit(CloudBox::unit(dim));
  for (Scramble s : {Scramble::none, Scramble::permute_digits, Scramble::owen}) {
    std::vector<double> out(n * dim);
    fill_radical_inverses(0, n, dim, 0, s, RadicalRounding::correct, 3, 1, unit, out.data());
    std::vector<int> slab(n, 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      const double x = out[i * dim + dim - 1];
      if (s == Scramble::none) {
        ASSERT_EQ(x, static_cast<double>(i) / 7919.0) << i;
      }
      ASSERT_TRUE(x >= 0.0 && x < 1.0);
      ++slab[static_cast<std::size_t>(x * 7919.0 + 1e-9)];  // x * 7919 may round just below an integer
    }
    // Scrambled or not, the first 7919 points put one in each slab of width 1/7919.
    for (std::uint64_t k = 0; k < n; ++k) ASSERT_EQ(slab[k], 1) << "scramble " << int(s) << " slab " << k;
  }
}

template <unsigned B>
void expect_prefix_bijection(std::uint64_t key, bool owen) {
  // Scrambling maps the B^k boxes [j B^-k, (j+1) B^-k) one to one onto
  // themselves for every k: the reason nets stay nets.
  const DigitPermutation<B> perm(key);
  for (int k = 1; k <= 6; ++k) {
    std::uint64_t boxes = 1;
    for (int i = 0; i < k; ++i) boxes *= B;
    std::set<std::uint64_t> seen;
    for (std::uint64_t j = 0; j < boxes; ++j) {
      // The smallest R in box j, and a value inside it with later digits set.
      const std::uint64_t r = j * (DigitScale<B>::scale / boxes) + (DigitScale<B>::scale / boxes) / 3;
      const double x = owen ? owen_scramble<B>(r, key) : digits_to_unit<B>(perm.apply(r), perm.tail());
      seen.insert(static_cast<std::uint64_t>(std::floor(x * static_cast<double>(boxes))));
    }
    EXPECT_EQ(seen.size(), boxes) << "base " << B << " depth " << k << (owen ? " owen" : " digits");
  }
}

TEST(LowDiscrepancy, ScramblingPermutesElementaryIntervals) {
  for (bool owen : {false, true}) {
    expect_prefix_bijection<2>(7, owen);
    expect_prefix_bijection<3>(8, owen);
    expect_prefix_bijection<5>(9, owen);
  }
}

TEST(LowDiscrepancy, OwenScramblingDependsOnThePrefix) {
  // Unlike a digit permutation, Owen's permutation of the second digit differs
  // between the two halves: over many keys, both "same" and "different" occur.
  int same = 0, different = 0;
  for (std::uint64_t key = 0; key < 64; ++key) {
    const auto second_digit = [&](std::uint64_t r) {
      return static_cast<int>(std::floor(owen_scramble<2>(r, key) * 4)) & 1;
    };
    // R = 0.00..., 0.10...: first digits differ, second digits both 0.
    (second_digit(0) == second_digit(std::uint64_t{1} << 31) ? same : different)++;
  }
  EXPECT_GT(same, 0);
  EXPECT_GT(different, 0);
}

TEST(LowDiscrepancy, NetCheckRejectsWhiteNoise) {
  // The helper the net tests rely on must be able to fail.
  const auto points = white_noise<2>({256}, Domain<2>::unit(), 1);
  EXPECT_NE(test::net_error(points, 8, 0), "");
  const auto lhs = latin_hypercube<2>({256}, Domain<2>::unit(), 1);
  EXPECT_NE(test::net_error(lhs, 8, 0), "");  // N-rooks: only the 256 x 1 and 1 x 256 boxes hold
}

// Warnock's formula for the L2-star discrepancy of points in [0, 1)^D:
// T^2 = 3^-D - 2^(1-D)/N sum_i prod_k (1 - x_ik^2) + 1/N^2 sum_ij prod_k (1 - max(x_ik, x_jk)).
// (The analysis issue adds a library version; this one stays in the test.)
template <int D>
double l2_star_discrepancy_squared(const PointSet<D>& points) {
  const double n = static_cast<double>(points.size());
  double single = 0, pairs = 0;
  for (const auto& p : points) {
    double a = 1;
    for (int k = 0; k < D; ++k) a *= 1 - p[k] * p[k];
    single += a;
    for (const auto& q : points) {
      double b = 1;
      for (int k = 0; k < D; ++k) b *= 1 - std::max(p[k], q[k]);
      pairs += b;
    }
  }
  return std::pow(3.0, -D) - std::pow(2.0, 1 - D) / n * single + pairs / (n * n);
}

// E[T^2] of N independent uniform points: (2^-D - 3^-D) / N.
double white_noise_expected_t2(int dim, std::size_t n) {
  return (std::pow(2.0, -dim) - std::pow(3.0, -dim)) / static_cast<double>(n);
}

template <int D>
void expect_white_noise_matches_theory() {
  // Validates the discrepancy code: the mean of T^2 over M white-noise sets is
  // within 4 standard errors (of the sample) of the closed form.
  const int sets = 64;
  const std::size_t n = 256;
  double sum = 0, sum2 = 0;
  for (int s = 0; s < sets; ++s) {
    const double t2 = l2_star_discrepancy_squared(white_noise<D>({n}, Domain<D>::unit(), 1000 + s));
    sum += t2;
    sum2 += t2 * t2;
  }
  const double mean = sum / sets;
  const double standard_error = std::sqrt((sum2 / sets - mean * mean) / (sets - 1));
  EXPECT_NEAR(mean, white_noise_expected_t2(D, n), 4 * standard_error) << "D = " << D;
}

TEST(LowDiscrepancy, WarnockMatchesWhiteNoiseTheory) {
  expect_white_noise_matches_theory<2>();
  expect_white_noise_matches_theory<3>();
}

template <int D>
void expect_far_below_white_noise(const char* name, const PointSet<D>& points) {
  // "Far below": at least ten times below white noise's expected T^2 (the
  // claim of an order of magnitude, fixed before measuring; measured at
  // N = 1024: 20-300 times below, see docs/low-discrepancy.md).
  const double expected_white = white_noise_expected_t2(D, points.size());
  const double t2 = l2_star_discrepancy_squared(points);
  EXPECT_LT(t2, expected_white / 10) << name << " in " << D << "D: T^2 = " << t2
                                     << ", white noise E[T^2] = " << expected_white;
}

TEST(LowDiscrepancy, SobolAndHaltonAreFarBelowWhiteNoiseAt1024) {
  constexpr std::uint64_t n = 1024;
  for (Scramble s : {Scramble::none, Scramble::owen}) {
    expect_far_below_white_noise<2>("sobol", sobol<2>({n, 0, s}, Domain<2>::unit(), 1));
    expect_far_below_white_noise<3>("sobol", sobol<3>({n, 0, s}, Domain<3>::unit(), 1));
    expect_far_below_white_noise<2>("halton", halton<2>({n, 0, s}, Domain<2>::unit(), 1));
    expect_far_below_white_noise<3>("halton", halton<3>({n, 0, s}, Domain<3>::unit(), 1));
    expect_far_below_white_noise<2>("hammersley", hammersley<2>({n, 0, 0, s}, Domain<2>::unit(), 1));
  }
}

}  // namespace
}  // namespace pds
