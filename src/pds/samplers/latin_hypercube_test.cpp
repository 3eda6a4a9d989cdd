#include "pds/samplers/latin_hypercube.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "pds/error.h"
#include "pds/registry.h"
#include "stratification.h"

namespace pds {
namespace {

template <int D>
void expect_n_rooks(const PointSet<D>& points, const std::string& what) {
  const std::uint64_t n = points.size();
  for (int k = 0; k < D; ++k) {
    std::array<std::uint64_t, D> slabs;
    slabs.fill(1);
    slabs[k] = n;
    EXPECT_EQ(test::stratification_error<D>(points, slabs, 1), "") << what << ", axis " << k;
  }
}

TEST(LatinHypercube, EveryRowAndColumnHoldsOnePoint) {
  for (std::uint64_t n : {1u, 2u, 7u, 100u, 1000u, 65536u}) {
    expect_n_rooks(latin_hypercube<2>({n}, Domain<2>::unit(), n), "2D, N = " + std::to_string(n));
    expect_n_rooks(latin_hypercube<3>({n}, Domain<3>::unit(), n), "3D, N = " + std::to_string(n));
  }
}

TEST(LatinHypercube, HoldsInABoxThroughItsOwnSlabs) {
  // In a box, slab s of axis k is [lo + s w, lo + (s+1) w), w = extent / N.
  const auto domain = Domain<2>::box({{-2, 3}}, {{1, 3.5}});
  const std::uint64_t n = 5000;
  const auto points = latin_hypercube<2>({n}, domain, 3);
  for (int k = 0; k < 2; ++k) {
    std::vector<int> count(n, 0);
    for (const auto& p : points) {
      ASSERT_TRUE(domain.contains(p)) << p;
      ++count[static_cast<std::size_t>((p[k] - domain.lo[k]) / domain.extent(k) * n)];
    }
    EXPECT_EQ(std::count(count.begin(), count.end(), 1), static_cast<long>(n)) << "axis " << k;
  }
}

TEST(LatinHypercube, SlabJitterStaysInItsSlab) {
  Rng rng(1);
  for (std::uint64_t n : {1ull, 3ull, 1000003ull, 1ull << 32}) {
    const SlabJitter within(n);
    for (std::uint64_t slab : {std::uint64_t{0}, n / 2, n - 1})
      for (int i = 0; i < 1000; ++i) {
        const double x = within(slab, rng);
        ASSERT_EQ(static_cast<std::uint64_t>(std::floor(x * static_cast<double>(n))), slab) << n << " " << slab;
      }
  }
}

TEST(LatinHypercube, SameSeedSameBytesAndOtherSeedsDiffer) {
  const auto domain = Domain<3>::unit(true);
  EXPECT_EQ(latin_hypercube<3>({500}, domain, 4), latin_hypercube<3>({500}, domain, 4));
  EXPECT_NE(latin_hypercube<3>({500}, domain, 4), latin_hypercube<3>({500}, domain, 5));
}

TEST(LatinHypercube, AxesAreIndependent) {
  // Spearman's rank correlation of the two axes: under independence its
  // standard deviation is 1/sqrt(N - 1); allow 5 of them.
  const std::uint64_t n = 10000;
  const auto points = latin_hypercube<2>({n}, Domain<2>::unit(), 8);
  double sum = 0;
  for (const auto& p : points) sum += (p[0] - 0.5) * (p[1] - 0.5);
  const double rho = sum / n * 12;  // the coordinates are the normalised ranks, variance 1/12
  EXPECT_LT(std::abs(rho), 5 / std::sqrt(n - 1.0));
}

TEST(LatinHypercube, RejectsZeroPoints) {
  EXPECT_THROW(latin_hypercube<2>({0}, Domain<2>::unit(), 0), InvalidArgument);
  EXPECT_THROW(generate("latin-hypercube", {.count = 0}), InvalidArgument);
}


TEST(LatinHypercube, EveryAxisOfARunTimeDimensionHoldsOnePointPerSlab) {
  // In a box, 1,000 axes, N = 97: on every axis every slab holds one point.
  CloudBox box = CloudBox::unit(1000);
  for (int a = 0; a < 1000; ++a) {
    box.lo[a] = -a;
    box.hi[a] = 1.0 + 0.5 * a;
  }
  const std::uint64_t n = 97;
  const PointCloud c = latin_hypercube({n}, box, 5);
  ASSERT_EQ(c.size(), n);
  std::vector<int> slab(n);
  for (int a = 0; a < 1000; ++a) {
    std::fill(slab.begin(), slab.end(), 0);
    const double width = (box.hi[a] - box.lo[a]) / static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = c.point(i)[a];
      ASSERT_TRUE(x >= box.lo[a] && x < box.hi[a]) << "axis " << a;
      ++slab[static_cast<std::size_t>(std::floor((x - box.lo[a]) / width))];
    }
    for (std::uint64_t k = 0; k < n; ++k) ASSERT_EQ(slab[k], 1) << "axis " << a << " slab " << k;
  }
  EXPECT_EQ(c, latin_hypercube({n}, box, 5));
  EXPECT_NE(c, latin_hypercube({n}, box, 6));
}

TEST(LatinHypercube, TypedAndRunTimeDimensionsAreOneCodePath) {
  const auto domain = Domain<6>::unit();
  EXPECT_EQ(latin_hypercube({300}, CloudBox::of(domain), 8), PointCloud::from<6>(latin_hypercube<6>({300}, domain, 8)));
  // Axes do not depend on how many follow.
  const PointCloud wide = latin_hypercube({50}, CloudBox::unit(500), 8);
  const auto narrow = latin_hypercube<3>({50}, Domain<3>::unit(), 8);
  for (std::size_t i = 0; i < 50; ++i)
    for (int a = 0; a < 3; ++a) ASSERT_EQ(wide.point(i)[a], narrow[i][a]);
}

}  // namespace
}  // namespace pds
