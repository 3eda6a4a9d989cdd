#include "pds/samplers/sobol.h"

#include <gsl/gsl_qrng.h>
#include <gtest/gtest.h>

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

TEST(Sobol, FirstPointsArePublishedValues) {
  // The first eight points of the 3D sequence as printed by Joe & Kuo's
  // generator and by MATLAB's sobolset(3) (Gray-code order).
  const double expected[8][3] = {{0, 0, 0},
                                 {0.5, 0.5, 0.5},
                                 {0.75, 0.25, 0.25},
                                 {0.25, 0.75, 0.75},
                                 {0.375, 0.375, 0.625},
                                 {0.875, 0.875, 0.125},
                                 {0.625, 0.125, 0.875},
                                 {0.125, 0.625, 0.375}};
  const auto points = sobol<3>({8}, Domain<3>::unit(), 0);
  ASSERT_EQ(points.size(), 8u);
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(points[i][k], expected[i][k]) << "point " << i << " axis " << k;
}

TEST(Sobol, MatchesGslOnTheSharedAxes) {
  // GSL uses Bratley & Fox's numbers: the same first two axes as Joe & Kuo,
  // a different third. It starts at index 1 (it skips the origin).
  constexpr int n = 1 << 12;
  std::unique_ptr<gsl_qrng, decltype(&gsl_qrng_free)> gsl(gsl_qrng_alloc(gsl_qrng_sobol, 2), gsl_qrng_free);
  const auto points = sobol<2>({n}, Domain<2>::unit(), 0);
  for (int i = 1; i < n; ++i) {
    double v[2];
    gsl_qrng_get(gsl.get(), v);
    ASSERT_EQ(points[i][0], v[0]) << "point " << i;
    ASSERT_EQ(points[i][1], v[1]) << "point " << i;
  }
}

TEST(Sobol, DirectionNumbersFollowJoeKuo) {
  // m_k = v_k >> (32 - k): axis 2 (d = 3: s = 2, a = 1, m = 1, 3) continues
  // 1, 3, 3, 9, 29, 23 ... by the recurrence m_k = 2 m_{k-1} ^ 4 m_{k-2} ^ m_{k-2}.
  const auto v = sobol_directions(2);
  const std::uint32_t m[6] = {1, 3, 3, 9, 29, 23};
  for (int k = 0; k < 6; ++k) EXPECT_EQ(v[k] >> (31 - k), m[k]) << "k = " << k;
  // Axis 3 (d = 4: s = 3, a = 1, m = 1, 3, 1) checks the order of a's bits:
  // x^3 + x + 1 gives m_k = 4 m_{k-2} ^ 8 m_{k-3} ^ m_{k-3}, so 5 and 31 follow
  // (the reversed order, x^3 + x^2 + 1, would give 11).
  const auto v3 = sobol_directions(3);
  const std::uint32_t m3[5] = {1, 3, 1, 5, 31};
  for (int k = 0; k < 5; ++k) EXPECT_EQ(v3[k] >> (31 - k), m3[k]) << "k = " << k;
  for (int axis = 0; axis < kSobolMaxDim; ++axis) {
    const auto d = sobol_directions(axis);
    for (int k = 0; k < 32; ++k) {
      // m_k is odd and below 2^k: the direction number's lowest set bit is 31 - k.
      EXPECT_EQ(d[k] >> (31 - k) & 1u, 1u) << "axis " << axis << " k " << k;
      EXPECT_EQ(d[k] & ((std::uint32_t{1} << (31 - k)) - 1), 0u) << "axis " << axis << " k " << k;
    }
  }
  EXPECT_THROW(sobol_directions(kSobolMaxDim), InvalidArgument);
}

TEST(Sobol, EveryPowerOfTwoPrefixIsAZeroNetIn2D) {
  for (Scramble s : kAllScrambles)
    for (int m = 2; m <= 12; ++m) {
      const auto points = sobol<2>({std::uint64_t{1} << m, 0, s}, Domain<2>::unit(), 42);
      EXPECT_EQ(test::net_error(points, m, 0), "") << "scramble " << int(s) << ", 2^" << m << " points";
    }
}

TEST(Sobol, LaterAlignedBlocksAreNetsToo) {
  // A (0, 2)-sequence: points k 2^m ... (k+1) 2^m - 1 form a (0, m, 2)-net.
  for (Scramble s : kAllScrambles)
    for (int m = 2; m <= 10; m += 4) {
      const std::uint64_t n = std::uint64_t{1} << m;
      const auto points = sobol<2>({n, 5 * n, s}, Domain<2>::unit(), 9);
      EXPECT_EQ(test::net_error(points, m, 0), "") << "scramble " << int(s) << ", block 5 of 2^" << m;
    }
}

TEST(Sobol, ThreeAxesFormANetWithTOne) {
  // Joe & Kuo's third axis has a degree-2 polynomial: t = 0 + 0 + 1.
  for (Scramble s : kAllScrambles)
    for (int m = 2; m <= 12; m += 2) {
      const auto points = sobol<3>({std::uint64_t{1} << m, 0, s}, Domain<3>::unit(), 3);
      EXPECT_EQ(test::net_error(points, m, 1), "") << "scramble " << int(s) << ", 2^" << m << " points";
    }
}

TEST(Sobol, RangesContinueTheSequenceByteForByte) {
  for (Scramble s : kAllScrambles) {
    const auto whole = sobol<3>({3000, 0, s}, Domain<3>::unit(), 5);
    for (std::uint64_t first : {1u, 7u, 1024u, 2047u}) {
      const auto part = sobol<3>({3000 - first, first, s}, Domain<3>::unit(), 5);
      ASSERT_EQ(std::memcmp(part.data(), whole.data() + first, part.size() * sizeof(Point<3>)), 0)
          << "scramble " << int(s) << " from " << first;
    }
  }
  // The very last indices.
  const auto tail = sobol<2>({2, kSequenceIndexLimit - 2}, Domain<2>::unit(), 0);
  EXPECT_EQ(tail[1][0], 0x1.0p-32);  // gray(2^32 - 1) = 2^31: only the last direction number, 2^-32
}

TEST(Sobol, SeedsMatterOnlyWhenScrambled) {
  const auto domain = Domain<2>::unit();
  EXPECT_EQ(sobol<2>({256}, domain, 1), sobol<2>({256}, domain, 2));
  for (Scramble s : {Scramble::permute_digits, Scramble::owen}) {
    EXPECT_EQ(sobol<2>({256, 0, s}, domain, 1), sobol<2>({256, 0, s}, domain, 1));
    EXPECT_NE(sobol<2>({256, 0, s}, domain, 1), sobol<2>({256, 0, s}, domain, 2));
  }
}

TEST(Sobol, OwenScramblingIsUniformPerPoint) {
  // Each point of an Owen-scrambled sequence is uniform on the cube: over 4000
  // seeds, the first coordinate of point 3 has mean 1/2 with standard error
  // sqrt(1/12 / 4000) = 0.0046; allow 5 of them.
  double sum = 0;
  const int seeds = 4000;
  for (int seed = 0; seed < seeds; ++seed) sum += sobol<2>({4, 0, Scramble::owen}, Domain<2>::unit(), seed)[3][0];
  EXPECT_NEAR(sum / seeds, 0.5, 5 * std::sqrt(1.0 / 12 / seeds));
}

TEST(Sobol, MapsToTheDomain) {
  const auto domain = Domain<2>::box({{-3, 10}}, {{1, 10.5}});
  for (Scramble s : kAllScrambles) {
    const auto points = sobol<2>({1000, 0, s}, domain, 1);
    const auto unit = sobol<2>({1000, 0, s}, Domain<2>::unit(), 1);
    for (std::size_t i = 0; i < points.size(); ++i) {
      ASSERT_TRUE(domain.contains(points[i])) << points[i];
      EXPECT_EQ(points[i][0], -3 + unit[i][0] * 4);
    }
  }
}

TEST(Sobol, RejectsIndicesPastTwoToThe32) {
  EXPECT_THROW(sobol<2>({2, kSequenceIndexLimit - 1}, Domain<2>::unit(), 0), InvalidArgument);
  EXPECT_THROW(generate("sobol", {.count = 10, .params = {{"first", 4294967290.0}}}), InvalidArgument);
  EXPECT_THROW(generate("sobol", {.count = 10, .params = {{"scramble", 3}}}), InvalidArgument);
  EXPECT_EQ(generate("sobol", {.count = 10, .params = {{"first", 4294967286.0}}}).size(), 10u);
}


TEST(Sobol, EqualsScipyInEveryDimension) {
  // scipy.stats.qmc.Sobol(d, scramble=False).random(64), computed once
  // (tests/data/scipy_sobol.txt): our index i is SciPy's row i, both start at
  // the origin, and every double is equal.
  const auto blocks = test::read_scipy_blocks("scipy_sobol.txt");
  ASSERT_EQ(blocks.size(), 7u) << "tests/data/scipy_sobol.txt";
  for (const auto& b : blocks) {
    const PointCloud ours = sobol({b.count}, CloudBox::unit(b.dim), 0);
    ASSERT_EQ(ours.size(), b.count);
    EXPECT_EQ(test::scipy_checksum(ours.coords), b.checksum) << "d = " << b.dim;
    for (std::size_t i = 0; i < b.count; ++i)
      for (std::size_t j = 0; j < b.columns.size(); ++j)
        ASSERT_EQ(ours.point(i)[b.columns[j]], b.rows[i][j]) << "d = " << b.dim << " point " << i << " axis "
                                                              << b.columns[j];
    // The registry gives the same points.
    EXPECT_EQ(generate("sobol", {.dim = b.dim, .count = b.count}), ours) << "d = " << b.dim;
  }
}

TEST(Sobol, TypedAndRunTimeDimensionsAreOneCodePath) {
  const auto domain = Domain<5>::box({{-1, 0, 2, 0, 0}}, {{1, 1e-3, 3, 5, 1}});
  for (Scramble s : kAllScrambles) {
    const auto typed = sobol<5>({700, 3, s}, domain, 4);
    EXPECT_EQ(sobol({700, 3, s}, CloudBox::of(domain), 4), PointCloud::from<5>(typed)) << "scramble " << int(s);
    // Axes do not depend on how many follow: dimension 1000's first 5 columns are dimension 5's.
    const PointCloud wide = sobol({64, 0, s}, CloudBox::unit(1000), 4);
    const auto narrow = sobol<5>({64, 0, s}, Domain<5>::unit(), 4);
    for (std::size_t i = 0; i < 64; ++i)
      for (int a = 0; a < 5; ++a) ASSERT_EQ(wide.point(i)[a], narrow[i][a]) << "scramble " << int(s);
  }
}

TEST(Sobol, EveryAxisOfEveryDimensionIsBalanced) {
  // Each axis alone is van der Corput's sequence permuted within its aligned
  // blocks: 2^m points put one in each interval of width 2^-m, in all 21,201
  // axes, scrambled or not.
  constexpr int m = 8;
  for (Scramble s : kAllScrambles) {
    const PointCloud cloud = sobol({1u << m, 0, s}, CloudBox::unit(kSobolMaxDim), 6);
    std::vector<unsigned char> seen(1u << m);
    for (int a = 0; a < kSobolMaxDim; ++a) {
      std::fill(seen.begin(), seen.end(), 0);
      for (std::size_t i = 0; i < cloud.size(); ++i) {
        const auto k = static_cast<std::size_t>(cloud.point(i)[a] * (1u << m));
        ASSERT_FALSE(seen[k]++) << "scramble " << int(s) << " axis " << a << " interval " << k;
      }
    }
  }
}

TEST(Sobol, ScrambledPairsKeepTheirNetQuality) {
  // For pairs of far axes, the least t for which 2^10 unscrambled points form
  // a (t, 10, 2)-net; digit permutation and Owen scrambling keep it.
  constexpr int m = 10;
  const std::pair<int, int> pairs[] = {{0, 1}, {3, 17}, {99, 100}, {998, 999}, {4000, 21200}};
  auto columns = [](const PointCloud& c, int a, int b) {
    PointSet<2> p(c.size());
    for (std::size_t i = 0; i < c.size(); ++i) p[i] = {{c.point(i)[a], c.point(i)[b]}};
    return p;
  };
  const PointCloud plain = sobol({1u << m}, CloudBox::unit(kSobolMaxDim), 0);
  for (Scramble s : {Scramble::permute_digits, Scramble::owen})
    for (std::uint64_t seed : {1u, 2u}) {
      const PointCloud scrambled = sobol({1u << m, 0, s}, CloudBox::unit(kSobolMaxDim), seed);
      for (auto [a, b] : pairs) {
        int t = 0;
        while (test::net_error(columns(plain, a, b), m, t) != "") ++t;
        EXPECT_LE(t, m);
        EXPECT_EQ(test::net_error(columns(scrambled, a, b), m, t), "")
            << "axes " << a << ", " << b << " scramble " << int(s) << " seed " << seed << " t " << t;
      }
    }
}

TEST(Sobol, ScrambledHighDimensionsAreSeededAndDeterministic) {
  for (Scramble s : {Scramble::permute_digits, Scramble::owen}) {
    const auto a = sobol({100, 0, s}, CloudBox::unit(1000), 9);
    EXPECT_EQ(a, sobol({100, 0, s}, CloudBox::unit(1000), 9));
    const auto b = sobol({100, 0, s}, CloudBox::unit(1000), 10);
    EXPECT_NE(a, b);
    // Every axis gets its own scrambling: no two columns equal.
    for (int axis = 1; axis < 1000; ++axis) ASSERT_NE(a.point(1)[axis], a.point(1)[axis - 1]) << "axis " << axis;
  }
}

TEST(Sobol, DimensionsPastTheTableAndBudgetsAreRefused) {
  EXPECT_THROW(sobol({4}, CloudBox::unit(kSobolMaxDim + 1), 0), InvalidArgument);
  EXPECT_THROW(sobol({4}, CloudBox::unit(0), 0), InvalidArgument);
  try {
    generate("sobol", {.dim = kSobolMaxDim + 1, .count = 4});
    ADD_FAILURE() << "no error past 21201 dimensions";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("1-21201"), std::string::npos) << e.what();
  }
  // 10^8 points (the default cap) of 21,201 doubles: refused before allocation.
  try {
    generate("sobol", {.dim = kSobolMaxDim, .count = 100'000'000});
    ADD_FAILURE() << "no error for 2 x 10^12 doubles";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("GiB"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pds
