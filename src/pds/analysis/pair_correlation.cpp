// Kernel estimate of the pair correlation function; the estimator, the kernel
// and the edge correction are stated in include/pds/analysis/pair_correlation.h.
// Pairs closer than r_max + h are found with the background grid, so the cost
// is N times the number of neighbours within r_max + h, times the r values
// each pair's kernel covers.

#include "pds/analysis/pair_correlation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "pds/error.h"
#include "pds/grid.h"

namespace pds {
namespace {

double epanechnikov(double u, double h) {
  const double t = u / h;
  return t * t < 1.0 ? 0.75 / h * (1.0 - t * t) : 0.0;
}

/// I(r) = integral_{s >= 0} k_h(r - s) s^(D-1) ds. The integrand is a
/// polynomial of degree <= 4 on [max(0, r-h), r+h], so 3-point Gauss-Legendre
/// is exact.
double kernel_moment(double r, double h, int dim) {
  const double a = std::max(0.0, r - h), b = r + h;
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  const double x = std::sqrt(0.6);
  const double nodes[3] = {-x, 0.0, x};
  const double weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    const double s = mid + half * nodes[i];
    sum += weights[i] * epanechnikov(r - s, h) * std::pow(s, dim - 1);
  }
  return sum * half;
}

}  // namespace

template <int D>
PairCorrelation pair_correlation(std::span<const PointSet<D>> sets, const Domain<D>& domain,
                                 const PairCorrelationOptions& options, const Progress& progress) {
  domain.validate();
  if (sets.empty()) throw InvalidArgument("pair correlation: no point sets given");
  double total = 0;
  for (std::size_t s = 0; s < sets.size(); ++s) {
    if (sets[s].size() < 2)
      throw InvalidArgument("pair correlation: point set " + std::to_string(s) + " has fewer than two points");
    total += static_cast<double>(sets[s].size());
  }
  const double volume = domain.volume();
  double shortest = domain.extent(0);
  for (int a = 1; a < D; ++a) shortest = std::min(shortest, domain.extent(a));
  PairCorrelation out;
  out.sets = sets.size();
  out.mean_spacing = std::pow(volume / (total / static_cast<double>(sets.size())), 1.0 / D);
  const double r_max = options.r_max > 0 ? options.r_max : std::min(2.5 * out.mean_spacing, 0.5 * shortest);
  const double h = options.bandwidth > 0 ? options.bandwidth : 0.1 * out.mean_spacing;
  if (!std::isfinite(r_max) || r_max > 0.5 * shortest)
    throw InvalidArgument("pair correlation: r_max must be at most half the shortest extent (" +
                          std::to_string(0.5 * shortest) + "), got " + std::to_string(r_max));
  if (!std::isfinite(h) || options.bandwidth < 0)
    throw InvalidArgument("pair correlation: bandwidth must be positive, got " + std::to_string(options.bandwidth));
  if (options.steps < 1 || options.steps > 100000)
    throw InvalidArgument("pair correlation: steps must be in [1, 100000], got " + std::to_string(options.steps));
  out.bandwidth = h;
  const int steps = options.steps;
  const double dr = r_max / steps;
  for (int i = 0; i < steps; ++i) out.r.push_back(r_max * (i + 1) / steps);
  out.g.assign(steps, 0.0);

  const double sphere = D == 2 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi;
  std::vector<double> norm(steps);
  for (int i = 0; i < steps; ++i) norm[i] = sphere * kernel_moment(out.r[i], h, D);
  const double reach = r_max + h;

  std::vector<double> sum(steps);
  ProgressReporter reporter(progress, total);
  double visited = 0;
  for (const PointSet<D>& set : sets) {
    std::fill(sum.begin(), sum.end(), 0.0);
    // Cells of about the mean spacing keep the search local for any reach.
    Grid<D> grid(domain, std::max(reach / 4.0, std::pow(volume / set.size(), 1.0 / D)));
    for (const auto& p : set) {
      if (!domain.contains(p)) throw InvalidArgument("pair correlation: a point lies outside the domain");
      grid.insert(p);
    }
    for (std::size_t i = 0; i < set.size(); ++i) {
      if (i % 1024 == 0) reporter.update(visited + static_cast<double>(i));
      grid.for_each_within(set[i], reach, [&](std::int32_t j, double d2) {
        if (static_cast<std::size_t>(j) == i) return true;
        const double d = std::sqrt(d2);
        double w = 1.0;
        if (!domain.periodic)
          for (int a = 0; a < D; ++a) w *= domain.extent(a) / (domain.extent(a) - std::abs(set[j][a] - set[i][a]));
        // Only the r values within h of d carry kernel mass.
        const int lo = std::max(0, static_cast<int>(std::floor((d - h) / dr)) - 1);
        const int hi = std::min(steps - 1, static_cast<int>(std::ceil((d + h) / dr)));
        for (int k = lo; k <= hi; ++k) sum[k] += w * epanechnikov(out.r[k] - d, h);
        return true;
      });
    }
    visited += static_cast<double>(set.size());
    const double n = static_cast<double>(set.size());
    const double pairs_per_volume = n * (n - 1.0) / volume;
    for (int k = 0; k < steps; ++k) out.g[k] += sum[k] / (pairs_per_volume * norm[k]);
  }
  for (double& g : out.g) g /= static_cast<double>(sets.size());
  reporter.finish();
  return out;
}

template PairCorrelation pair_correlation<2>(std::span<const PointSet<2>>, const Domain<2>&,
                                             const PairCorrelationOptions&, const Progress&);
template PairCorrelation pair_correlation<3>(std::span<const PointSet<3>>, const Domain<3>&,
                                             const PairCorrelationOptions&, const Progress&);

}  // namespace pds
