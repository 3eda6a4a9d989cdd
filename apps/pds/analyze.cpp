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
#include <span>
#include <sstream>

#include "analysis_common.h"
#include "commands.h"
#include "pds/analysis/report.h"
#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/io/chunks.h"
#include "pds/io/plot.h"
#include "pds/io/point_file.h"
#include "pds/io/report_json.h"
#include "pds/registry.h"
#include "terminal.h"

namespace pds::cli {
namespace {

struct AnalyzeOptions {
  std::vector<std::string> files;
  DomainOptions domain;
  double radius = 0;
  // Generating the sets instead of reading them.
  std::string method;
  std::size_t sets = 1;
  GenerationOptions generation;  // its --dim; --torus and --bounds are `domain`, --radius is `radius`
  // Analysis settings.
  int max_frequency = 0;
  std::string scale = "log";
  double pcf_bandwidth = 0, pcf_max = 0;
  double disk_radius = 0;
  double dot_radius = 0;
  std::vector<double> class_dots;  // --class-dots: the dot radius of each class
  std::vector<double> point_dots;  // the first set's dots, one a point, from its class column
  // Outputs.
  std::string spectrum, radial, pcf, plot;
};

const GenerationOptionSet kAnalyzeGeneration{.radius = false, .domain = false, .scope = "with --method"};

/// --radial and --pcf write a plot for a picture name and a CSV otherwise.
bool is_picture(const std::string& path) {
  for (const char* ext : {".png", ".svg", ".pdf"})
    if (path.size() > 4 && path.compare(path.size() - 4, 4, ext) == 0) return true;
  return false;
}

template <int D>
AnalysisReport analyze_and_draw(const std::vector<PointSet<D>>& sets, const Domain<D>& domain,
                                std::optional<double> radius, const AnalyzeOptions& opt) {
  // Input checks first, in the command's words, before any work.
  for (std::size_t s = 0; s < sets.size(); ++s)
    for (std::size_t i = 0; i < sets[s].size(); ++i)
      if (!domain.contains(sets[s][i])) {
        std::ostringstream os;
        os << (sets.size() > 1 ? "set " + std::to_string(s) + ": " : "") << "point " << i << " " << sets[s][i]
           << " lies outside the domain " << domain << " (give --bounds to match the file)";
        throw InvalidArgument(os.str());
      }
  if (!opt.spectrum.empty() && D != 2) throw InvalidArgument("--spectrum: pictures of the spectrum are 2D only");
  if (!opt.plot.empty() && D != 2) throw InvalidArgument("--plot: point pictures are 2D only");
  if (D != 2 && D != 3)
    for (const auto& [name, value] : {std::pair{"--radial", &opt.radial}, std::pair{"--pcf", &opt.pcf}})
      if (!value->empty())
        throw InvalidArgument(std::string(name) + ": spectra and the pair correlation are measured in 2D and 3D only");

  AnalysisCurves curves;
  AnalysisReport report;
  {
    const ProgressBar bar("analysis", opt.generation.quiet);
    report = analyze<D>(sets, domain,
                        {.radius = radius,
                         .max_frequency = opt.max_frequency,
                         .spectrum = !opt.spectrum.empty() || !opt.radial.empty(),
                         .pcf = {.r_max = opt.pcf_max, .bandwidth = opt.pcf_bandwidth},
                         .progress = bar.progress()},
                        &curves);
  }
  if (!report.spectrum_note.empty() && (D == 2 || D == 3))
    report.spectrum_note = "skipped: more than " + std::to_string(static_cast<long long>(kDefaultSpectrumWork)) +
                           " point-frequency products; ask with --frequencies, --spectrum or --radial";

  if (curves.periodogram) {
    if (!opt.spectrum.empty())
      plot_spectrum(*curves.periodogram, opt.spectrum,
                    {.scale = opt.scale == "linear" ? SpectrumScale::Linear : SpectrumScale::Log});
    const RadialSpectrum& r = *curves.radial;
    if (is_picture(opt.radial))
      plot_radial(r, opt.radial, {.title = "radial power spectrum, " + std::to_string(sets.size()) + " set(s)"});
    else if (!opt.radial.empty())
      write_csv_columns(opt.radial, {"frequency", "power", "anisotropy_db"},
                        {&r.frequency, &r.power, &r.anisotropy_db});
  }
  if (curves.pcf) {
    const PairCorrelation& g = *curves.pcf;
    if (is_picture(opt.pcf))
      plot_pair_correlation(g, opt.pcf, {.title = "pair correlation function"});
    else if (!opt.pcf.empty())
      write_csv_columns(opt.pcf, {"r", "g"}, {&g.r, &g.g});
  } else if (!opt.pcf.empty()) {
    throw InvalidArgument("--pcf: every set needs at least two points");
  }
  if constexpr (D == 2)
    if (!opt.plot.empty())
      plot_points(sets[0], domain, opt.plot,
                  {.disk_radius = opt.disk_radius, .dot_radius = opt.dot_radius, .dot_radii = opt.point_dots});
  return report;
}

// --class-dots: takes the class column off every set and gives the first
// set's points their dot radii.
void strip_classes(std::vector<PointCloud>& clouds, AnalyzeOptions& opt) {
  for (const double r : opt.class_dots)
    if (!(r > 0) || !std::isfinite(r))
      throw InvalidArgument("--class-dots: radii must be positive, got " + detail::format_number(r));
  for (std::size_t s = 0; s < clouds.size(); ++s) {
    PointCloud& c = clouds[s];
    if (c.dim < 2) throw InvalidArgument("--class-dots: the points need a class column after their coordinates");
    PointCloud stripped{c.dim - 1, {}};
    stripped.coords.reserve(c.size() * static_cast<std::size_t>(stripped.dim));
    for (std::size_t i = 0; i < c.size(); ++i) {
      const double k = c.point(i)[c.dim - 1];
      if (!(k >= 0 && k < static_cast<double>(opt.class_dots.size()) && k == std::floor(k)))
        throw InvalidArgument("--class-dots: point " + std::to_string(i) + " has class " + detail::format_number(k) +
                              "; " + std::to_string(opt.class_dots.size()) + " radii cover classes 0 to " +
                              std::to_string(opt.class_dots.size() - 1));
      stripped.coords.insert(stripped.coords.end(), c.point(i), c.point(i) + stripped.dim);
      if (s == 0) opt.point_dots.push_back(opt.class_dots[static_cast<std::size_t>(k)]);
    }
    c = std::move(stripped);
  }
}

}  // namespace

void add_analyze(CLI::App& app) {
  auto opt = std::make_shared<AnalyzeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "analyze",
      "Measure point sets (files, '-' for CSV on stdin, or --method to generate them); prints JSON. Minimum and "
      "nearest-neighbour distances and the L2-star, centered, wrap-around and mixture discrepancies in any "
      "dimension; relative radius and maximality (--radius) in 1 to 8; spectra and pair correlation in 2D and 3D");
  cmd->add_option("file", opt->files, "Point files (.csv or .npy, any number of columns), '-', or a chunked set's manifest.json (pds chunks); "
                  "several files are several realisations");
  add_domain_options(*cmd, opt->domain, false);
  auto* radius = cmd->add_option("--radius,-r", opt->radius,
                                 "Minimum distance to check (and, with --method, to generate with); also reports "
                                 "maximality at this radius");
  auto* method =
      cmd->add_option("--method,-m", opt->method, "Generate the sets with this method instead of reading files");
  cmd->add_option("--sets,-M", opt->sets, "With --method: number of realisations (seeds SEED, SEED+1, ...)")
      ->capture_default_str();
  add_generation_options(*cmd, opt->generation, kAnalyzeGeneration);
  cmd->add_option("--frequencies,-K", opt->max_frequency,
                  "Periodogram frequencies -K..K per axis (default 128 in 2D, 32 in 3D)");
  cmd->add_option("--scale", opt->scale, "Spectrum picture scale")
      ->check(CLI::IsMember({"log", "linear"}))
      ->capture_default_str();
  cmd->add_option("--pcf-bandwidth", opt->pcf_bandwidth,
                  "PCF kernel half-width in domain units (default 0.1 mean inter-point distances)");
  cmd->add_option("--pcf-max", opt->pcf_max, "Largest PCF distance (default 2.5 mean inter-point distances)");
  cmd->add_option("--disk-radius", opt->disk_radius, "--plot also draws disks of this radius around the points");
  cmd->add_option("--dot-radius", opt->dot_radius,
                  "--plot draws dots of this radius (domain units), e.g. for a stippling");
  cmd->add_option("--class-dots", opt->class_dots,
                  "The files' last column is a class (0, 1, ...; as pds generate --classes writes): it is left out "
                  "of the analysis, and --plot draws class c's dots with the c-th radius given")
      ->delimiter(',');
  cmd->add_option("--spectrum", opt->spectrum, "Write the averaged periodogram image (.png, .svg, .pdf)");
  cmd->add_option("--radial", opt->radial,
                  "Write the radial spectrum: CSV (frequency,power,anisotropy_db), or a plot for .png/.svg/.pdf");
  cmd->add_option("--pcf", opt->pcf, "Write the pair correlation function: CSV (r,g), or a plot for .png/.svg/.pdf");
  cmd->add_option("--plot", opt->plot, "Write a picture of the (first) point set (.png, .svg, .pdf)");
  cmd->callback([opt, radius, method, cmd] {
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
    std::vector<PointCloud> clouds;
    AnalysisSource source;
    const bool generating = method->count() > 0;
    if (generating == !opt->files.empty())
      throw InvalidArgument(generating ? "give point files or --method, not both"
                                       : "give point files (or '-') or --method NAME to generate the sets");
    if (generating) {
      opt->generation.domain.torus = opt->domain.torus;
      opt->generation.domain.bounds = opt->domain.bounds;
      GenerateRequest request = generation_request(opt->generation, kAnalyzeGeneration);
      request.radius = r;
      const ProgressBar bar(opt->method + " sets", opt->generation.quiet);
      clouds = generate_sets(opt->method, request, opt->sets, bar.progress());
      source.method = opt->method;
      source.seed = request.seed;
    } else {
      if (cmd->get_option("--sets")->count() || any_generation_option_given(opt->generation))
        throw InvalidArgument(
            "--sets, --count, --seed, --dim, --threads, --max-points and --param apply to --method only");
      int stdin_uses = 0;
      for (const std::string& f : opt->files) stdin_uses += f == "-";
      if (stdin_uses > 1) throw InvalidArgument("'-' (standard input) can be given once");
      for (const std::string& f : opt->files) {
        if (f.size() >= 5 && f.compare(f.size() - 5, 5, ".json") == 0) {
          // A chunked set (pds chunks): its chunks as one set, over the
          // region they cover (a torus when they cover the whole torus)
          // unless --bounds says otherwise.
          ChunkManifest m;
          clouds.push_back(read_chunks(f, &m));
          if (opt->domain.bounds.empty()) {
            opt->domain.bounds = m.lo;
            opt->domain.bounds.insert(opt->domain.bounds.end(), m.hi.begin(), m.hi.end());
            if (!m.torus_lo.empty() && m.torus_lo == m.lo && m.torus_hi == m.hi) opt->domain.torus = true;
          }
        } else {
          clouds.push_back(read_points(f));
        }
        if (clouds.back().dim != clouds.front().dim)
          throw InvalidArgument("'" + f + "' has dimension " + std::to_string(clouds.back().dim) + ", '" +
                                opt->files.front() + "' has " + std::to_string(clouds.front().dim));
      }
      source.files = opt->files;
      if (!opt->class_dots.empty()) strip_classes(clouds, *opt);
    }
    const int dim = clouds.front().dim;
    const AnalysisReport report = [&] {
      if (dim > kMaxDim) {
        // Past 8 dimensions: distances and discrepancies (analysis/report.h).
        for (const std::string* path : {&opt->spectrum, &opt->plot, &opt->radial, &opt->pcf})
          if (!path->empty())
            throw InvalidArgument("spectra, the pair correlation and pictures are 2D/3D only; the points have " +
                                  std::to_string(dim) + " dimensions");
        std::vector<double> lo, hi;
        split_bounds(opt->domain, dim, lo, hi);
        if (lo.empty()) {  // the unit cube
          lo.assign(static_cast<std::size_t>(dim), 0.0);
          hi.assign(static_cast<std::size_t>(dim), 1.0);
        }
        const ProgressBar bar("analysis", opt->generation.quiet);
        return analyze(std::span<const PointCloud>(clouds), lo, hi, opt->domain.torus,
                       {.radius = r, .progress = bar.progress()});
      }
      return visit_dim<kMinDim, kMaxDim>(dim, [&](auto d) {
        constexpr int D = decltype(d)::value;
        GenerateRequest spec;  // reuses the request's bounds handling
        spec.dim = D;
        spec.torus = opt->domain.torus;
        split_bounds(opt->domain, D, spec.lo, spec.hi);
        std::vector<PointSet<D>> sets;
        for (const PointCloud& c : clouds) sets.push_back(c.as<D>());
        return analyze_and_draw<D>(sets, spec.domain<D>(), r, *opt);
      });
    }();
    std::cout << analysis_report_json(report, source) << std::endl;
  });
}

}  // namespace pds::cli
