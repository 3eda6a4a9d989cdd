// pds tile METHOD ...: a pattern on the unit torus, for tiling the plane.

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "analysis_common.h"
#include "commands.h"
#include "pds/analysis/distance.h"
#include "pds/analysis/relative_radius.h"
#include "pds/io/point_file.h"
#include "pds/registry.h"

namespace pds::cli {
namespace {

struct TileOptions {
  std::string method;
  int dim = 2;
  std::uint64_t count = 0;
  double radius = 0;
  std::uint64_t seed = 0;
  int threads = 0;
  std::vector<std::string> params;
  std::string output;
};

}  // namespace

void add_tile(CLI::App& app) {
  auto opt = std::make_shared<TileOptions>();
  CLI::App* cmd = app.add_subcommand(
      "tile", "Generate a tileable pattern: METHOD run on the unit torus, so its minimum distance holds across seams");
  cmd->footer(methods_help());
  cmd->add_option("method", opt->method, "Sampling method (see the list below)")->required();
  auto* count = cmd->add_option("--count,-n", opt->count, "Number of points");
  auto* radius = cmd->add_option("--radius,-r", opt->radius, "Minimum distance between any two samples (torus)");
  cmd->add_option("--dim,-d", opt->dim, "Dimension (2 or 3)")->capture_default_str();
  cmd->add_option("--seed,-s", opt->seed, "Random seed; the same seed gives the same bytes")->capture_default_str();
  cmd->add_option("--threads,-t", opt->threads, "Threads for parallel methods (0: all cores)")->capture_default_str();
  cmd->add_option("--param,-P", opt->params, "Method parameter NAME=VALUE (repeatable)");
  cmd->add_option("--output,-o", opt->output, "Output file (.npy or .csv); '-' for CSV on stdout")->required();
  cmd->callback([opt, count, radius] {
    GenerateRequest request;
    request.dim = opt->dim;
    request.torus = true;
    if (count->count()) request.count = opt->count;
    if (radius->count()) request.radius = opt->radius;
    request.seed = opt->seed;
    request.threads = opt->threads;
    request.params = parse_params(opt->params);
    const PointCloud points = generate(opt->method, request);
    write_points(opt->output, points);
    if (opt->output == "-") return;
    // A summary: the toroidal minimum distance is what survives tiling.
    nlohmann::ordered_json out;
    out["file"] = opt->output;
    out["method"] = opt->method;
    out["count"] = points.size();
    visit_dim(points.dim, [&](auto d) {
      constexpr int D = decltype(d)::value;
      const MinDistance m = min_distance(points.as<D>(), Domain<D>::unit(true));
      out["torus_min_distance"] = std::isfinite(m.distance) ? nlohmann::ordered_json(m.distance) : nullptr;
      out["relative_radius"] = relative_radius(m.distance, 1.0, points.size(), D);
      return 0;
    });
    std::cout << out.dump(2) << std::endl;
  });
}

}  // namespace pds::cli
