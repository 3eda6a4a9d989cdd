#include "pds/samplers/multi_jittered.h"

#include <gtest/gtest.h>

#include "pds/error.h"
#include "pds/registry.h"
#include "stratification.h"

namespace pds {
namespace {

template <int D>
void expect_jitter_and_n_rooks(const MultiJitteredParams& params, std::uint64_t seed) {
  const auto points = multi_jittered<D>(params, Domain<D>::unit(), seed);
  std::array<std::uint64_t, D> cells;
  std::uint64_t n = 1;
  for (int k = 0; k < D; ++k) n *= cells[k] = static_cast<std::uint64_t>(params.cells[k]);
  ASSERT_EQ(points.size(), n);
  std::string what = std::to_string(D) + "D ";
  for (int k = 0; k < D; ++k) what += std::to_string(cells[k]) + (k + 1 < D ? "x" : "");
  what += params.correlated ? " correlated" : " independent";
  EXPECT_EQ(test::stratification_error<D>(points, cells, 1), "") << what << ": jitter";
  for (int k = 0; k < D; ++k) {
    std::array<std::uint64_t, D> slabs;
    slabs.fill(1);
    slabs[k] = n;
    EXPECT_EQ(test::stratification_error<D>(points, slabs, 1), "") << what << ": N-rooks along axis " << k;
  }
}

TEST(MultiJittered, KeepsJitterAndNRooks) {
  for (bool correlated : {true, false}) {
    for (auto [x, y] : {std::pair{1, 1}, {4, 4}, {3, 5}, {16, 9}, {64, 64}, {1, 7}})
      expect_jitter_and_n_rooks<2>({{x, y, 1}, correlated}, 17);
    for (auto [x, y, z] : {std::tuple{2, 2, 2}, {3, 4, 5}, {16, 16, 16}})
      expect_jitter_and_n_rooks<3>({{x, y, z}, correlated}, 17);
    // Any dimension: the same code over D axes.
    expect_jitter_and_n_rooks<1>({{12}, correlated}, 17);
    expect_jitter_and_n_rooks<4>({{3, 4, 2, 5}, correlated}, 17);
    expect_jitter_and_n_rooks<8>({{2, 3, 2, 2, 2, 3, 2, 2}, correlated}, 17);
  }
}

TEST(MultiJitteredCorrelated, ShufflesEveryColumnAlike) {
  // Kensler's variant: within every column the sub-slab offsets follow the
  // same permutation, so the offset pattern of column 0 repeats in column c.
  const int nx = 8, ny = 8, n = nx * ny;
  const auto points = multi_jittered<2>({{nx, ny, 1}, true}, Domain<2>::unit(), 5);
  for (int c = 1; c < nx; ++c)
    for (int row = 0; row < ny; ++row) {
      const auto offset = [&](int column) {
        const auto& p = points[static_cast<std::size_t>(row * nx + column)];  // axis 0 fastest
        return static_cast<int>(std::floor(p[0] * n)) - column * ny;
      };
      ASSERT_EQ(offset(c), offset(0)) << "column " << c << " row " << row;
    }
  // Independent shuffles differ between columns (with probability 1 - 8 (1/8!)).
  const auto free = multi_jittered<2>({{nx, ny, 1}, false}, Domain<2>::unit(), 5);
  int differing = 0;
  for (int row = 0; row < ny; ++row)
    differing += std::floor(free[row * nx + 1][0] * n) - ny != std::floor(free[row * nx][0] * n);
  EXPECT_GT(differing, 0);
}

TEST(MultiJittered, SameSeedSameBytesAndInsideTheDomain) {
  const auto domain = Domain<3>::box({{0, -1, 2}}, {{1, 1, 2.5}});
  const MultiJitteredParams params{{5, 6, 7}, true};
  const auto a = multi_jittered<3>(params, domain, 9);
  EXPECT_EQ(a, multi_jittered<3>(params, domain, 9));
  EXPECT_NE(a, multi_jittered<3>(params, domain, 10));
  for (const auto& p : a) ASSERT_TRUE(domain.contains(p)) << p;
}

TEST(MultiJittered, RegistryPicksNearCubicStrataAndRejectsBadInput) {
  const PointCloud cloud = generate("multi-jittered", {.count = 1024});
  EXPECT_EQ(cloud.size(), 1024u);
  EXPECT_EQ(test::stratification_error<2>(cloud.as<2>(), {32, 32}, 1), "");
  EXPECT_THROW(generate("multi-jittered", {.count = 1021}), InvalidArgument);  // prime: no near-square split
  EXPECT_THROW(multi_jittered<2>({{0, 4, 1}}, Domain<2>::unit(), 0), InvalidArgument);
  EXPECT_THROW(generate("multi-jittered", {.count = 16, .params = {{"correlated", 2}}}), InvalidArgument);
}

}  // namespace
}  // namespace pds
