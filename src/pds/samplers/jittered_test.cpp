#include "pds/samplers/jittered.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "pds/samplers/regular.h"
#include "pds/samplers/strata.h"

namespace pds {
namespace {

template <int D>
void expect_one_point_per_stratum(const Domain<D>& domain, const std::array<int, D>& cells, std::uint64_t seed) {
  JitteredParams params;
  std::copy(cells.begin(), cells.end(), params.cells.begin());
  const PointSet<D> points = jittered<D>(params, domain, seed);
  std::size_t total = 1;
  for (int c : cells) total *= static_cast<std::size_t>(c);
  ASSERT_EQ(points.size(), total);
  std::vector<int> hits(total, 0);
  for (const auto& p : points) {
    ASSERT_TRUE(domain.contains(p)) << p;
    std::size_t index = 0, stride = 1;
    for (int i = 0; i < D; ++i) {
      // The stratum is found from the point alone, with exact comparisons.
      int c = static_cast<int>((p[i] - domain.lo[i]) / domain.extent(i) * cells[i]);
      if (c > 0 && p[i] < domain.lo[i] + c * (domain.extent(i) / cells[i])) --c;
      if (c + 1 < cells[i] && p[i] >= domain.lo[i] + (c + 1) * (domain.extent(i) / cells[i])) ++c;
      index += static_cast<std::size_t>(c) * stride;
      stride *= static_cast<std::size_t>(cells[i]);
    }
    ++hits[index];
  }
  for (std::size_t s = 0; s < total; ++s) EXPECT_EQ(hits[s], 1) << "stratum " << s;
}

TEST(Jittered, ExactlyOnePointPerStratum) {
  expect_one_point_per_stratum<2>(Domain<2>::unit(), {32, 32}, 1);
  expect_one_point_per_stratum<2>(Domain<2>::box({-3, 1}, {5, 2}), {40, 5}, 2);
  expect_one_point_per_stratum<3>(Domain<3>::unit(true), {8, 8, 8}, 3);
  expect_one_point_per_stratum<3>(Domain<3>::box({0, 0, 0}, {1, 2, 3}), {3, 5, 7}, 4);
  // Any dimension: the same code over D axes.
  expect_one_point_per_stratum<1>(Domain<1>::box({-2}, {3}), {37}, 5);
  expect_one_point_per_stratum<4>(Domain<4>::unit(true), {3, 4, 5, 2}, 6);
  expect_one_point_per_stratum<6>(Domain<6>::box({0, -1, 0, 0, 2, 0}, {1, 1, 1, 0.5, 3, 1}), {2, 3, 2, 1, 2, 3}, 7);
  expect_one_point_per_stratum<8>(Domain<8>::unit(), {2, 3, 2, 2, 3, 2, 2, 2}, 8);
}

TEST(Jittered, SeedsReproduceAndDiffer) {
  const auto d = Domain<2>::unit();
  EXPECT_EQ(jittered<2>({{16, 16, 1}}, d, 5), jittered<2>({{16, 16, 1}}, d, 5));
  EXPECT_NE(jittered<2>({{16, 16, 1}}, d, 5), jittered<2>({{16, 16, 1}}, d, 6));
}

TEST(Jittered, PointsAreUniformWithinTheirStrata) {
  // Offsets within a stratum, pooled over all strata, are uniform: a
  // chi-square test over 10 bins per axis (9 degrees of freedom; the 99.99%
  // quantile is 33.7).
  const int side = 100;
  const auto points = jittered<2>({{side, side, 1}}, Domain<2>::unit(), 7);
  for (int axis = 0; axis < 2; ++axis) {
    std::array<int, 10> bins{};
    for (const auto& p : points) {
      const double offset = p[axis] * side - std::floor(p[axis] * side);
      ++bins[std::min(9, static_cast<int>(offset * 10))];
    }
    double chi2 = 0;
    const double expected = side * side / 10.0;
    for (int b : bins) chi2 += (b - expected) * (b - expected) / expected;
    EXPECT_LT(chi2, 33.7) << "axis " << axis;
  }
}

TEST(Regular, PointsSitAtCellCentresAndTheMinimumDistanceIsTheEdge) {
  const auto d = Domain<2>::box({0, 0}, {2, 1});
  const auto points = regular<2>({{8, 4, 1}}, d);
  ASSERT_EQ(points.size(), 32u);
  EXPECT_EQ(points[0], (Point<2>{0.125, 0.125}));
  EXPECT_EQ(points[31], (Point<2>{1.875, 0.875}));
  EXPECT_THROW(regular<2>({{0, 4, 1}}, d), InvalidArgument);
}

TEST(Strata, CountsSplitIntoNearCubicCells) {
  EXPECT_EQ(strata_for_count<2>(Domain<2>::unit(), 1024), (std::array<int, 2>{32, 32}));
  EXPECT_EQ(strata_for_count<2>(Domain<2>::box({0, 0}, {2, 1}), 200), (std::array<int, 2>{20, 10}));
  EXPECT_EQ(strata_for_count<3>(Domain<3>::unit(), 4096), (std::array<int, 3>{16, 16, 16}));
  const auto cells = strata_for_count<2>(Domain<2>::unit(), 1000);  // 40 x 25
  EXPECT_EQ(cells[0] * cells[1], 1000);
  EXPECT_LE(strata_aspect<2>(Domain<2>::unit(), cells), kMaxStratumAspect);
}

TEST(Strata, HigherDimensionsSplitIntoNearCubicCells) {
  EXPECT_EQ(strata_for_count<4>(Domain<4>::unit(), 4096), (std::array<int, 4>{8, 8, 8, 8}));
  EXPECT_EQ(strata_for_count<8>(Domain<8>::unit(), 6561), (std::array<int, 8>{3, 3, 3, 3, 3, 3, 3, 3}));
  const auto box = Domain<5>::box({0, 0, 0, 0, 0}, {4, 1, 1, 1, 1});
  const auto cells = strata_for_count<5>(box, 1024);
  EXPECT_EQ(cells[0] * cells[1] * cells[2] * cells[3] * cells[4], 1024);
  EXPECT_LE(strata_aspect<5>(box, cells), kMaxStratumAspect);
  try {
    strata_for_count<8>(Domain<8>::unit(), 257);  // prime
    FAIL() << "257 points cannot form a near-cubic 8D grid";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("nearest counts that can: 256 and 384"), std::string::npos) << e.what();
  }
  // A large count: the search for its neighbours tries only divisors that can fit.
  try {
    strata_for_count<8>(Domain<8>::unit(), 99999989);
    FAIL() << "99999989 points cannot form a near-cubic 8D grid";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("nearest counts that can: 99939840 and 100000000"), std::string::npos)
        << e.what();
  }
}

TEST(Strata, AnUnsplittableCountNamesItsNeighbours) {
  try {
    strata_for_count<2>(Domain<2>::unit(), 997);  // prime
    FAIL() << "997 points cannot form a near-square grid";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("count 997"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("992 and 999"), std::string::npos) << e.what();
  }
}

TEST(Strata, SpacingGivesCellsNoSmallerThanIt) {
  // 1 / 0.1 is exactly 10, but centres 0.05 and 0.15 compute 0.0999...9
  // apart: the grid gives up a cell rather than the guarantee.
  const auto cells = strata_for_spacing<2>(Domain<2>::box({0, 0}, {1, 0.35}), 0.1);
  EXPECT_EQ(cells, (std::array<int, 2>{9, 3}));
  EXPECT_EQ(strata_for_spacing<2>(Domain<2>::unit(), 0.125), (std::array<int, 2>{8, 8}));
  EXPECT_EQ(strata_for_spacing<2>(Domain<2>::unit(), 5.0), (std::array<int, 2>{1, 1}));
}

}  // namespace
}  // namespace pds
