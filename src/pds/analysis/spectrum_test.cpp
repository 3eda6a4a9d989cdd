#include "pds/analysis/spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "pds/analysis/relative_radius.h"
#include "pds/error.h"
#include "pds/parallel.h"
#include "pds/registry.h"
#include "pds/samplers/jittered.h"
#include "pds/samplers/random.h"
#include "pds/samplers/regular.h"

namespace pds {
namespace {

std::vector<PointSet<2>> white_noise_sets(std::size_t m, std::uint64_t n) {
  std::vector<PointSet<2>> sets;
  for (std::size_t s = 0; s < m; ++s) sets.push_back(white_noise<2>({n}, Domain<2>::unit(true), 100 + s));
  return sets;
}

/// |sum_j exp(-2 pi i k.u_j)|^2 / N straight from the definition.
template <int D>
double naive_power(const PointSet<D>& points, const Domain<D>& domain, const std::array<int, D>& k) {
  std::complex<double> s = 0;
  for (const auto& p : points) {
    double phase = 0;
    for (int a = 0; a < D; ++a) phase += k[a] * (p[a] - domain.lo[a]) / domain.extent(a);
    s += std::polar(1.0, -2.0 * std::numbers::pi * phase);
  }
  return std::norm(s) / static_cast<double>(points.size());
}

TEST(Periodogram, MatchesTheDefinitionIn2DAnd3D) {
  const auto box2 = Domain<2>::box({-1, 2}, {1, 3});
  const auto points2 = white_noise<2>({50}, box2, 7);
  const std::vector<PointSet<2>> sets2{points2};
  const Periodogram p2 = periodogram<2>(sets2, box2, {.max_frequency = 40});
  for (int ky = -40; ky <= 40; ky += 3)
    for (int kx = -40; kx <= 40; ++kx) ASSERT_NEAR(p2.at(kx, ky), naive_power<2>(points2, box2, {kx, ky}), 1e-11);

  const auto torus3 = Domain<3>::unit(true);
  const auto points3 = white_noise<3>({40}, torus3, 8);
  const std::vector<PointSet<3>> sets3{points3};
  const Periodogram p3 = periodogram<3>(sets3, torus3, {.max_frequency = 6});
  const int side = p3.side();
  for (int kz = -6; kz <= 6; ++kz)
    for (int ky = -6; ky <= 6; ++ky)
      for (int kx = -6; kx <= 6; ++kx) {
        const double got = p3.power[((kz + 6) * side + ky + 6) * side + kx + 6];
        ASSERT_NEAR(got, naive_power<3>(points3, torus3, {kx, ky, kz}), 1e-11) << kx << "," << ky << "," << kz;
      }
}

TEST(Periodogram, TinySetsByHand) {
  // One point: |e^{...}|^2 / 1 = 1 at every frequency.
  const std::vector<PointSet<2>> one{{{{0.3, 0.7}}}};
  const Periodogram p1 = periodogram<2>(one, Domain<2>::unit(true), {.max_frequency = 5});
  for (double v : p1.power) EXPECT_NEAR(v, 1.0, 1e-13);
  // The 2 x 2 grid at quarters: the sum is 4 when both k are even (every
  // term is 1) and 0 otherwise (terms cancel in pairs), so P = 16/4 or 0.
  const std::vector<PointSet<2>> grid{{{{0.25, 0.25}}, {{0.75, 0.25}}, {{0.25, 0.75}}, {{0.75, 0.75}}}};
  const Periodogram p4 = periodogram<2>(grid, Domain<2>::unit(true), {.max_frequency = 6});
  for (int ky = -6; ky <= 6; ++ky)
    for (int kx = -6; kx <= 6; ++kx) EXPECT_NEAR(p4.at(kx, ky), kx % 2 == 0 && ky % 2 == 0 ? 4.0 : 0.0, 1e-13);
  EXPECT_DOUBLE_EQ(p4.mean_spacing(), 0.5);
}

TEST(Periodogram, WhiteNoiseIsFlatAtOneWithAnisotropyNearMinus10dB) {
  // Each white-noise P(k), k != 0, is close to exponential with mean 1, so the
  // mean of M sets has variance 1/M; an annulus of n frequencies holds n/2
  // independent values (P(-k) = P(k)).
  const std::size_t m = 10;
  const auto sets = white_noise_sets(m, 1024);
  const Periodogram p = periodogram<2>(sets, Domain<2>::unit(true), {.max_frequency = 64});
  const RadialSpectrum radial = radial_average(p);
  ASSERT_EQ(radial.power.size(), 64u);
  double db_sum = 0, db_expected = 0, db_var = 0;
  int annuli = 0;
  for (std::size_t b = 0; b < radial.power.size(); ++b) {
    const double independent = radial.samples[b] / 2.0;
    const double sd = std::sqrt(1.0 / (m * independent));
    EXPECT_NEAR(radial.power[b], 1.0, 5 * sd) << "annulus " << b + 1;
    if (independent >= 50) {
      // The sample variance of a gamma(M) variable has relative variance
      // (2 + 6/M) / n; through 10 log10 that is sd (10/ln10) sqrt((2 + 6/M)/n)
      // and a bias of -(10/ln10) (1 + 3/M) / n (second-order term of the log).
      const double rel = (2.0 + 6.0 / m) / independent;
      db_expected += 10.0 * std::log10(1.0 / m) - 10.0 / std::numbers::ln10 * rel / 2.0;
      db_var += std::pow(10.0 / std::numbers::ln10, 2) * rel;
      db_sum += radial.anisotropy_db[b];
      ++annuli;
    }
  }
  ASSERT_GT(annuli, 30);
  EXPECT_NEAR(db_sum / annuli, db_expected / annuli, 5 * std::sqrt(db_var) / annuli);
  EXPECT_NEAR(db_sum / annuli, -10.0, 0.5);
}

TEST(Periodogram, RegularGridPeaksExactlyAtLatticeFrequencies) {
  const int n = 16;
  const std::vector<PointSet<2>> sets{regular<2>({{n, n, 1}}, Domain<2>::unit(true))};
  const Periodogram p = periodogram<2>(sets, Domain<2>::unit(true), {.max_frequency = 40});
  for (int ky = -40; ky <= 40; ++ky)
    for (int kx = -40; kx <= 40; ++kx) {
      const bool lattice = kx % n == 0 && ky % n == 0;
      EXPECT_NEAR(p.at(kx, ky), lattice ? n * n : 0.0, 1e-9 * n * n) << kx << "," << ky;
    }
  // The first annulus with any power is the lattice's first frequency, nu = 1.
  const RadialSpectrum radial = radial_average(p);
  std::size_t first = 0;
  while (first < radial.power.size() && radial.power[first] < 1e-6) ++first;
  ASSERT_LT(first, radial.power.size());
  EXPECT_NEAR(radial.frequency[first], 1.0, 1e-12);
}

/// Expected jittered periodogram on n x n strata: 1 - sinc^2(kx/n) sinc^2(ky/n)
/// away from the lattice frequencies (each point is uniform in its stratum).
double jittered_theory(int kx, int ky, int n) {
  auto sinc = [](double x) { return x == 0 ? 1.0 : std::sin(std::numbers::pi * x) / (std::numbers::pi * x); };
  const double s = sinc(static_cast<double>(kx) / n) * sinc(static_cast<double>(ky) / n);
  return 1.0 - s * s;
}

TEST(Periodogram, JitteredFollowsItsTheory) {
  const int n = 32, m = 10, K = 48;
  std::vector<PointSet<2>> sets;
  for (int s = 0; s < m; ++s) sets.push_back(jittered<2>({{n, n, 1}}, Domain<2>::unit(true), 500 + s));
  const Periodogram p = periodogram<2>(sets, Domain<2>::unit(true), {.max_frequency = K});
  // Per annulus: the mean of P against the mean of the theory. Each P(k) is
  // near exponential with mean theory(k), so the annulus mean has variance
  // sum theory^2 / (M n^2) times 2 for the mirrored pairs.
  std::vector<double> got(K + 1), expected(K + 1), var(K + 1);
  std::vector<int> count(K + 1);
  for (int ky = -K; ky <= K; ++ky)
    for (int kx = -K; kx <= K; ++kx) {
      const long b = std::lround(std::hypot(kx, ky));
      if (b < 1 || b > K || (kx % n == 0 && ky % n == 0)) continue;
      const double t = jittered_theory(kx, ky, n);
      got[b] += p.at(kx, ky);
      expected[b] += t;
      var[b] += 2 * t * t / m;
      ++count[b];
    }
  for (int b = 1; b <= K; ++b)
    EXPECT_NEAR(got[b] / count[b], expected[b] / count[b], 5 * std::sqrt(var[b]) / count[b]) << "annulus " << b;
}

/// Methods whose spectrum has little power below the ring. Poisson disk
/// methods (dart-throwing, bridson, ...) join the list when they are
/// registered; jittered is the one that exists everywhere. The bound: mean
/// power over the annuli below nu = 0.5 under 0.5, where white noise gives
/// 1 (within 5 of its standard deviations, checked above).
TEST(Periodogram, BlueNoiseMethodsHaveLowPowerBelowTheRing) {
  const char* candidates[] = {"jittered", "dart-throwing", "bridson", "best-candidate"};
  int checked = 0;
  for (const char* name : candidates) {
    const Method* method = nullptr;
    for (const Method& m : methods())
      if (m.name == name) method = &m;
    if (method == nullptr) continue;
    std::vector<PointSet<2>> sets;
    for (std::uint64_t s = 0; s < 4; ++s) {
      GenerateRequest request;
      request.torus = true;
      // About 1024 points: by count, or at the radius where a maximal set has
      // that many (relative radius 0.75).
      if (method->takes_count)
        request.count = 1024;
      else
        request.radius = 2 * 0.75 * max_packing_radius(1.0, 1024, 2);
      request.seed = 900 + s;
      sets.push_back(generate(name, request).as<2>());
    }
    const RadialSpectrum radial = radial_average(periodogram<2>(sets, Domain<2>::unit(true), {.max_frequency = 48}));
    double low = 0;
    int annuli = 0;
    for (std::size_t b = 0; b < radial.power.size() && radial.frequency[b] <= 0.5; ++b, ++annuli)
      low += radial.power[b];
    ASSERT_GT(annuli, 5);
    EXPECT_LT(low / annuli, 0.5) << name;
    ++checked;
  }
  EXPECT_GE(checked, 1);
}

TEST(Periodogram, SameBytesForAnyThreadCount) {
  const auto sets = white_noise_sets(3, 300);
  Periodogram one, many;
  {
    ThreadLimit limit(1);
    one = periodogram<2>(sets, Domain<2>::unit(true), {.max_frequency = 30});
  }
  {
    ThreadLimit limit(4);
    many = periodogram<2>(sets, Domain<2>::unit(true), {.max_frequency = 30});
  }
  EXPECT_EQ(one.power, many.power);
}

TEST(Periodogram, RejectsBadInput) {
  const std::vector<PointSet<2>> none;
  EXPECT_THROW(periodogram<2>(none, Domain<2>::unit(true)), InvalidArgument);
  const std::vector<PointSet<2>> empty(1);
  EXPECT_THROW(periodogram<2>(empty, Domain<2>::unit(true)), InvalidArgument);
  const auto sets = white_noise_sets(1, 10);
  EXPECT_THROW(periodogram<2>(sets, Domain<2>::unit(true), {.max_frequency = 0}), InvalidArgument);
  EXPECT_THROW(periodogram<2>(sets, Domain<2>::unit(true), {.max_frequency = 5000}), InvalidArgument);
}

}  // namespace
}  // namespace pds
