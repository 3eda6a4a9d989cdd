// pds generate METHOD ...: run a registered method and write the points.

#include <iostream>
#include <memory>

#include "analysis_common.h"
#include "classes.h"
#include "commands.h"
#include "constraints.h"
#include "mesh.h"
#include "pds/error.h"
#include "pds/io/point_file.h"
#include "pds/registry.h"
#include "unbounded.h"

namespace pds::cli {
namespace {

struct GenerateOptions {
  std::string method;
  GenerationOptions generation;
  std::string output = "-";
  std::string dtype = "float64";
  ConstraintOptions constraints;
  MeshOptions mesh;
  ClassOptions classes;
  UnboundedGenerateOptions unbounded;
};

}  // namespace

void add_generate(CLI::App& app) {
  auto opt = std::make_shared<GenerateOptions>();
  CLI::App* cmd = app.add_subcommand("generate", "Generate a point set with a registered method");
  cmd->footer(methods_help());
  cmd->add_option("method", opt->method, "Sampling method (see the list below)")->required();
  add_generation_options(*cmd, opt->generation);
  cmd->add_option("--output,-o", opt->output, "Output file (.csv, .npy or .ply); '-' for CSV on stdout")
      ->capture_default_str();
  cmd->add_option("--dtype", opt->dtype,
                  "Coordinates as float64 or float32 (.npy stores that type); float32 keeps --radius and the "
                  "bounds after rounding")
      ->check(CLI::IsMember({"float64", "float32"}))
      ->capture_default_str();
  add_constraint_options(*cmd, opt->constraints);
  add_mesh_options(*cmd, opt->mesh);
  add_class_options(*cmd, opt->classes);
  add_unbounded_generate_options(*cmd, opt->unbounded);

  cmd->callback([opt, cmd] {
    if (unbounded_requested(opt->unbounded)) {
      generate_unbounded(*cmd, opt->method, opt->unbounded, opt->generation, opt->output);
      return;
    }
    if (classes_requested(opt->classes)) {
      generate_classes(*cmd, opt->method, opt->classes, opt->generation, opt->output);
      return;
    }
    if (!opt->classes.matrix.empty()) throw InvalidArgument("--class-matrix needs --classes");
    if (mesh_requested(opt->mesh)) {
      generate_on_mesh(*cmd, opt->method, opt->mesh, opt->generation, opt->output);
      return;
    }
    if (!opt->mesh.vertex_density.empty()) throw InvalidArgument("--vertex-density needs --mesh");
    GenerateRequest request = generation_request(opt->generation);
    apply_constraint_options(opt->constraints, request);
    request.float32 = opt->dtype == "float32";
    const PointCloud points = generate_with_progress(opt->method, request, opt->generation.quiet);
    write_output(opt->output, points, opt->dtype == "float32" ? NpyType::Float32 : NpyType::Float64);
    if (const std::size_t fixed = request.constraints.fixed.size(); fixed && !opt->generation.quiet)
      std::cerr << "pds: the first " << fixed << " of " << points.size() << " points are the fixed ones of "
                << opt->constraints.fixed << "\n";
  });
}

}  // namespace pds::cli
