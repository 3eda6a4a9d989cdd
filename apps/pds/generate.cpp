// pds generate METHOD ...: run a registered method and write the points.

#include <memory>

#include "analysis_common.h"
#include "commands.h"
#include "pds/error.h"
#include "pds/io/point_file.h"
#include "pds/registry.h"

namespace pds::cli {
namespace {

struct GenerateOptions {
  std::string method;
  DomainOptions domain;
  std::uint64_t count = 0;
  double radius = 0;
  std::uint64_t seed = 0;
  int threads = 0;
  std::uint64_t max_points = kDefaultMaxPoints;
  std::vector<std::string> params;
  std::string output = "-";
  std::string dtype = "float64";
};

}  // namespace

void add_generate(CLI::App& app) {
  auto opt = std::make_shared<GenerateOptions>();
  CLI::App* cmd = app.add_subcommand("generate", "Generate a point set with a registered method");
  cmd->footer(methods_help());
  cmd->add_option("method", opt->method, "Sampling method (see the list below)")->required();
  auto* count = cmd->add_option("--count,-n", opt->count, "Number of points");
  auto* radius = cmd->add_option("--radius,-r", opt->radius, "Minimum distance between any two samples");
  add_domain_options(*cmd, opt->domain);
  cmd->add_option("--seed,-s", opt->seed, "Random seed; the same seed gives the same bytes")->capture_default_str();
  cmd->add_option("--threads,-t", opt->threads, "Threads for parallel methods (0: all cores)")->capture_default_str();
  cmd->add_option("--max-points", opt->max_points, "Refuse requests that could produce more points")
      ->capture_default_str();
  cmd->add_option("--param,-P", opt->params, "Method parameter NAME=VALUE (repeatable)");
  cmd->add_option("--output,-o", opt->output, "Output file (.csv or .npy); '-' for CSV on stdout")
      ->capture_default_str();
  cmd->add_option("--dtype", opt->dtype, "Element type of .npy output")
      ->check(CLI::IsMember({"float64", "float32"}))
      ->capture_default_str();

  cmd->callback([opt, count, radius] {
    GenerateRequest request;
    request.dim = opt->domain.dim;
    request.torus = opt->domain.torus;
    split_bounds(opt->domain, request.dim, request.lo, request.hi);
    if (count->count()) request.count = opt->count;
    if (radius->count()) request.radius = opt->radius;
    request.seed = opt->seed;
    request.threads = opt->threads;
    request.max_points = opt->max_points;
    request.params = parse_params(opt->params);
    const PointCloud points = generate(opt->method, request);
    write_points(opt->output, points, opt->dtype == "float32" ? NpyType::Float32 : NpyType::Float64);
  });
}

}  // namespace pds::cli
