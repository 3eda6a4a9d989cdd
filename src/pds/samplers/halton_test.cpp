#include "pds/samplers/halton.h"

#include <gsl/gsl_qrng.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

#include "pds/error.h"
#include "pds/registry.h"
#include "scipy_reference.h"
#include "stratification.h"

namespace pds {
namespace {

const Scramble kAllScrambles[] = {Scramble::none, Scramble::permute_digits, Scramble::owen};

TEST(Halton, FirstPointsArePublishedValues) {
  // Halton (1960); the table in every textbook: base 2 1/2, 1/4, 3/4, 1/8, ...
  // base 3 1/3, 2/3, 1/9, 4/9, ...; base 5 1/5, 2/5, 3/5, 4/5, 1/25, ...
  const double expected[9][3] = {{0, 0, 0},
                                 {1. / 2, 1. / 3, 1. / 5},
                                 {1. / 4, 2. / 3, 2. / 5},
                                 {3. / 4, 1. / 9, 3. / 5},
                                 {1. / 8, 4. / 9, 4. / 5},
                                 {5. / 8, 7. / 9, 1. / 25},
                                 {3. / 8, 2. / 9, 6. / 25},
                                 {7. / 8, 5. / 9, 11. / 25},
                                 {1. / 16, 8. / 9, 16. / 25}};
  const auto points = halton<3>({9, 0, Scramble::none, RadicalRounding::correct}, Domain<3>::unit(), 0);
  // Exact: each value is the correctly rounded rational, as the division above.
  for (int i = 0; i < 9; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(points[i][k], expected[i][k]) << "point " << i << " axis " << k;
}

TEST(Halton, MatchesGsl) {
  // GSL starts at index 1 and sums digits in floating point: a few ulps apart.
  constexpr int n = 5000;
  std::unique_ptr<gsl_qrng, decltype(&gsl_qrng_free)> gsl(gsl_qrng_alloc(gsl_qrng_halton, 3), gsl_qrng_free);
  const auto points = halton<3>({n}, Domain<3>::unit(), 0);
  for (int i = 1; i < n; ++i) {
    double v[3];
    gsl_qrng_get(gsl.get(), v);
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(points[i][k], v[k], 1e-15) << "point " << i << " axis " << k;
  }
}

TEST(Halton, StratifiesTwoToTheAThreeToTheB) {
  // The first 2^a 3^b points put exactly one point in each box of the
  // 2^a x 3^b grid; scrambling permutes whole boxes, so it keeps that.
  for (Scramble s : kAllScrambles)
    for (int a = 0; a <= 6; ++a)
      for (int b = 0; b <= 4; ++b) {
        const std::uint64_t nx = std::uint64_t{1} << a, ny = static_cast<std::uint64_t>(std::pow(3, b));
        // Correctly rounded: SciPy's sums may put a point on a box's lower edge an ulp below it.
        const auto points = halton<2>({nx * ny, 0, s, RadicalRounding::correct}, Domain<2>::unit(), 11);
        EXPECT_EQ(test::stratification_error<2>(points, {nx, ny}, 1), "")
            << "scramble " << int(s) << " a " << a << " b " << b;
      }
}

TEST(Halton, RangesContinueTheSequenceByteForByte) {
  for (Scramble s : kAllScrambles) {
    const auto whole = halton<3>({4000, 0, s}, Domain<3>::unit(), 5);
    for (std::uint64_t first : {1u, 2u, 26u, 125u, 1000u, 3999u}) {
      const auto part = halton<3>({4000 - first, first, s}, Domain<3>::unit(), 5);
      ASSERT_EQ(std::memcmp(part.data(), whole.data() + first, part.size() * sizeof(Point<3>)), 0)
          << "scramble " << int(s) << " from " << first;
    }
  }
}

TEST(Halton, LastIndexIsExact) {
  // 2^32 - 1 is all ones in base 2: its radical inverse is 1 - 2^-32.
  const auto p = halton<2>({1, kSequenceIndexLimit - 1}, Domain<2>::unit(), 0);
  EXPECT_EQ(p[0][0], 1.0 - 0x1.0p-32);
  EXPECT_THROW(halton<2>({2, kSequenceIndexLimit - 1}, Domain<2>::unit(), 0), InvalidArgument);
}

TEST(Halton, SeedsMatterOnlyWhenScrambled) {
  const auto domain = Domain<3>::unit(true);
  EXPECT_EQ(halton<3>({300}, domain, 1), halton<3>({300}, domain, 2));
  for (Scramble s : {Scramble::permute_digits, Scramble::owen}) {
    EXPECT_EQ(halton<3>({300, 0, s}, domain, 1), halton<3>({300, 0, s}, domain, 1));
    EXPECT_NE(halton<3>({300, 0, s}, domain, 1), halton<3>({300, 0, s}, domain, 2));
  }
}

TEST(Halton, StaysInsideTheDomain) {
  const auto domain = Domain<3>::box({{-1, 0, 5}}, {{0, 1e-3, 6}});
  for (Scramble s : kAllScrambles)
    for (const auto& p : halton<3>({2000, 0, s}, domain, 3)) ASSERT_TRUE(domain.contains(p)) << p;
}


TEST(Halton, EqualsScipyInEveryDimension) {
  // scipy.stats.qmc.Halton(d, scramble=False).random(64), computed once
  // (tests/data/scipy_halton.txt): SciPy 1.10 starts at index 0 (the origin),
  // as we do, and sums digit * b^-k in floating point; the default rounding
  // does the same sums, so every double is equal.
  const auto blocks = test::read_scipy_blocks("scipy_halton.txt");
  ASSERT_EQ(blocks.size(), 7u) << "tests/data/scipy_halton.txt";
  for (const auto& b : blocks) {
    const PointCloud ours = halton({b.count}, CloudBox::unit(b.dim), 0);
    EXPECT_EQ(test::scipy_checksum(ours.coords), b.checksum) << "d = " << b.dim;
    for (std::size_t i = 0; i < b.count; ++i)
      for (std::size_t j = 0; j < b.columns.size(); ++j)
        ASSERT_EQ(ours.point(i)[b.columns[j]], b.rows[i][j]) << "d = " << b.dim << " point " << i << " axis "
                                                              << b.columns[j];
    EXPECT_EQ(generate("halton", {.dim = b.dim, .count = b.count}), ours) << "d = " << b.dim;
  }
}

TEST(Halton, ScipyRoundingIsWithinUlpsOfTheExactValues) {
  const HaltonParams scipy{.count = 3000};
  const HaltonParams exact{.count = 3000, .rounding = RadicalRounding::correct};
  const PointCloud a = halton(scipy, CloudBox::unit(200), 0), b = halton(exact, CloudBox::unit(200), 0);
  std::size_t differ = 0;
  for (std::size_t k = 0; k < a.coords.size(); ++k) {
    ASSERT_NEAR(a.coords[k], b.coords[k], 4 * std::ldexp(1.0, -53)) << k;
    differ += a.coords[k] != b.coords[k];
  }
  EXPECT_GT(differ, 0u);  // they are not the same arithmetic
}

TEST(Halton, TypedAndRunTimeDimensionsAreOneCodePath) {
  const auto domain = Domain<4>::box({{-1, 0, 2, 0}}, {{1, 1e-3, 3, 5}});
  for (Scramble s : kAllScrambles) {
    EXPECT_EQ(halton({500, 7, s}, CloudBox::of(domain), 4), PointCloud::from<4>(halton<4>({500, 7, s}, domain, 4)))
        << "scramble " << int(s);
  }
}

TEST(Halton, LargeBasesStratifyTheirAxesScrambledOrNot) {
  // Axis 999 has base 7919: the first 7919 points hold one per slab of width
  // 1/7919 on it (and on every axis with a smaller base, b per slab of ...).
  for (Scramble s : kAllScrambles) {
    const PointCloud c = halton({7919, 0, s}, CloudBox::unit(1000), 12);
    std::vector<int> slab(7919, 0);
    for (std::size_t i = 0; i < c.size(); ++i) ++slab[static_cast<std::size_t>(c.point(i)[999] * 7919 + 1e-9)];
    for (int k = 0; k < 7919; ++k) ASSERT_EQ(slab[k], 1) << "scramble " << int(s) << " slab " << k;
    EXPECT_EQ(c, halton({7919, 0, s}, CloudBox::unit(1000), 12));
    if (s != Scramble::none) {
      EXPECT_NE(c, halton({7919, 0, s}, CloudBox::unit(1000), 13));
    }
  }
}

TEST(Halton, DimensionsPastThePrimeTableAreRefused) {
  EXPECT_THROW(halton({4}, CloudBox::unit(kHaltonMaxDim + 1), 0), InvalidArgument);
  EXPECT_THROW(generate("halton", {.dim = kHaltonMaxDim + 1, .count = 4}), InvalidArgument);
  EXPECT_EQ(generate("halton", {.dim = kHaltonMaxDim, .count = 4, .params = {{"scramble", 2}}}).size(), 4u);
}

}  // namespace
}  // namespace pds
