#include "pds/samplers/jones.h"

#include <gtest/gtest.h>

#include "nn_statistics.h"
#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"
#include "pds/error.h"
#include "pds/samplers/dart_throwing.h"
#include "set_checks.h"

namespace pds {
namespace {

TEST(Jones, MinimumDistanceInsideAndMaximalOnBoxAndTorus) {
  const double r = 0.02;  // about 2200 samples
  for (bool torus : {false, true}) {
    const auto domain = testing_stats::offset_domain<2>(torus);
    const auto points = jones({r}, domain, 5);
    ASSERT_GT(points.size(), 1500u);
    EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, r));
  }
}

// A square torus takes CGAL's periodic triangulation; the offset domain above
// is 1.25 x 1, so its torus takes the plane triangulation with 3 x 3 copies.
TEST(Jones, MinimumDistanceInsideAndMaximalOnSquareAndOblongTori) {
  const double r = 0.02;
  for (const auto& domain :
       {Domain<2>::torus({{-0.5, 2.0}}, {{0.5, 3.0}}), Domain<2>::torus({{0.0, 0.0}}, {{0.3, 1.0}})}) {
    ASSERT_TRUE(domain.periodic);
    const auto points = jones({r}, domain, 9);
    ASSERT_GT(points.size(), 0.6 * domain.volume() / (r * r));  // saturation: 0.684 / r^2
    EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, r));
  }
}

// Tori of 4 to 6 radii: CGAL keeps the 9-sheeted covering for the whole run
// at 4 radii (an edge longer than 0.407 periods remains) and converts to the
// 1-sheeted one late in the run at 5 and 6; the oblong ones use the 3 x 3 copies.
TEST(Jones, SmallToriStayMaximalAndSpaced) {
  const double r = 1.0;
  const std::vector<std::array<double, 2>> periods{{4.0, 4.0}, {4.5, 4.5}, {5.0, 5.0},
                                                   {6.0, 6.0}, {4.0, 6.0}, {6.0, 4.5}};
  for (const auto& [lx, ly] : periods) {
    const auto domain = Domain<2>::torus({{-1.0, 3.0}}, {{-1.0 + lx, 3.0 + ly}});
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const auto points = jones({r}, domain, seed);
      ASSERT_GE(points.size(), 4u) << domain << " seed " << seed;
      EXPECT_TRUE(testing_checks::maximal_poisson_disk_set(points, domain, r)) << "seed " << seed;
      EXPECT_EQ(points, jones({r}, domain, seed));
    }
  }
}

// Far from the origin the coordinates carry few bits below r: computed in
// absolute coordinates, the slivers left near a Voronoi vertex just outside
// the circle lost their area and about 4% of these sets kept a gap (up to
// 3e-4 r at 1e5 r from the origin). The cells are now relative to their site.
TEST(Jones, MaximalFarFromTheOrigin) {
  const double r = 1.0, lo = 1e5;
  for (const auto& domain :
       {Domain<2>::box({{lo, lo}}, {{lo + 16.0, lo + 16.0}}), Domain<2>::torus({{lo, lo}}, {{lo + 16.0, lo + 16.0}}),
        Domain<2>::torus({{lo, lo}}, {{lo + 16.0, lo + 20.0}})}) {
    int gaps = 0;
    for (std::uint64_t seed = 1; seed <= 100; ++seed) {
      const auto points = jones({r}, domain, seed);
      const auto check = testing_checks::maximal_poisson_disk_set(points, domain, r);
      EXPECT_TRUE(check) << "seed " << seed;
      if (!check && ++gaps > 3) break;
    }
  }
}

TEST(Jones, SameSeedSamePointsOtherSeedOtherPoints) {
  const auto domain = testing_stats::offset_domain<2>(true);
  EXPECT_EQ(jones({0.05}, domain, 3), jones({0.05}, domain, 3));
  EXPECT_NE(jones({0.05}, domain, 3), jones({0.05}, domain, 4));
  const auto square = Domain<2>::unit(true);
  EXPECT_EQ(jones({0.05}, square, 3), jones({0.05}, square, 3));
  EXPECT_NE(jones({0.05}, square, 3), jones({0.05}, square, 4));
}

TEST(Jones, RejectsBadInput) {
  EXPECT_THROW(jones({0.0}, Domain<2>::unit(), 1), InvalidArgument);
  EXPECT_THROW(jones({std::nan("")}, Domain<2>::unit(), 1), InvalidArgument);
  EXPECT_THROW(jones({0.3}, Domain<2>::unit(true), 1), InvalidArgument);  // period < 4 radius
}

// Jones's process is random sequential adsorption run to saturation: each
// sample is uniform over the free area, as a dart-throwing sample is. So the
// first n samples of Jones and n samples of dart throwing are equal in law;
// their nearest-neighbour statistics must agree within statistical error.
// Both torus paths: the unit (square) torus and the 1.25 x 1 offset one.
TEST(Jones, PrefixHasTheLawOfDartThrowing) {
  const double r = 0.02;
  for (const auto& domain : {Domain<2>::unit(true), testing_stats::offset_domain<2>(true)}) {
    // Dart throwing reaches it easily (saturation ~1741 per unit area).
    const auto n = static_cast<std::size_t>(1400 * domain.volume());
    std::vector<double> jm, jf, dm, df;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      auto points = jones({r}, domain, seed);
      ASSERT_GT(points.size(), n);
      points.resize(n);
      const auto j = testing_stats::summarize(points, domain, r);
      DartThrowingParams dart{r};
      dart.count = n;
      const auto d = testing_stats::summarize(dart_throwing(dart, domain, 100 + seed), domain, r);
      jm.push_back(j.mean_over_r);
      jf.push_back(j.fraction_near);
      dm.push_back(d.mean_over_r);
      df.push_back(d.fraction_near);
    }
    EXPECT_LT(std::abs(testing_stats::welch_t(jm, dm)), testing_stats::kMaxT) << domain;
    EXPECT_LT(std::abs(testing_stats::welch_t(jf, df)), testing_stats::kMaxT) << domain;
  }
}

// The same comparison on the radially averaged power spectrum: 48 annuli (up
// to 1.3 times the frequency of the mean spacing, past the blue-noise peak),
// one spectrum per set, Welch t per annulus.
TEST(Jones, PrefixSpectrumMatchesDartThrowing) {
  const double r = 0.02;
  const auto domain = Domain<2>::unit(true);
  const std::size_t n = 1400;
  std::vector<std::vector<double>> jones_spectra, dart_spectra;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    auto points = jones({r}, domain, seed);
    points.resize(n);
    jones_spectra.push_back(testing_stats::radial_power(points, domain, 48));
    DartThrowingParams dart{r};
    dart.count = n;
    dart_spectra.push_back(testing_stats::radial_power(dart_throwing(dart, domain, 100 + seed), domain, 48));
  }
  EXPECT_LT(testing_stats::max_spectrum_t(jones_spectra, dart_spectra), testing_stats::kMaxSpectrumT);
}

// Saturated random sequential adsorption of disks of diameter r covers a
// fraction 0.5470735 of the plane (Zhang & Torquato, PRE 88, 2013), i.e.
// 0.5470735 / (pi r^2 / 4) samples per unit area, rho = 0.7776. The count
// over seeds must agree within its standard error.
TEST(Jones, SaturationDensityMatchesTheJammingLimit) {
  const double r = 0.02;
  const auto domain = Domain<2>::unit(true);
  const double expected = 0.5470735 / (M_PI * r * r / 4.0);
  std::vector<double> counts;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) counts.push_back(double(jones({r}, domain, seed).size()));
  double mean = 0.0, var = 0.0;
  for (double c : counts) mean += c / 10.0;
  for (double c : counts) var += (c - mean) * (c - mean) / 9.0;
  EXPECT_LT(std::abs(mean - expected) / std::sqrt(var / 10.0), testing_stats::kMaxT)
      << "mean count " << mean << " expected " << expected;
}

}  // namespace
}  // namespace pds
