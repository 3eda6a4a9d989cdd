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
  GenerationOptions generation;  // on the unit torus, so no domain options
  std::string output;
};

}  // namespace

void add_tile(CLI::App& app) {
  auto opt = std::make_shared<TileOptions>();
  CLI::App* cmd = app.add_subcommand(
      "tile", "Generate a tileable pattern: METHOD run on the unit torus, so its minimum distance holds across seams");
  cmd->footer(methods_help());
  cmd->add_option("method", opt->method, "Sampling method (see the list below)")->required();
  add_generation_options(*cmd, opt->generation, {.domain = false});
  cmd->add_option("--output,-o", opt->output, "Output file (.npy or .csv); '-' for CSV on stdout")->required();
  cmd->callback([opt] {
    GenerateRequest request = generation_request(opt->generation, {.domain = false});
    request.torus = true;
    // Sized as the tiled render samplers size their tiles (pds::generate_tile),
    // so `pds render --tile` of this file and `pds render --sampler METHOD`
    // with the same count and seed draw the same samples.
    const PointCloud points =
        generate_with_progress(opt->method, size_request(find_method(opt->method), request), opt->generation.quiet);
    write_output(opt->output, points);
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
