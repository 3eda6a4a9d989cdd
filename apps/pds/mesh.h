#pragma once
// pds generate METHOD --mesh FILE: samples on a triangle mesh's surface
// (docs/surface.md).

#include <CLI/CLI.hpp>
#include <string>

#include "analysis_common.h"

namespace pds::cli {

struct MeshOptions {
  std::string mesh;            // .obj, .ply, .off
  std::string vertex_density;  // CSV/NPY, one value a vertex
};

void add_mesh_options(CLI::App& command, MeshOptions& options);

/// Whether --mesh was given.
inline bool mesh_requested(const MeshOptions& options) { return !options.mesh.empty(); }

/// Reads the mesh, samples it with `method` (elimination only) as the
/// generation options say, and writes x,y,z,nx,ny,nz,face to `output`.
/// `command` is asked which options were given: those that do not apply to a
/// surface (--dim, --torus, --bounds, the constraints, float32) are refused.
void generate_on_mesh(const CLI::App& command, const std::string& method, const MeshOptions& options,
                      const GenerationOptions& generation, const std::string& output);

}  // namespace pds::cli
