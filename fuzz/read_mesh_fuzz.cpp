// libFuzzer target: the mesh reader (pds generate --mesh), CGAL's OBJ, PLY
// and OFF parsers behind pds::read_mesh. The first byte picks the format,
// the rest is the file. Any bytes either give a valid mesh (a triangle,
// every index in range, finite coordinates, positive area) or raise
// InvalidArgument; a valid mesh then samples without error.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "pds/error.h"
#include "pds/io/mesh_file.h"
#include "pds/samplers/surface.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const pds::MeshFormat format = data[0] % 3 == 0 ? pds::MeshFormat::Obj
                                 : data[0] % 3 == 1 ? pds::MeshFormat::Ply
                                                    : pds::MeshFormat::Off;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data) + 1, size - 1), std::ios::binary);
  pds::TriangleMesh mesh;
  try {
    mesh = pds::read_mesh(in, format, "fuzz");
  } catch (const pds::InvalidArgument&) {
    return 0;
  }
  if (mesh.triangles.empty()) std::abort();
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t)
      if (v >= mesh.vertices.size()) std::abort();
  for (const auto& v : mesh.vertices)
    for (double x : v)
      if (!std::isfinite(x)) std::abort();
  if (!(pds::surface_area(mesh) > 0)) std::abort();
  const pds::SurfaceSamples s = pds::sample_surface(mesh, {.count = 8}, 1);
  if (s.size() != 8) std::abort();
  return 0;
}
