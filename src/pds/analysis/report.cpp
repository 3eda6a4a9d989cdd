// The analysis report (include/pds/analysis/report.h): every measure of the
// analysis component, summarised for one or several sets.

#include "pds/analysis/report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "pds/analysis/discrepancy.h"
#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"
#include "pds/analysis/relative_radius.h"
#include "pds/analysis/spacing.h"
#include "pds/error.h"
#include "pds/limits.h"

namespace pds {
namespace {

// The fields that describe the first set: its size, domain, nearest
// neighbours, and the radius checks.
template <int D>
void first_set_fields(const PointSet<D>& points, const Domain<D>& domain, std::optional<double> radius,
                      AnalysisReport& out) {
  out.count = points.size();
  out.dim = D;
  out.lo.assign(domain.lo.begin(), domain.lo.end());
  out.hi.assign(domain.hi.begin(), domain.hi.end());
  out.torus = domain.periodic;
  // One pass over the nearest neighbours gives both the minimum and the mean.
  const NearestNeighbors nn = nearest_neighbors(points, domain);
  MinDistance m;
  double sum = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    sum += nn.distance[i];
    if (nn.distance[i] < m.distance) {
      m.distance = nn.distance[i];
      m.i = std::min<std::size_t>(i, nn.index[i]);
      m.j = std::max<std::size_t>(i, nn.index[i]);
    }
  }
  out.min_distance = m.distance;
  if (std::isfinite(m.distance)) out.min_distance_pair = std::array<std::size_t, 2>{m.i, m.j};
  out.mean_nn_distance = points.size() > 1 ? sum / points.size() : NAN;
  out.relative_radius = relative_radius(m.distance, domain.volume(), points.size(), D);
  out.max_packing_radius = points.empty() ? NAN : max_packing_radius(domain.volume(), points.size(), D);
  if (radius) {
    out.radius = *radius;
    out.min_distance_holds = !(m.distance < *radius);
    const Maximality<D> mx = check_maximality(points, domain, *radius);
    MaximalityReport r;
    r.maximal = mx.maximal;
    r.exact = mx.tolerance == 0.0;
    r.tolerance = mx.tolerance;
    if (mx.gap) {
      r.gap = std::vector<double>(mx.gap->begin(), mx.gap->end());
      r.gap_distance = mx.gap_distance;
    }
    r.cells_checked = mx.cells_checked;
    out.maximality = r;
  }
}

SpectrumSummary summarise(const RadialSpectrum& r, int max_frequency) {
  SpectrumSummary s;
  s.max_frequency = max_frequency;
  double low = 0, aniso = 0;
  int n_low = 0;
  std::size_t peak = 0;
  for (std::size_t b = 0; b < r.power.size(); ++b) {
    if (r.frequency[b] <= 0.5) {
      low += r.power[b];
      ++n_low;
    }
    if (r.power[b] > r.power[peak]) peak = b;
    aniso += r.anisotropy_db[b];
  }
  if (n_low) s.low_frequency_power = low / n_low;
  if (!r.power.empty()) {
    s.peak_frequency = r.frequency[peak];
    s.peak_power = r.power[peak];
    s.mean_anisotropy_db = aniso / r.power.size();
  }
  return s;
}

PcfSummary summarise(const PairCorrelation& g) {
  std::size_t peak = 0;
  for (std::size_t i = 0; i < g.g.size(); ++i)
    if (g.g[i] > g.g[peak]) peak = i;
  return {.bandwidth = g.bandwidth, .r_max = g.r.back(), .peak_r = g.r[peak], .peak_g = g.g[peak]};
}

}  // namespace

template <int D>
AnalysisReport analyze(std::span<const PointSet<D>> sets, const Domain<D>& domain, const AnalysisOptions& options,
                       AnalysisCurves* curves) {
  if (sets.empty()) throw InvalidArgument("analysis: no point sets");
  if (options.radius) require_radius(*options.radius);
  for (std::size_t s = 0; s < sets.size(); ++s)
    for (std::size_t i = 0; i < sets[s].size(); ++i)
      if (!domain.contains(sets[s][i])) {
        std::ostringstream os;
        os << (sets.size() > 1 ? "set " + std::to_string(s) + ": " : "") << "point " << i << " " << sets[s][i]
           << " lies outside the domain " << domain;
        throw InvalidArgument(os.str());
      }

  AnalysisReport out;
  first_set_fields(sets[0], domain, options.radius, out);
  out.sets = sets.size();
  std::size_t smallest = sets[0].size(), total = 0;
  for (const auto& s : sets) {
    smallest = std::min(smallest, s.size());
    total += s.size();
  }

  // Spacing and discrepancy: means over the sets.
  double rho_min = 0, rho_mean = 0, l2 = 0, star = 0;
  const bool l2_ok = smallest > 0 && std::all_of(sets.begin(), sets.end(),
                                                 [](const PointSet<D>& s) { return s.size() <= kMaxL2StarPoints; });
  bool star_ok = smallest > 0;
  for (const auto& s : sets) star_ok = star_ok && star_discrepancy_feasible(s.size(), D);
  for (const auto& s : sets) {
    const Spacing sp = spacing(s, domain);
    rho_min += sp.rho_min;
    rho_mean += sp.rho_mean;
    if (l2_ok) l2 += l2_star_discrepancy(s, domain);
    if (star_ok) star += star_discrepancy(s, domain);
  }
  const double m = static_cast<double>(sets.size());
  if (smallest > 1) {
    out.rho_min = rho_min / m;
    out.rho_mean = rho_mean / m;
  }
  if (l2_ok) out.l2_star_discrepancy = l2 / m;
  if (star_ok) out.star_discrepancy = star / m;

  // Fourier view.
  const int K = options.max_frequency > 0 ? options.max_frequency : (D == 2 ? 128 : 32);
  const double work = static_cast<double>(total) * std::pow(2.0 * K + 1.0, D) / 2.0;
  if (smallest > 0 && (options.spectrum || options.max_frequency > 0 || work <= options.spectrum_work)) {
    Periodogram p = periodogram<D>(sets, domain, {.max_frequency = K});
    RadialSpectrum r = radial_average(p);
    out.spectrum = summarise(r, K);
    if (curves) {
      curves->periodogram = std::move(p);
      curves->radial = std::move(r);
    }
  } else if (smallest > 0) {
    out.spectrum_note = "skipped: more than " + std::to_string(static_cast<long long>(options.spectrum_work)) +
                        " point-frequency products; ask for it with a number of frequencies or the spectrum option";
  }

  // Pair correlation.
  if (smallest > 1) {
    PairCorrelation g = pair_correlation<D>(sets, domain, options.pcf);
    out.pcf = summarise(g);
    if (curves) curves->pcf = std::move(g);
  }
  return out;
}

template AnalysisReport analyze<2>(std::span<const PointSet<2>>, const Domain<2>&, const AnalysisOptions&,
                                   AnalysisCurves*);
template AnalysisReport analyze<3>(std::span<const PointSet<3>>, const Domain<3>&, const AnalysisOptions&,
                                   AnalysisCurves*);

}  // namespace pds
