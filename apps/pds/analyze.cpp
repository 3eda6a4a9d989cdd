// pds analyze [FILE ...] | --method NAME: measure point sets and print one
// JSON object; optionally write the pictures and tables of the analysis.
//
// Several files (or --sets M with --method) are realisations of one process:
// the fields of the foundation (count, min_distance, ...) describe the first
// set, as they did for a single file; the spectrum and the PCF are averaged
// over all sets, and the spacing and discrepancy fields are means over them.

#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "analysis_common.h"
#include "commands.h"
#include "pds/analysis/discrepancy.h"
#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"
#include "pds/analysis/pair_correlation.h"
#include "pds/analysis/relative_radius.h"
#include "pds/analysis/spacing.h"
#include "pds/analysis/spectrum.h"
#include "pds/error.h"
#include "pds/io/plot.h"
#include "pds/io/point_file.h"
#include "pds/registry.h"

namespace pds::cli {
namespace {

using Json = nlohmann::ordered_json;

/// Periodogram work (points x frequencies / 2) computed without being asked
/// for by --spectrum or --radial: a few seconds at most.
constexpr double kDefaultSpectrumWork = 2e9;

struct AnalyzeOptions {
  std::vector<std::string> files;
  DomainOptions domain;
  double radius = 0;
  // Generating the sets instead of reading them.
  std::string method;
  std::size_t sets = 1;
  std::uint64_t count = 0;
  std::uint64_t seed = 0;
  std::vector<std::string> params;
  // Analysis settings.
  int max_frequency = 0;
  std::string scale = "log";
  double pcf_bandwidth = 0, pcf_max = 0;
  double disk_radius = 0;
  // Outputs.
  std::string spectrum, radial, pcf, plot;
};

/// --radial and --pcf write a plot for a picture name and a CSV otherwise.
bool is_picture(const std::string& path) {
  for (const char* ext : {".png", ".svg", ".pdf"})
    if (path.size() > 4 && path.compare(path.size() - 4, 4, ext) == 0) return true;
  return false;
}

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

template <int D>
Json first_set_fields(const PointSet<D>& points, const Domain<D>& domain, std::optional<double> radius) {
  Json out;
  out["count"] = points.size();
  out["dim"] = D;
  out["domain"] = {{"lo", domain.lo}, {"hi", domain.hi}, {"torus", domain.periodic}};
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
  out["min_distance"] = number_or_null(m.distance);
  if (std::isfinite(m.distance)) out["min_distance_pair"] = {m.i, m.j};
  out["mean_nn_distance"] = number_or_null(points.size() > 1 ? sum / points.size() : NAN);
  out["relative_radius"] = relative_radius(m.distance, domain.volume(), points.size(), D);
  out["max_packing_radius"] =
      points.empty() ? Json(nullptr) : Json(max_packing_radius(domain.volume(), points.size(), D));
  if (radius) {
    out["radius"] = *radius;
    out["min_distance_holds"] = !(m.distance < *radius);
    const Maximality<D> mx = check_maximality(points, domain, *radius);
    out["maximal"] = mx.maximal;
    Json detail;
    detail["exact"] = mx.tolerance == 0.0;
    detail["tolerance"] = mx.tolerance;
    if (mx.gap) {
      detail["gap"] = *mx.gap;
      detail["gap_distance"] = number_or_null(mx.gap_distance);
    }
    detail["cells_checked"] = mx.cells_checked;
    out["maximality"] = detail;
  }
  return out;
}

template <int D>
Json analyze(const std::vector<PointSet<D>>& sets, const Domain<D>& domain, std::optional<double> radius,
             const AnalyzeOptions& opt) {
  for (std::size_t s = 0; s < sets.size(); ++s)
    for (std::size_t i = 0; i < sets[s].size(); ++i)
      if (!domain.contains(sets[s][i])) {
        std::ostringstream os;
        os << (sets.size() > 1 ? "set " + std::to_string(s) + ": " : "") << "point " << i << " " << sets[s][i]
           << " lies outside the domain " << domain << " (give --bounds to match the file)";
        throw InvalidArgument(os.str());
      }
  Json out = first_set_fields(sets[0], domain, radius);
  out["sets"] = sets.size();
  std::size_t smallest = sets[0].size(), total = 0;
  for (const auto& s : sets) {
    smallest = std::min(smallest, s.size());
    total += s.size();
  }

  // Spacing and discrepancy: means over the sets.
  double rho_min = 0, rho_mean = 0, l2 = 0, star = 0;
  const bool l2_ok = smallest > 0 && [&] {
    for (const auto& s : sets)
      if (s.size() > kMaxL2StarPoints) return false;
    return true;
  }();
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
  out["rho_min"] = smallest > 1 ? Json(rho_min / m) : Json(nullptr);
  out["rho_mean"] = smallest > 1 ? Json(rho_mean / m) : Json(nullptr);
  out["l2_star_discrepancy"] = l2_ok ? Json(l2 / m) : Json(nullptr);
  out["star_discrepancy"] = star_ok ? Json(star / m) : Json(nullptr);

  // Fourier view.
  const int K = opt.max_frequency > 0 ? opt.max_frequency : (D == 2 ? 128 : 32);
  const double work = static_cast<double>(total) * std::pow(2.0 * K + 1.0, D) / 2.0;
  const bool wanted = !opt.spectrum.empty() || !opt.radial.empty() || opt.max_frequency > 0;
  if (!opt.spectrum.empty() && D != 2) throw InvalidArgument("--spectrum: pictures of the spectrum are 2D only");
  if (smallest > 0 && (wanted || work <= kDefaultSpectrumWork)) {
    const Periodogram p = periodogram<D>(sets, domain, {.max_frequency = K});
    const RadialSpectrum r = radial_average(p);
    Json spec;
    spec["max_frequency"] = K;
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
    spec["low_frequency_power"] = n_low ? Json(low / n_low) : Json(nullptr);
    spec["peak_frequency"] = r.power.empty() ? Json(nullptr) : Json(r.frequency[peak]);
    spec["peak_power"] = r.power.empty() ? Json(nullptr) : Json(r.power[peak]);
    spec["mean_anisotropy_db"] = r.power.empty() ? Json(nullptr) : Json(aniso / r.power.size());
    out["spectrum"] = spec;
    if (!opt.spectrum.empty())
      plot_spectrum(p, opt.spectrum, {.scale = opt.scale == "linear" ? SpectrumScale::Linear : SpectrumScale::Log});
    if (is_picture(opt.radial))
      plot_radial(r, opt.radial, {.title = "radial power spectrum, " + std::to_string(sets.size()) + " set(s)"});
    else if (!opt.radial.empty())
      write_csv_columns(opt.radial, {"frequency", "power", "anisotropy_db"},
                        {&r.frequency, &r.power, &r.anisotropy_db});
  } else {
    out["spectrum"] = nullptr;
    if (smallest > 0)
      out["spectrum_note"] = "skipped: more than " + std::to_string(static_cast<long long>(kDefaultSpectrumWork)) +
                             " point-frequency products; ask with --frequencies, --spectrum or --radial";
  }

  // Pair correlation.
  if (smallest > 1) {
    const PairCorrelation g = pair_correlation<D>(sets, domain, {.r_max = opt.pcf_max, .bandwidth = opt.pcf_bandwidth});
    std::size_t peak = 0;
    for (std::size_t i = 0; i < g.g.size(); ++i)
      if (g.g[i] > g.g[peak]) peak = i;
    out["pcf"] = {{"bandwidth", g.bandwidth}, {"r_max", g.r.back()}, {"peak_r", g.r[peak]}, {"peak_g", g.g[peak]}};
    if (is_picture(opt.pcf))
      plot_pair_correlation(g, opt.pcf, {.title = "pair correlation function"});
    else if (!opt.pcf.empty())
      write_csv_columns(opt.pcf, {"r", "g"}, {&g.r, &g.g});
  } else {
    out["pcf"] = nullptr;
    if (!opt.pcf.empty()) throw InvalidArgument("--pcf: every set needs at least two points");
  }

  if (!opt.plot.empty()) {
    if constexpr (D == 2)
      plot_points(sets[0], domain, opt.plot, {.disk_radius = opt.disk_radius});
    else
      throw InvalidArgument("--plot: point pictures are 2D only");
  }
  return out;
}

}  // namespace

void add_analyze(CLI::App& app) {
  auto opt = std::make_shared<AnalyzeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "analyze", "Measure point sets (files, '-' for CSV on stdin, or --method to generate them); prints JSON");
  cmd->add_option("file", opt->files, "Point files (.csv or .npy) or '-'; several files are several realisations");
  add_domain_options(*cmd, opt->domain, true);
  auto* radius = cmd->add_option("--radius,-r", opt->radius,
                                 "Minimum distance to check (and, with --method, to generate with); also reports "
                                 "maximality at this radius");
  auto* method =
      cmd->add_option("--method,-m", opt->method, "Generate the sets with this method instead of reading files");
  cmd->add_option("--sets,-M", opt->sets, "With --method: number of realisations (seeds SEED, SEED+1, ...)")
      ->capture_default_str();
  auto* count = cmd->add_option("--count,-n", opt->count, "With --method: points per set");
  cmd->add_option("--seed,-s", opt->seed, "With --method: seed of the first set")->capture_default_str();
  cmd->add_option("--param,-P", opt->params, "With --method: method parameter NAME=VALUE (repeatable)");
  cmd->add_option("--frequencies,-K", opt->max_frequency,
                  "Periodogram frequencies -K..K per axis (default 128 in 2D, 32 in 3D)");
  cmd->add_option("--scale", opt->scale, "Spectrum picture scale")
      ->check(CLI::IsMember({"log", "linear"}))
      ->capture_default_str();
  cmd->add_option("--pcf-bandwidth", opt->pcf_bandwidth,
                  "PCF kernel half-width in domain units (default 0.1 mean inter-point distances)");
  cmd->add_option("--pcf-max", opt->pcf_max, "Largest PCF distance (default 2.5 mean inter-point distances)");
  cmd->add_option("--disk-radius", opt->disk_radius, "--plot also draws disks of this radius around the points");
  cmd->add_option("--spectrum", opt->spectrum, "Write the averaged periodogram image (.png, .svg, .pdf)");
  cmd->add_option("--radial", opt->radial,
                  "Write the radial spectrum: CSV (frequency,power,anisotropy_db), or a plot for .png/.svg/.pdf");
  cmd->add_option("--pcf", opt->pcf, "Write the pair correlation function: CSV (r,g), or a plot for .png/.svg/.pdf");
  cmd->add_option("--plot", opt->plot, "Write a picture of the (first) point set (.png, .svg, .pdf)");
  cmd->callback([opt, radius, method, count, cmd] {
    std::optional<double> r;
    if (radius->count()) {
      require_radius(opt->radius);
      r = opt->radius;
    }
    for (const std::string* path : {&opt->spectrum, &opt->plot})
      if (!path->empty()) image_format_for(*path);  // fail before the work
    if (opt->sets < 1 || opt->sets > 100000)
      throw InvalidArgument("--sets must be in [1, 100000], got " + std::to_string(opt->sets));
    if (opt->max_frequency < 0) throw InvalidArgument("--frequencies must be positive");
    Json out;
    std::vector<PointCloud> clouds;
    const bool generating = method->count() > 0;
    if (generating == !opt->files.empty())
      throw InvalidArgument(generating ? "give point files or --method, not both"
                                       : "give point files (or '-') or --method NAME to generate the sets");
    if (generating) {
      GenerateRequest request;
      request.dim = opt->domain.dim;
      request.torus = opt->domain.torus;
      split_bounds(opt->domain, request.dim, request.lo, request.hi);
      if (count->count()) request.count = opt->count;
      request.radius = r;
      request.seed = opt->seed;
      request.params = parse_params(opt->params);
      clouds = generate_sets(opt->method, request, opt->sets);
      out["method"] = opt->method;
      out["seed"] = opt->seed;
    } else {
      if (cmd->get_option("--sets")->count() || count->count() || !opt->params.empty() ||
          cmd->get_option("--dim")->count() || cmd->get_option("--seed")->count())
        throw InvalidArgument("--sets, --count, --seed, --dim and --param apply to --method only");
      int stdin_uses = 0;
      for (const std::string& f : opt->files) stdin_uses += f == "-";
      if (stdin_uses > 1) throw InvalidArgument("'-' (standard input) can be given once");
      for (const std::string& f : opt->files) {
        clouds.push_back(read_points(f));
        if (clouds.back().dim != clouds.front().dim)
          throw InvalidArgument("'" + f + "' has dimension " + std::to_string(clouds.back().dim) + ", '" +
                                opt->files.front() + "' has " + std::to_string(clouds.front().dim));
      }
      out["file"] = opt->files.front();
      if (opt->files.size() > 1) out["files"] = opt->files;
    }
    const Json body = visit_dim(clouds.front().dim, [&](auto d) {
      constexpr int D = decltype(d)::value;
      GenerateRequest spec;  // reuses the request's bounds handling
      spec.dim = D;
      spec.torus = opt->domain.torus;
      split_bounds(opt->domain, D, spec.lo, spec.hi);
      std::vector<PointSet<D>> sets;
      for (const PointCloud& c : clouds) sets.push_back(c.as<D>());
      return analyze<D>(sets, spec.domain<D>(), r, *opt);
    });
    out.update(body);
    std::cout << out.dump(2) << std::endl;
  });
}

}  // namespace pds::cli
