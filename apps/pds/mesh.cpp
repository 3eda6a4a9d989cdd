// pds generate elimination --mesh FILE (--count N | --radius R): Poisson disk
// samples on a triangle mesh (docs/surface.md).

#include "mesh.h"

#include <iostream>

#include "pds/error.h"
#include "pds/io/mesh_file.h"
#include "pds/io/point_file.h"
#include "pds/limits.h"
#include "pds/registry.h"
#include "pds/samplers/surface.h"
#include "terminal.h"

namespace pds::cli {

void add_mesh_options(CLI::App& command, MeshOptions& o) {
  command.add_option("--mesh", o.mesh,
                     "Sample the surface of a triangle mesh (.obj, .ply, .off) in 3D (elimination only); writes "
                     "x,y,z,nx,ny,nz,face (.ply, .csv or .npy)");
  command.add_option("--vertex-density", o.vertex_density,
                     "With --mesh: CSV/NPY of one column, a density a vertex (spacing ~ density^-1/2)");
}

void generate_on_mesh(const CLI::App& command, const std::string& method, const MeshOptions& o,
                      const GenerationOptions& generation, const std::string& output) {
  if (method != "elimination")
    throw InvalidArgument("--mesh is taken by elimination only (weighted sample elimination on the surface), not " +
                          method);
  refuse_options(command,
                 {"--dim", "--torus", "--bounds", "--density", "--radius-range", "--invert", "--mask", "--polygons",
                  "--fixed", "--dtype", "--max-memory"},
                 "--mesh (the mesh is the domain)");
  const bool by_count = generation.count_option && generation.count_option->count();
  const bool by_radius = generation.radius_option && generation.radius_option->count();
  if (by_count == by_radius) throw InvalidArgument("--mesh needs exactly one of --count and --radius");
  const Method& m = find_method(method);
  const std::map<std::string, double> params = parse_params(generation.params);
  validate_params(m, params);
  auto param = [&](const char* name, double fallback) {
    const auto it = params.find(name);
    return it == params.end() ? fallback : it->second;
  };

  const TriangleMesh mesh = read_mesh(o.mesh);
  SurfaceParams sp;
  if (!o.vertex_density.empty()) {
    const PointCloud density = read_points(o.vertex_density);
    if (density.dim != 1)
      throw InvalidArgument(o.vertex_density + ": --vertex-density needs one column, got " +
                            std::to_string(density.dim));
    sp.vertex_density = density.coords;
  }
  // On a surface every sample stays one of the candidates.
  if (params.count("min_rho"))
    throw InvalidArgument("--mesh does not take min_rho: on a surface each sample is one of the candidates");
  if (params.count("levels"))
    throw InvalidArgument("--mesh does not take levels: on a surface the order is the paper's halvings");
  sp.count = by_count ? generation.count : surface_count_for_radius(surface_area(mesh), generation.radius);
  sp.candidates = param("candidates", 5);
  // Off by default on a surface: it doubles the time, and a mesh's samples
  // are seldom taken by prefix.
  sp.progressive = param("progressive", 0) != 0;
  sp.weights.alpha = param("alpha", 8);
  sp.weights.beta = param("beta", 0.65);
  sp.weights.gamma = param("gamma", 1.5);
  require_count(sp.count, generation.max_points);
  // The candidates take the memory: a position, a face and an index each,
  // and elimination's copies.
  require_point_budget(std::ceil(sp.candidates * static_cast<double>(sp.count)), 3,
                       std::numeric_limits<std::uint64_t>::max(), "elimination's candidates on the mesh");

  SurfaceSamples samples;
  {
    const ProgressBar bar(method, generation.quiet);
    sp.progress = bar.progress();
    samples = sample_surface(mesh, sp, generation.seed);
  }
  PointCloud table{7, {}};
  table.coords.reserve(samples.size() * 7);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    table.coords.insert(table.coords.end(), samples.positions[i].begin(), samples.positions[i].end());
    table.coords.insert(table.coords.end(), samples.normals[i].begin(), samples.normals[i].end());
    table.coords.push_back(samples.faces[i]);
  }
  write_output(output, table, {{"x"}, {"y"}, {"z"}, {"nx"}, {"ny"}, {"nz"}, {"face", true}});
}

}  // namespace pds::cli
