#pragma once
// Elementary functions and random variates that give the same bits on every
// platform: written with + - * / and frexp only (IEEE-754 rounds these
// exactly the same everywhere; libm's exp and log need not, and differ in
// the last bit between libraries). A seed must give the same samples on
// every machine, so every exp, log and Poisson count that decides a sample
// comes from here. The project builds with -ffp-contract=off: a fused
// multiply-add would change the bits.
//
// Accuracy against libm (measured over 10^6 arguments a range; the bounds,
// with margin, are tested in portable_math_test.cpp):
//   neg_log(u)       within 4 ulp of -log(u) on (0, 1] (measured 2).
//   exp_neg(x)       within 4 ulp of exp(-x) for x <= 1/16 (measured 3); each
//                    doubling of x above that squares the result once more
//                    and doubles the error: within 64 ulp for x <= 1
//                    (measured 53), 4096 for x <= 64 (3524, a relative 8e-13),
//                    65536 up to 700 (51827, 1.2e-11). Kept as it is: the
//                    samplers' bytes depend on these bits, and the error is far
//                    below any statistical effect of a probability.
//   portable_exp(x)  as exp_neg(|x|), for either sign.
//   exp_neg_table(x) within 4 ulp of exp(-x) for 0 <= x <= 700 (measured 2), a
//                    few times faster than exp_neg: for kernels summed over
//                    many neighbours.
//   portable_erf(x)  within 4e-15 of erf(x) (absolute; measured 1.1e-15).

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "pds/rng.h"

namespace pds {

/// Uniform in [0, 1) from the top 53 of 64 random bits.
inline double uniform_from_bits(std::uint64_t h) { return static_cast<double>(h >> 11) * 0x1.0p-53; }

/// Uniform in (0, 1] from the top 53 of 64 random bits (never 0: a safe
/// argument for a logarithm).
inline double uniform_open_from_bits(std::uint64_t h) { return static_cast<double>((h >> 11) + 1) * 0x1.0p-53; }

/// -ln(u) for u in (0, 1].
inline double neg_log(double u) {
  int e = 0;
  double m = std::frexp(u, &e);  // u = m 2^e, m in [1/2, 1)
  if (m < 0.70710678118654752440) {
    m *= 2.0;
    --e;
  }
  // ln m = 2 atanh(z) = 2 (z + z^3/3 + z^5/5 + ...), |z| <= 0.172: the terms
  // after z^19/19 add less than 1e-16 relative.
  static constexpr double kInverseOdd[] = {1.0 / 1,  1.0 / 3,  1.0 / 5,  1.0 / 7,  1.0 / 9,
                                           1.0 / 11, 1.0 / 13, 1.0 / 15, 1.0 / 17, 1.0 / 19};
  const double z = (m - 1.0) / (m + 1.0), z2 = z * z;
  double series = kInverseOdd[9];
  for (int k = 8; k >= 0; --k) series = series * z2 + kInverseOdd[k];
  return -(e * 0.69314718055994530942 + 2.0 * z * series);
}

/// e^-x for x >= 0: a Taylor series on x / 2^s <= 1/16, squared s times.
inline double exp_neg(double x) {
  int s = 0;
  while (x > 0.0625) {
    x *= 0.5;
    ++s;
  }
  double term = 1.0, sum = 1.0;
  for (int k = 1; k <= 12; ++k) {
    term *= -x / k;
    sum += term;
  }
  while (s--) sum *= sum;
  return sum;
}

/// e^-x for 0 <= x <= 700 by a table: x = n ln2 / 64 + r with |r| <= ln2 / 128,
/// e^-x = 2^-(n / 64) e^-r, 2^-(n mod 64 / 64) from a table made of square
/// roots of 1/2, the whole powers of two exact, e^-r by six terms of its series
/// (the seventh is below 4e-17). Larger x give 0.
inline double exp_neg_table(double x) {
  struct Table {
    double v[64];
    Table() {
      // 2^(-2^b / 64) by square roots of 1/2 (each rounded exactly), then
      // each entry the product of those its bits name.
      double root[6];
      root[5] = std::sqrt(0.5);
      for (int b = 4; b >= 0; --b) root[b] = std::sqrt(root[b + 1]);
      for (int j = 0; j < 64; ++j) {
        v[j] = 1.0;
        for (int b = 0; b < 6; ++b)
          if (j >> b & 1) v[j] *= root[b];
      }
    }
  };
  static const Table table;
  if (!(x <= 700.0)) return 0.0;
  // ln 2 in two parts (fdlibm's): the high part ends in 32 zero bits, so
  // n times it is exact and x - n ln2 / 64 loses nothing to rounding.
  constexpr double kLn2High = 0x1.62e42feep-1, kLn2Low = 0x1.a39ef35793c76p-33;
  constexpr double kStepsPerUnit = 64 / 0.69314718055994530942;
  const int n = static_cast<int>(x * kStepsPerUnit + 0.5);
  const double r = (x - n * (kLn2High / 64)) - n * (kLn2Low / 64);
  const double series = 1.0 - r * (1.0 - r * (0.5 - r * (1.0 / 6 - r * (1.0 / 24 - r * (1.0 / 120)))));
  // 2^-(n / 64): the exponent field of a double, exact.
  const double power = std::bit_cast<double>(static_cast<std::uint64_t>(1023 - (n >> 6)) << 52);
  return table.v[n & 63] * series * power;
}

/// e^x for either sign (|x| up to about 700, where e^x stays a normal double).
inline double portable_exp(double x) { return x <= 0.0 ? exp_neg(-x) : 1.0 / exp_neg(x); }

/// erf(x): its Taylor series for |x| <= 2 (40 terms: the last is below
/// 1e-19), else 1 - erfc(x) with erfc from its continued fraction,
/// e^(-x^2) / (sqrt(pi) (x + (1/2) / (x + 1 / (x + (3/2) / (x + ...))))),
/// 60 terms evaluated from the tail.
inline double portable_erf(double x) {
  constexpr double kTwoOverSqrtPi = 1.1283791670955125739, kInverseSqrtPi = 0.56418958354775628695;
  const double a = std::abs(x);
  double value;
  if (a <= 2.0) {
    double term = a, sum = a;
    for (int n = 1; n < 40; ++n) {
      term *= -a * a / n;
      sum += term / (2 * n + 1);
    }
    value = kTwoOverSqrtPi * sum;
  } else {
    double f = a;
    for (int k = 60; k >= 1; --k) f = a + 0.5 * k / f;
    value = 1.0 - exp_neg(a * a) * kInverseSqrtPi / f;
  }
  return x < 0.0 ? -value : value;
}

/// Poisson(1) by inversion of u in [0, 1), from the literal e^-1 (the
/// probabilities by division; 40 terms at most, beyond which P < 1e-40).
inline int poisson_one(double u) {
  double p = 0.36787944117144233, cdf = p;  // e^-1
  int n = 0;
  while (u >= cdf && n < 40) {
    ++n;
    p /= n;
    cdf += p;
  }
  return n;
}

/// Poisson(lambda) by inversion, given the uniform u >= p0 = e^-lambda that
/// already ruled out 0 (the probabilities by multiplication with lambda / k).
/// Bounded by the support that matters: the tail beyond
/// lambda + 40 sqrt(lambda) + 100 has probability below 1e-300.
inline std::uint64_t poisson_above_zero(double u, double lambda, double p0) {
  double p = p0, cdf = p0;
  std::uint64_t k = 0;
  const double limit = lambda + 40.0 * std::sqrt(lambda) + 100.0;
  while (u >= cdf && k < limit) {
    ++k;
    p *= lambda / static_cast<double>(k);
    cdf += p;
  }
  return k;
}

/// Poisson(mean) for any mean >= 0 from `rng`: a sum of draws of mean at
/// most 64 (a sum of Poisson variates is Poisson; inversion alone would
/// underflow e^-mean for large means), one uniform each.
inline std::uint64_t poisson(double mean, Rng& rng) {
  std::uint64_t n = 0;
  while (mean > 0.0) {
    const double part = std::min(mean, 64.0);
    mean -= part;
    const double p0 = exp_neg(part), u = rng.uniform();
    if (u >= p0) n += poisson_above_zero(u, part, p0);
  }
  return n;
}

}  // namespace pds
