#include "pds/samplers/hammersley.h"

#include <gtest/gtest.h>

#include "pds/error.h"
#include "pds/registry.h"
#include "pds/samplers/halton.h"
#include "pds/samplers/random.h"
#include "stratification.h"

namespace pds {
namespace {

const Scramble kAllScrambles[] = {Scramble::none, Scramble::permute_digits, Scramble::owen};

TEST(Hammersley, SmallSetIsTheTextbookOne) {
  // N = 8: (i/8, phi_2(i), phi_3(i)).
  const auto points = hammersley<3>({8}, Domain<3>::unit(), 0);
  const double phi2[8] = {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  const double phi3[8] = {0, 1. / 3, 2. / 3, 1. / 9, 4. / 9, 7. / 9, 2. / 9, 5. / 9};
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(points[i][0], i / 8.0);
    EXPECT_EQ(points[i][1], phi2[i]);
    EXPECT_EQ(points[i][2], phi3[i]);
  }
}

TEST(Hammersley, PowerOfTwoSetsAreZeroNetsIn2D) {
  for (Scramble s : kAllScrambles)
    for (int m = 2; m <= 12; ++m) {
      const auto points = hammersley<2>({std::uint64_t{1} << m, 0, 0, s}, Domain<2>::unit(), 8);
      EXPECT_EQ(test::net_error(points, m, 0), "") << "scramble " << int(s) << ", 2^" << m << " points";
    }
}

TEST(Hammersley, PartsOfASetMatchTheWholeSet) {
  for (Scramble s : kAllScrambles) {
    const auto whole = hammersley<3>({1000, 0, 0, s}, Domain<3>::unit(), 4);
    const auto part = hammersley<3>({300, 600, 1000, s}, Domain<3>::unit(), 4);
    for (int i = 0; i < 300; ++i) ASSERT_EQ(part[i], whole[600 + i]) << "scramble " << int(s) << " point " << i;
  }
  EXPECT_THROW(hammersley<2>({10, 995, 1000}, Domain<2>::unit(), 0), InvalidArgument);
}

TEST(Hammersley, SeedsMatterOnlyWhenScrambled) {
  const auto domain = Domain<2>::unit();
  EXPECT_EQ(hammersley<2>({100}, domain, 1), hammersley<2>({100}, domain, 2));
  EXPECT_NE(hammersley<2>({100, 0, 0, Scramble::owen}, domain, 1),
            hammersley<2>({100, 0, 0, Scramble::owen}, domain, 2));
}


TEST(Hammersley, RunTimeDimensionsAreIndexThenHaltonAxes) {
  // Unscrambled: axis 0 is i / N, axis a the correctly rounded Halton axis a - 1.
  const std::uint64_t n = 300;
  const PointCloud h = hammersley({n}, CloudBox::unit(1001), 0);
  const PointCloud halt = halton({n, 0, Scramble::none, RadicalRounding::correct}, CloudBox::unit(1000), 0);
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_EQ(h.point(i)[0], static_cast<double>(i) / n);
    for (int a = 1; a < 1001; ++a) ASSERT_EQ(h.point(i)[a], halt.point(i)[a - 1]) << "point " << i << " axis " << a;
  }
  const auto domain = Domain<4>::box({{0, 0, -1, 2}}, {{1, 3, 0, 2.5}});
  for (Scramble s : kAllScrambles)
    EXPECT_EQ(hammersley({200, 5, 400, s}, CloudBox::of(domain), 3),
              PointCloud::from<4>(hammersley<4>({200, 5, 400, s}, domain, 3)));
  EXPECT_THROW(hammersley({4}, CloudBox::unit(kHammersleyMaxDim + 1), 0), InvalidArgument);
  EXPECT_EQ(generate("hammersley", {.dim = kHammersleyMaxDim, .count = 3}).size(), 3u);
}

TEST(WhiteNoise, RunTimeDimensionsAreOneCodePath) {
  const auto domain = Domain<7>::unit();
  EXPECT_EQ(white_noise({300}, CloudBox::of(domain), 8), PointCloud::from<7>(white_noise<7>({300}, domain, 8)));
  CloudBox box = CloudBox::unit(2000);
  box.lo[7] = -1e-9;
  box.hi[7] = 0;
  const PointCloud c = white_noise({100}, box, 2);
  for (std::size_t i = 0; i < c.size(); ++i)
    for (int a = 0; a < 2000; ++a) ASSERT_TRUE(c.point(i)[a] >= box.lo[a] && c.point(i)[a] < box.hi[a]);
  EXPECT_EQ(c, white_noise({100}, box, 2));
  EXPECT_NE(c, white_noise({100}, box, 3));
}

}  // namespace
}  // namespace pds
