// Boundary sampling's two neighbourhood kernels, each on its own (against a
// brute-force oracle and the guarantees) and against each other (bit for
// bit), and the switch that forces the scalar one. The scalar kernel runs on
// every processor; the AVX-512 one is skipped, with the missing processor
// feature named, where the processor or the build lacks it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <string>

#include "kernel_select.h"
#include "pds/detail/diamond_arcs.h"
#include "pds/rng.h"
#include "pds/samplers/dunbar_humphreys.h"
#include "set_checks.h"

namespace pds {
namespace {

constexpr double kPi = std::numbers::pi;

/// Skips the current test where the AVX-512 kernel cannot run, saying why.
#define SKIP_WITHOUT_VECTOR_KERNEL()                                                     \
  do {                                                                                   \
    if (!detail::dunbar_humphreys_has_vector_kernel())                                   \
      GTEST_SKIP() << "AVX-512 kernel not run: " << detail::dh::vector_kernel_missing(); \
  } while (false)

/// The kernels by name: false scalar, true AVX-512.
class BoundaryKernel : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    if (GetParam()) SKIP_WITHOUT_VECTOR_KERNEL();
  }
  bool vector() const { return GetParam(); }
};

INSTANTIATE_TEST_SUITE_P(DunbarHumphreys, BoundaryKernel, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) { return info.param ? "Avx512" : "Scalar"; });

// Each kernel's free arcs against brute force: a direction is free when the
// point of the circle (radius r (1 + 1e-10)) there is at least that far from
// every neighbour. Directions within 1e-9 r of that limit are not judged.
TEST_P(BoundaryKernel, FreeArcsMatchBruteForce) {
  Rng rng(21);
  const double r = 0.01, rc = r * (1.0 + 1e-10);
  const Point<2> p{{0.3, 0.6}};
  int judged = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const int n = 1 + trial % 24;
    PointSet<2> neighbours;
    for (int k = 0; k < n; ++k) {
      const double angle = rng.uniform(0.0, 2.0 * kPi), d = rng.uniform(r, 2.0 * r);
      neighbours.push_back({{p[0] + d * std::cos(angle), p[1] + d * std::sin(angle)}});
    }
    const auto arcs = detail::dunbar_humphreys_free_arcs(p, neighbours, r, vector());
    for (int k = 0; k < 400; ++k) {
      const double t = rng.uniform(0.0, 4.0);
      const auto [vx, vy] = detail::diamond_direction(t);
      const double scale = rc / std::hypot(vx, vy);
      const Point<2> q{{p[0] + vx * scale, p[1] + vy * scale}};
      double nearest = INFINITY;
      for (const Point<2>& s : neighbours) nearest = std::min(nearest, std::hypot(q[0] - s[0], q[1] - s[1]));
      if (std::abs(nearest - rc) < 1e-9 * r) continue;
      bool in_arc = false;
      for (const auto& [lo, len] : arcs) in_arc = in_arc || std::fmod(t - lo + 4.0, 4.0) < len;
      ASSERT_EQ(in_arc, nearest > rc) << "trial " << trial << ", " << n << " neighbours, diamond angle " << t;
      ++judged;
    }
  }
  EXPECT_GT(judged, 200000);
}

// The guarantees with each kernel: all pairs at least r apart, every point
// inside, maximal; in boxes and on tori, a thin box and small tori.
TEST_P(BoundaryKernel, MaximalPoissonDiskSets) {
  for (bool torus : {false, true}) {
    const Domain<2> domain{{{0.0, -1.0}}, {{1.25, 0.0}}, torus};
    const auto points = detail::dunbar_humphreys_boundary({0.02}, domain, 5, vector());
    ASSERT_GT(points.size(), 2000u);
    EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, 0.02)) << domain;
  }
  const Domain<2> thin = Domain<2>::box({{0.0, 0.0}}, {{0.3, 0.001}});
  EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(detail::dunbar_humphreys_boundary({0.002}, thin, 3, vector()),
                                                       thin, 0.002));
  const Domain<2> small{{{0.0, 0.0}}, {{1.0, 1.3}}, true};
  for (double r : {0.24, 0.13})
    EXPECT_TRUE(
        testing_checks::maximal_poisson_disk_set(detail::dunbar_humphreys_boundary({r}, small, 2, vector()), small, r))
        << "r " << r;
}

// The kernels' blocked arcs and complements agree bit for bit for any number
// of neighbours, up to the 32 a circle can have with walls: real
// neighbourhoods stay under 16, where the AVX-512 kernel takes its two-vector
// path, so only this reaches its longer block and its complement fallback.
TEST(DunbarHumphreys, KernelsFreeArcsAgreeForAnyNeighbourCount) {
  SKIP_WITHOUT_VECTOR_KERNEL();
  Rng rng(8);
  const double r = 0.01;
  const Point<2> p{{0.3, 0.6}};
  int nonempty = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int n = 1 + trial % 32;
    PointSet<2> neighbours;
    for (int k = 0; k < n; ++k) {
      const double angle = rng.uniform(0.0, 2.0 * kPi), d = rng.uniform(r, 2.0 * r);
      neighbours.push_back({{p[0] + d * std::cos(angle), p[1] + d * std::sin(angle)}});
    }
    const auto scalar = detail::dunbar_humphreys_free_arcs(p, neighbours, r, false);
    ASSERT_EQ(scalar, detail::dunbar_humphreys_free_arcs(p, neighbours, r, true))
        << "trial " << trial << ", " << n << " neighbours";
    nonempty += n > 16 && !scalar.empty();
  }
  EXPECT_GT(nonempty, 50);  // the long paths also produced free arcs, not only empty circles
}

// The AVX-512 neighbourhood kernel and the scalar one make the same points,
// bit for bit (same seed, same bytes on every processor), in boxes and on
// tori, large and small, near walls and seams.
TEST(DunbarHumphreys, VectorKernelMatchesScalarKernelBitForBit) {
  SKIP_WITHOUT_VECTOR_KERNEL();
  for (bool torus : {false, true}) {
    const Domain<2> domain{{{0.1, -0.2}}, {{1.4, 0.9}}, torus};
    for (double r : {0.004, 0.02, 0.13}) {
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const auto scalar = detail::dunbar_humphreys_boundary({r}, domain, seed, false);
        const auto vector = detail::dunbar_humphreys_boundary({r}, domain, seed, true);
        ASSERT_EQ(scalar.size(), vector.size()) << domain << " r " << r << " seed " << seed;
        EXPECT_EQ(std::memcmp(scalar.data(), vector.data(), scalar.size() * sizeof(scalar[0])), 0)
            << domain << " r " << r << " seed " << seed;
      }
    }
  }
}

// Asking for the vector kernel where it cannot run is an error, not a crash.
TEST(DunbarHumphreys, VectorKernelRequestWithoutItThrows) {
  if (detail::dunbar_humphreys_has_vector_kernel()) GTEST_SKIP() << "this processor has the AVX-512 kernel";
  EXPECT_THROW(detail::dunbar_humphreys_boundary({0.05}, Domain<2>::unit(), 1, true), InvalidArgument);
  EXPECT_FALSE(detail::dh::vector_kernel_missing().empty());
}

TEST(DunbarHumphreysKernelSwitch, EnvironmentValues) {
  EXPECT_FALSE(detail::dh::forces_scalar(nullptr));
  EXPECT_FALSE(detail::dh::forces_scalar(""));
  EXPECT_FALSE(detail::dh::forces_scalar("0"));
  EXPECT_TRUE(detail::dh::forces_scalar("1"));
  EXPECT_TRUE(detail::dh::forces_scalar("yes"));
}

// force_scalar(true) makes pds::dunbar_humphreys run the scalar kernel (the
// same bytes, so what is checked is the choice); false gives the choice back
// to the processor. The state the run started with (PDS_FORCE_SCALAR) is restored.
TEST(DunbarHumphreysKernelSwitch, ForceScalarChoosesTheScalarKernel) {
  const bool was = detail::dh::scalar_forced();
  detail::dh::force_scalar(true);
  EXPECT_TRUE(detail::dh::scalar_forced());
  EXPECT_FALSE(detail::dh::use_vector_kernel());
  const Domain<2> domain = Domain<2>::unit(true);
  EXPECT_EQ(dunbar_humphreys({0.03}, domain, 3), detail::dunbar_humphreys_boundary({0.03}, domain, 3, false));
  detail::dh::force_scalar(false);
  EXPECT_EQ(detail::dh::use_vector_kernel(), detail::dunbar_humphreys_has_vector_kernel());
  detail::dh::force_scalar(was);
}

}  // namespace
}  // namespace pds
