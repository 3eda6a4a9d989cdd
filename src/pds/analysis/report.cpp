// The analysis report (include/pds/analysis/report.h): every measure of the
// analysis component, summarised for one or several sets.

#include "pds/analysis/report.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "pds/analysis/discrepancy.h"
#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"
#include "pds/analysis/relative_radius.h"
#include "pds/analysis/spacing.h"
#include "pds/detail/instantiate.h"
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
    r.budget_exhausted = mx.budget_exhausted;
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
  const bool hickernell_ok = smallest > 0 && std::all_of(sets.begin(), sets.end(), [&](const PointSet<D>& s) {
    return s.size() <= options.discrepancy_points;
  });
  std::array<double, 3> hickernell{};
  const std::vector<double> lo(domain.lo.begin(), domain.lo.end()), hi(domain.hi.begin(), domain.hi.end());
  const auto m = static_cast<double>(sets.size());
  ProgressReporter progress(options.progress, m + 2);
  for (std::size_t k = 0; k < sets.size(); ++k) {
    // A set's unit in six steps, one a measure: in many dimensions each
    // discrepancy is O(N^2 D) and can take a second or more, so each also
    // reports within its step.
    const auto step = [&](int done) { progress.update(static_cast<double>(k) + done / 6.0); };
    const auto within = [&](int done) {
      return progress.span(static_cast<double>(k) + done / 6.0, static_cast<double>(k) + (done + 1) / 6.0);
    };
    step(0);
    const PointSet<D>& s = sets[k];
    const Spacing sp = spacing(s, domain);
    rho_min += sp.rho_min;
    rho_mean += sp.rho_mean;
    step(1);
    if (l2_ok) l2 += l2_star_discrepancy(s, domain, within(1));
    step(2);
    if (star_ok) star += star_discrepancy(s, domain);
    step(3);
    if (hickernell_ok) {
      const PointCloud cloud = PointCloud::from(s);
      hickernell[0] += discrepancy(cloud, lo, hi, DiscrepancyMethod::Centered, within(3));
      step(4);
      hickernell[1] += discrepancy(cloud, lo, hi, DiscrepancyMethod::WrapAround, within(4));
      step(5);
      hickernell[2] += discrepancy(cloud, lo, hi, DiscrepancyMethod::Mixture, within(5));
    }
  }
  if (smallest > 1) {
    out.rho_min = rho_min / m;
    out.rho_mean = rho_mean / m;
  }
  if (l2_ok) out.l2_star_discrepancy = l2 / m;
  if (star_ok) out.star_discrepancy = star / m;
  if (hickernell_ok) {
    out.centered_discrepancy = hickernell[0] / m;
    out.wrap_around_discrepancy = hickernell[1] / m;
    out.mixture_discrepancy = hickernell[2] / m;
  }
  if constexpr (D != 2 && D != 3) {
    out.spectrum_note = "not computed: the spectrum is measured in 2D and 3D only";
    out.pcf_note = "not computed: the pair correlation is measured in 2D and 3D only";
    progress.finish();
    return out;
  } else {

  // Fourier view.
  progress.update(m);
  const int K = options.max_frequency > 0 ? options.max_frequency : (D == 2 ? 128 : 32);
  const double work = static_cast<double>(total) * std::pow(2.0 * K + 1.0, D) / 2.0;
  if (smallest > 0 && (options.spectrum || options.max_frequency > 0 || work <= options.spectrum_work)) {
    Periodogram p = periodogram<D>(sets, domain, {.max_frequency = K},
                                   part_of(options.progress, sets.size(), sets.size() + 2));
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
  progress.update(m + 1);
  if (smallest > 1) {
    PairCorrelation g =
        pair_correlation<D>(sets, domain, options.pcf, part_of(options.progress, sets.size() + 1, sets.size() + 2));
    out.pcf = summarise(g);
    if (curves) curves->pcf = std::move(g);
  }
  progress.finish();
  return out;
  }
}

AnalysisReport analyze(std::span<const PointCloud> sets, std::span<const double> lo, std::span<const double> hi,
                       bool periodic, const AnalysisOptions& options) {
  if (sets.empty()) throw InvalidArgument("analysis: no point sets");
  const int dim = sets[0].dim;
  for (const PointCloud& s : sets)
    if (s.dim != dim)
      throw InvalidArgument("analysis: sets of dimensions " + std::to_string(dim) + " and " + std::to_string(s.dim));
  if (lo.size() != static_cast<std::size_t>(dim) || hi.size() != static_cast<std::size_t>(dim))
    throw InvalidArgument("analysis: the bounds have " + std::to_string(lo.size()) + " and " +
                          std::to_string(hi.size()) + " coordinates, the points " + std::to_string(dim));
  if (dim >= kMinDim && dim <= kMaxDim)
    return visit_dim<kMinDim, kMaxDim>(dim, [&](auto d) {
      constexpr int D = decltype(d)::value;
      const Domain<D> domain = Domain<D>::from_bounds(lo.data(), hi.data(), periodic);
      domain.validate();
      std::vector<PointSet<D>> typed;
      for (const PointCloud& s : sets) typed.push_back(s.as<D>());
      return analyze<D>(std::span<const PointSet<D>>(typed), domain, options);
    });
  // Past kMaxDim: distances and discrepancies only.
  AnalysisReport out;
  out.count = sets[0].size();
  out.dim = dim;
  out.lo.assign(lo.begin(), lo.end());
  out.hi.assign(hi.begin(), hi.end());
  out.torus = periodic;
  // Progress: the first set's nearest neighbours, then each set's four
  // discrepancies (O(N^2 D) each), one unit apiece.
  ProgressReporter progress(options.progress, 1.0 + 4.0 * static_cast<double>(sets.size()));
  const NearestNeighbors nn = nearest_neighbors(sets[0], lo, hi, periodic);
  progress.update(1);
  double sum = 0;
  for (std::size_t i = 0; i < nn.distance.size(); ++i) {
    sum += nn.distance[i];
    if (nn.distance[i] < out.min_distance) {
      out.min_distance = nn.distance[i];
      out.min_distance_pair = std::array<std::size_t, 2>{std::min<std::size_t>(i, nn.index[i]),
                                                         std::max<std::size_t>(i, nn.index[i])};
    }
  }
  out.mean_nn_distance = out.count > 1 ? sum / static_cast<double>(out.count) : NAN;
  out.relative_radius = NAN;
  out.relative_radius_note =
      "undefined past " + std::to_string(kMaxDim) + " dimensions (the densest packing is not known there)";
  if (options.radius) {
    require_radius(*options.radius);
    out.radius = *options.radius;
    out.min_distance_holds = !(out.min_distance < *options.radius);
    out.maximality_note = "not checked past " + std::to_string(kMaxDim) + " dimensions";
  }
  out.sets = sets.size();
  std::size_t smallest = sets[0].size();
  for (const PointCloud& s : sets) smallest = std::min(smallest, s.size());
  const bool l2_ok = smallest > 0 && std::all_of(sets.begin(), sets.end(),
                                                 [](const PointCloud& s) { return s.size() <= kMaxL2StarPoints; });
  const bool hickernell_ok = smallest > 0 && std::all_of(sets.begin(), sets.end(), [&](const PointCloud& s) {
    return s.size() <= options.discrepancy_points;
  });
  std::array<double, 4> sums{};
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const PointCloud& s = sets[k];
    const auto step = [&](int done) { progress.update(1.0 + 4.0 * static_cast<double>(k) + done); };
    const auto within = [&](int done) {
      return progress.span(1.0 + 4.0 * static_cast<double>(k) + done, 2.0 + 4.0 * static_cast<double>(k) + done);
    };
    if (l2_ok) sums[0] += discrepancy(s, lo, hi, DiscrepancyMethod::L2Star, within(0));
    step(1);
    if (hickernell_ok) {
      sums[1] += discrepancy(s, lo, hi, DiscrepancyMethod::Centered, within(1));
      step(2);
      sums[2] += discrepancy(s, lo, hi, DiscrepancyMethod::WrapAround, within(2));
      step(3);
      sums[3] += discrepancy(s, lo, hi, DiscrepancyMethod::Mixture, within(3));
    }
    step(4);
  }
  const double m = static_cast<double>(sets.size());
  if (l2_ok) out.l2_star_discrepancy = sums[0] / m;
  if (hickernell_ok) {
    out.centered_discrepancy = sums[1] / m;
    out.wrap_around_discrepancy = sums[2] / m;
    out.mixture_discrepancy = sums[3] / m;
  }
  out.spectrum_note = "not computed: the spectrum is measured in 2D and 3D only";
  out.pcf_note = "not computed: the pair correlation is measured in 2D and 3D only";
  progress.finish();
  return out;
}

#define PDS_INSTANTIATE(D)                                                                                  \
  template AnalysisReport analyze<D>(std::span<const PointSet<D>>, const Domain<D>&, const AnalysisOptions&, \
                                     AnalysisCurves*);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
