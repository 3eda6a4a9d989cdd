#pragma once
// Nearest-neighbour and radial-spectrum statistics for comparing a sampler's
// output with a reference process over several seeds (the fast Poisson disk tests).

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "pds/analysis/distance.h"
#include "pds/analysis/spectrum.h"

namespace pds::testing_stats {

/// A domain off the origin and not a square or cube (2D: [0, 1.25) x [-1, 0);
/// 3D: [-0.5, 0.5) x [0, 1.5) x [2, 2.8)), so that no sampler gets away with
/// assuming the unit square.
template <int D>
Domain<D> offset_domain(bool torus) {
  if constexpr (D == 2) {
    return Domain<2>{{{0.0, -1.0}}, {{1.25, 0.0}}, torus};
  } else {
    return Domain<3>{{{-0.5, 0.0, 2.0}}, {{0.5, 1.5, 2.8}}, torus};
  }
}

/// Mean nearest-neighbour distance in units of r, and the fraction of points
/// whose nearest neighbour is closer than 1.1 r.
struct NnSummary {
  double mean_over_r = 0.0;
  double fraction_near = 0.0;
};

template <int D>
NnSummary summarize(const PointSet<D>& points, const Domain<D>& domain, double r) {
  const auto nn = nearest_neighbors(points, domain);
  NnSummary s;
  for (double d : nn.distance) {
    s.mean_over_r += d / r;
    s.fraction_near += d < 1.1 * r;
  }
  s.mean_over_r /= static_cast<double>(points.size());
  s.fraction_near /= static_cast<double>(points.size());
  return s;
}

/// Welch's t statistic for the difference of the means of two samples.
inline double welch_t(const std::vector<double>& a, const std::vector<double>& b) {
  auto moments = [](const std::vector<double>& v, double& mean, double& var) {
    mean = 0.0;
    for (double x : v) mean += x;
    mean /= static_cast<double>(v.size());
    var = 0.0;
    for (double x : v) var += (x - mean) * (x - mean);
    var /= static_cast<double>(v.size() - 1);
  };
  double ma, va, mb, vb;
  moments(a, ma, va);
  moments(b, mb, vb);
  return (ma - mb) / std::sqrt(va / static_cast<double>(a.size()) + vb / static_cast<double>(b.size()));
}

/// |t| below this for 10 + 10 seeds: two-sided p < 0.002 for Welch's test
/// with about 18 degrees of freedom, so a true difference of a few standard
/// errors fails while agreement passes with certainty for fixed seeds.
inline constexpr double kMaxT = 3.9;

}  // namespace pds::testing_stats

namespace pds::testing_stats {

/// The radial power spectrum of one 2D set, annuli 1..K of the integer
/// frequency grid (K cycles per domain extent).
inline std::vector<double> radial_power(const PointSet<2>& points, const Domain<2>& domain, int max_frequency) {
  PeriodogramOptions options;
  options.max_frequency = max_frequency;
  return radial_average(periodogram<2>(std::span<const PointSet<2>>(&points, 1), domain, options)).power;
}

/// The largest |Welch t| over the first `annuli` annuli (all by default)
/// between two groups of per-set radial spectra (one vector per set).
inline double max_spectrum_t(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b,
                             std::size_t annuli = 0) {
  double worst = 0.0;
  if (annuli == 0) annuli = a.front().size();
  for (std::size_t annulus = 0; annulus < annuli; ++annulus) {
    std::vector<double> x, y;
    for (const auto& s : a) x.push_back(s[annulus]);
    for (const auto& s : b) y.push_back(s[annulus]);
    worst = std::max(worst, std::abs(welch_t(x, y)));
  }
  return worst;
}

/// Per-set statistics of several realisations of a 2D process with minimum
/// distance r: the count, the nearest-neighbour summary and, when asked for,
/// the radial power spectrum (annuli 1-48).
struct Realisations {
  std::vector<double> count, mean_over_r, fraction_near;
  std::vector<std::vector<double>> spectrum;

  void add(const PointSet<2>& points, const Domain<2>& domain, double r, bool with_spectrum) {
    const NnSummary nn = summarize(points, domain, r);
    count.push_back(static_cast<double>(points.size()));
    mean_over_r.push_back(nn.mean_over_r);
    fraction_near.push_back(nn.fraction_near);
    if (with_spectrum) spectrum.push_back(radial_power(points, domain, 48));
  }
};

/// Bound on the largest |t| over 48 annuli for 10 + 10 sets: each annulus
/// two-sided p < 1e-4 (t about 5.0 at 18 degrees of freedom), so about 5e-3
/// for all 48 together (Bonferroni) when the spectra agree.
inline constexpr double kMaxSpectrumT = 5.0;

}  // namespace pds::testing_stats
