// pds compare [METHOD ...] -o SHEET: the comparison of patterns of Lagae & Dutre (2008), one
// row per method with the spatial view (one set) beside the Fourier view (the
// periodogram and radial power averaged over --sets realisations), all on the
// unit torus so that the spectrum has no boundary artefacts.

#include <memory>

#include "analysis_common.h"
#include "commands.h"
#include "pds/analysis/spectrum.h"
#include "pds/error.h"
#include "pds/io/plot.h"
#include "pds/registry.h"
#include "terminal.h"

namespace pds::cli {
namespace {

struct CompareOptions {
  std::vector<std::string> methods;
  GenerationOptions generation;  // on the unit torus in 2D, so neither --dim nor a domain
  std::size_t sets = 10;
  int max_frequency = 64;
  int panel = 320;
  std::string output;
};

const GenerationOptionSet kCompareGeneration{.radius = false, .dim = false, .domain = false, .default_count = 1024};

/// The default rows: the methods the registry marks for comparison, in its
/// order (white noise, stratified, then the Poisson disk families).
std::vector<std::string> default_methods() {
  std::vector<std::string> out;
  for (const Method& m : methods())
    if (m.compare) out.push_back(m.name);
  return out;
}

}  // namespace

void add_compare(CLI::App& app) {
  auto opt = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "Draw one sheet comparing methods: points beside their spectrum (spatial and Fourier views)");
  std::string defaults;
  for (const std::string& name : default_methods()) defaults += (defaults.empty() ? "" : ", ") + name;
  cmd->add_option("methods", opt->methods, "Methods to compare (default: " + defaults + ")");
  add_generation_options(*cmd, opt->generation, kCompareGeneration);
  cmd->add_option("--sets,-M", opt->sets, "Realisations averaged in the spectrum (seeds SEED, SEED+1, ...)")
      ->capture_default_str();
  cmd->add_option("--frequencies,-K", opt->max_frequency, "Periodogram frequencies -K..K per axis")
      ->capture_default_str();
  cmd->add_option("--panel", opt->panel, "Size of each panel")->capture_default_str();
  cmd->add_option("--output,-o", opt->output, "The sheet (.png, .svg or .pdf)")->required();
  cmd->callback([opt] {
    image_format_for(opt->output);
    if (opt->sets < 1 || opt->sets > 1000)
      throw InvalidArgument("--sets must be in [1, 1000], got " + std::to_string(opt->sets));
    const std::vector<std::string> names = opt->methods.empty() ? default_methods() : opt->methods;
    if (names.empty()) throw InvalidArgument("no methods to compare");
    std::vector<ComparisonRow> rows;
    for (const std::string& name : names) {
      find_method(name);  // names the known methods if unknown
      GenerateRequest request = generation_request(opt->generation, kCompareGeneration);
      request.torus = true;
      std::vector<PointSet<2>> sets;
      {
        const ProgressBar bar(name, opt->generation.quiet);
        for (const PointCloud& c : generate_sets(name, request, opt->sets, bar.progress())) sets.push_back(c.as<2>());
      }
      const Domain<2> domain = Domain<2>::unit(true);
      ComparisonRow row;
      row.name = name;
      row.points = sets.front();
      row.domain = domain;
      row.spectrum = periodogram<2>(sets, domain, {.max_frequency = opt->max_frequency});
      row.radial = radial_average(row.spectrum);
      rows.push_back(std::move(row));
    }
    plot_comparison(rows, opt->output, opt->panel);
  });
}

}  // namespace pds::cli
