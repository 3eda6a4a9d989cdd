#include "pds/samplers/halton.h"

#include <gsl/gsl_qrng.h>
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "pds/error.h"
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
  const auto points = halton<3>({9}, Domain<3>::unit(), 0);
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
        const auto points = halton<2>({nx * ny, 0, s}, Domain<2>::unit(), 11);
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

}  // namespace
}  // namespace pds
