// Mesh files through CGAL's polygon-soup readers: CGAL is already a
// dependency of pds (the cgal component), header-only, and reads the three
// formats asked for (OBJ, PLY ASCII and binary, OFF) with one interface.
// tinyobjloader reads OBJ alone; assimp reads all three but is a large
// library with many formats and dependencies that pds would not use.

#include "pds/io/mesh_file.h"

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <sstream>
#include <vector>

#include "pds/error.h"

namespace pds {
namespace {

using CgalPoint = CGAL::Simple_cartesian<double>::Point_3;

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

const char* format_name(MeshFormat format) {
  switch (format) {
    case MeshFormat::Obj:
      return "OBJ";
    case MeshFormat::Ply:
      return "PLY";
    case MeshFormat::Off:
      return "OFF";
  }
  return "?";
}

// CGAL's OFF reader reserves memory for the counts its header declares
// (3 * 10^8 vertices took 7 GB before reading one): the counts are checked
// against the bytes the stream holds first (every vertex and face takes at
// least 2 bytes in any OFF form). The stream is left where it was.
void check_off_counts(std::istream& in, const std::string& name) {
  const std::streampos start = in.tellg();
  if (start < 0) return;  // not seekable: nothing to measure against
  in.seekg(0, std::ios::end);
  const std::streamoff bytes = in.tellg() - start;
  in.seekg(start);
  std::vector<std::string> tokens;
  std::string line;
  for (int lines = 0; lines < 64 && tokens.size() < 4 && std::getline(in, line); ++lines) {
    const std::size_t hash = line.find('#');
    std::istringstream words(line.substr(0, hash));
    for (std::string w; tokens.size() < 4 && words >> w;) tokens.push_back(w);
  }
  in.clear();
  in.seekg(start);
  // The keyword (OFF, COFF, NOFF, ...) may be followed on its line by the counts.
  if (tokens.size() < 3 || tokens[0].find("OFF") == std::string::npos) return;
  for (std::size_t k = 1; k < 3; ++k) {
    char* end = nullptr;
    const double count = std::strtod(tokens[k].c_str(), &end);
    if (end != tokens[k].c_str() + tokens[k].size()) return;  // not counts: CGAL decides
    if (count > static_cast<double>(bytes) / 2.0)
      throw InvalidArgument(name + ": the OFF header declares " + tokens[k] + (k == 1 ? " vertices" : " faces") +
                            " in a file of " + std::to_string(bytes) + " bytes");
  }
}

}  // namespace

TriangleMesh read_mesh(std::istream& in, MeshFormat format, const std::string& name) {
  if (format == MeshFormat::Off) check_off_counts(in, name);
  std::vector<CgalPoint> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool ok = false;
  try {
    switch (format) {
      case MeshFormat::Obj:
        ok = CGAL::IO::read_OBJ(in, points, polygons, CGAL::parameters::verbose(false));
        break;
      case MeshFormat::Ply:
        ok = CGAL::IO::read_PLY(in, points, polygons, CGAL::parameters::verbose(false));
        break;
      case MeshFormat::Off:
        ok = CGAL::IO::read_OFF(in, points, polygons, CGAL::parameters::verbose(false));
        break;
    }
  } catch (const std::bad_alloc&) {
    throw InvalidArgument(name + ": not a readable " + format_name(format) + " mesh (it asks for too much memory)");
  } catch (const std::exception& e) {
    throw InvalidArgument(name + ": not a readable " + format_name(format) + " mesh (" + e.what() + ")");
  }
  if (!ok) throw InvalidArgument(name + ": not a readable " + format_name(format) + " mesh");
  TriangleMesh mesh;
  mesh.vertices.reserve(points.size());
  for (const CgalPoint& p : points) mesh.vertices.push_back({{p.x(), p.y(), p.z()}});
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    const std::vector<std::size_t>& face = polygons[k];
    if (face.size() < 3)
      throw InvalidArgument(name + ": face " + std::to_string(k) + " has " + std::to_string(face.size()) +
                            " vertices (at least 3)");
    for (std::size_t v : face)
      if (v >= points.size())
        throw InvalidArgument(name + ": face " + std::to_string(k) + " names a vertex out of range (there are " +
                              std::to_string(points.size()) + ")");
    for (std::size_t j = 1; j + 1 < face.size(); ++j)
      mesh.triangles.push_back({static_cast<std::uint32_t>(face[0]), static_cast<std::uint32_t>(face[j]),
                                static_cast<std::uint32_t>(face[j + 1])});
  }
  try {
    validate_mesh(mesh);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(name + ": " + e.what());
  }
  return mesh;
}

TriangleMesh read_mesh(const std::string& path) {
  const std::string ext = extension_of(path);
  MeshFormat format;
  if (ext == ".obj")
    format = MeshFormat::Obj;
  else if (ext == ".ply")
    format = MeshFormat::Ply;
  else if (ext == ".off")
    format = MeshFormat::Off;
  else
    throw InvalidArgument(path + ": unknown mesh file extension '" + ext + "' (use .obj, .ply or .off)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidArgument(path + ": cannot open: " + std::strerror(errno));
  return read_mesh(in, format, path);
}

}  // namespace pds
