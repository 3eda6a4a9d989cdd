#include "pds/rng.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

namespace pds {
namespace {

TEST(Rng, SameSeedSameStream) {
  Rng a(42), b(42), c(43);
  bool differs = false;
  for (int i = 0; i < 1000; ++i) {
    const auto x = a.next();
    EXPECT_EQ(x, b.next());
    differs |= x != c.next();
  }
  EXPECT_TRUE(differs);
}

TEST(Rng, StreamIsPinnedAcrossPlatforms) {
  // The generator is specified by integer arithmetic only; these values are
  // what xoshiro256++ seeded through SplitMix64 gives. A change here changes
  // every seeded output of the library, on every platform.
  Rng rng(0);
  const std::uint64_t first = rng.next();
  Rng again(0);
  EXPECT_EQ(first, again.next());
  // Reference implementation of the same algorithm, written out separately.
  auto mix = [](std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  std::uint64_t h = mix(0 + 0x9e3779b97f4a7c15ULL), s[4];
  for (auto& w : s) w = mix(h += 0x9e3779b97f4a7c15ULL);
  auto rotl = [](std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); };
  EXPECT_EQ(first, rotl(s[0] + s[3], 23) + s[0]);
  // Pinned values: if any of these change, every seeded output changes.
  EXPECT_EQ(first, 0x84f09bf307c1073aULL);
  EXPECT_EQ(again.next(), 0xc82ffb597ceee51bULL);
  EXPECT_EQ(again.next(), 0xadf96905c5df4417ULL);
  EXPECT_EQ(Rng(12345, {1, 2}).uniform(), 0.80825121884856177);
}

TEST(Rng, KeysSplitIntoIndependentStreams) {
  std::set<std::uint64_t> firsts;
  for (std::uint64_t cell = 0; cell < 1000; ++cell) firsts.insert(Rng(7, {0, cell}).next());
  EXPECT_EQ(firsts.size(), 1000u);
  EXPECT_NE(Rng(7, {1, 2}).next(), Rng(7, {2, 1}).next());
  const Rng parent(9);
  EXPECT_EQ(parent.split(3).uniform(), parent.split(3).uniform());
  EXPECT_NE(parent.split(3).next(), parent.split(4).next());
}

TEST(Rng, UniformStaysInItsHalfOpenRange) {
  Rng rng(1);
  double lo = 1, hi = 0, sum = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double u = rng.uniform();
    lo = std::min(lo, u);
    hi = std::max(hi, u);
    sum += u;
  }
  EXPECT_GE(lo, 0.0);
  EXPECT_LT(hi, 1.0);
  // Mean of n uniforms: standard error 1/sqrt(12 n); allow 5 of them.
  EXPECT_NEAR(sum / n, 0.5, 5.0 / std::sqrt(12.0 * n));
  // A range whose width rounds: never returns hi.
  const double a = 1.0, b = std::nextafter(1.0, 2.0);
  for (int i = 0; i < 1000; ++i) EXPECT_LT(rng.uniform(a, b), b);
}

TEST(Rng, BelowIsUnbiased) {
  // Chi-square over 7 buckets (6 degrees of freedom): 99.99% quantile 27.9.
  Rng rng(5);
  std::array<int, 7> counts{};
  const int n = 70000;
  for (int i = 0; i < n; ++i) ++counts[rng.below(7)];
  double chi2 = 0;
  for (int c : counts) chi2 += (c - n / 7.0) * (c - n / 7.0) / (n / 7.0);
  EXPECT_LT(chi2, 27.9);
  EXPECT_EQ(Rng(1).below(1), 0u);
}

}  // namespace
}  // namespace pds
