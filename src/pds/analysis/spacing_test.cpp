#include "pds/analysis/spacing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pds/samplers/random.h"

namespace pds {
namespace {

TEST(Spacing, TinySetByHand) {
  // The 2 x 2 grid at quarters on the torus: every neighbour at 0.5; the
  // densest packing of 4 disks in area 1 has r_max = sqrt(1 / (8 sqrt 3)).
  const PointSet<2> grid{{{0.25, 0.25}}, {{0.75, 0.25}}, {{0.25, 0.75}}, {{0.75, 0.75}}};
  const Spacing s = spacing(grid, Domain<2>::unit(true));
  EXPECT_DOUBLE_EQ(s.min_distance, 0.5);
  EXPECT_DOUBLE_EQ(s.mean_distance, 0.5);
  EXPECT_NEAR(s.rho_min, 0.25 * std::sqrt(8 * std::sqrt(3.0)), 1e-12);
  EXPECT_NEAR(s.rho_mean, s.rho_min, 1e-15);
}

TEST(Spacing, WhiteNoiseMeanNearestNeighbour) {
  // Uniform points of density N: the nearest-neighbour distance has mean
  // 1/(2 sqrt N) and variance (4 - pi)/(4 pi N), so rho_mean has mean
  // sqrt(2 sqrt 3)/4 and, over N points, a standard deviation of about
  // (1/(2 r_max)) sqrt((4 - pi)/(4 pi N)) / sqrt N.
  const std::size_t n = 4096;
  const Spacing s = spacing(white_noise<2>({n}, Domain<2>::unit(true), 11), Domain<2>::unit(true));
  const double r_max = std::sqrt(1.0 / (2 * std::sqrt(3.0) * n));
  const double sd = 0.5 / r_max * std::sqrt((4 - std::numbers::pi) / (4 * std::numbers::pi * n)) / std::sqrt(n);
  EXPECT_NEAR(s.rho_mean, std::sqrt(2 * std::sqrt(3.0)) / 4, 5 * sd);
  EXPECT_LT(s.rho_min, s.rho_mean);
}

}  // namespace
}  // namespace pds
