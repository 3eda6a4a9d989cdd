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
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <iterator>
#include <set>
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

// CGAL's OFF reader trusts its input more than a reader of arbitrary files
// may (each found by the fuzz target, read_mesh_fuzz.cpp): it reserves
// memory for the counts the header declares (3 x 10^8 vertices took 7 GB
// before reading one); casts each face index, read as a double, to an
// unsigned integer however large or negative it is; doubles the edge count
// in an int; reads texture and colour entries past the end of a short vertex
// line; casts colours to bytes unchecked; and takes the character after the
// keyword for a separator ("OFF#BINARY" is binary to it, "OFF#0 20 0" has
// 20 faces). pds uses positions and faces only, so the file is read here
// line by line ('#' starts a comment; the keyword is [ST][C][N]OFF, binary
// OFF refused), every count checked against the file's size, every face
// index checked to be an integer in [0, vertices), and CGAL is handed a
// plain OFF of the first three numbers of each vertex line and the index
// list of each face line: the variants' normals, colours and textures are
// dropped before they reach it.
std::string plain_off(std::istream& in, const std::string& name) {
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::istringstream lines(text);
  auto fail = [&](const std::string& what) { throw InvalidArgument(name + ": " + what); };
  auto integer = [](const std::string& t, long long& value) {
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    return ec == std::errc() && end == t.data() + t.size();
  };
  // The meaningful lines, split into tokens, one at a time.
  std::string line;
  auto next_line = [&](std::vector<std::string>& tokens) {
    tokens.clear();
    while (tokens.empty() && std::getline(lines, line)) {
      std::istringstream words(line.substr(0, line.find('#')));
      for (std::string w; words >> w;) tokens.push_back(w);
    }
    return !tokens.empty();
  };
  std::vector<std::string> header, tokens;
  if (!next_line(header)) fail("empty OFF file");
  const std::string keyword = header[0];
  const std::size_t off = keyword.rfind("OFF");
  if (off == std::string::npos || off + 3 != keyword.size())
    fail("the OFF file starts with '" + keyword + "', not an OFF keyword");
  for (std::size_t i = 0; i < off; ++i)
    if (std::string("STCN").find(keyword[i]) == std::string::npos)
      fail("the OFF variant " + keyword + " is not read (OFF, COFF, NOFF, STOFF and their combinations are)");
  const std::size_t after = line.find_first_not_of(" \t\r\v\f") + keyword.size();
  if (after < line.size() && line[after] == '#')
    fail("the OFF keyword " + keyword + " is followed by '#'; put a space between them");
  header.erase(header.begin());
  while (header.size() < 3 && next_line(tokens)) header.insert(header.end(), tokens.begin(), tokens.end());
  for (const std::string& t : header)
    if (t.rfind("BINARY", 0) == 0) fail("binary OFF is not read (use ASCII OFF, PLY or OBJ)");
  if (header.size() > 3) fail("the OFF counts' line holds more than the three counts");
  long long counts[2];
  for (int k = 0; k < 2; ++k) {
    if (header.size() < 3 || !integer(header[static_cast<std::size_t>(k)], counts[k]) || counts[k] < 0)
      fail("the OFF header needs the counts of vertices, faces and edges");
    if (static_cast<double>(counts[k]) > static_cast<double>(text.size()) / 2.0)
      fail("the OFF header declares " + header[static_cast<std::size_t>(k)] + (k == 0 ? " vertices" : " faces") +
           " in a file of " + std::to_string(text.size()) + " bytes");
  }
  long long edges = 0;  // unused, but must be a count
  if (!integer(header[2], edges) || edges < 0)
    fail("the OFF header's edge count '" + header[2] + "' is not a non-negative integer");
  std::string plain = "OFF\n" + std::to_string(counts[0]) + " " + std::to_string(counts[1]) + " 0\n";
  plain.reserve(text.size());
  for (long long v = 0; v < counts[0]; ++v) {
    if (!next_line(tokens))
      fail("the OFF file ends after " + std::to_string(v) + " of its " + std::to_string(counts[0]) + " vertices");
    if (tokens.size() < 3) fail("OFF vertex " + std::to_string(v) + " has fewer than three coordinates");
    plain += tokens[0] + " " + tokens[1] + " " + tokens[2] + "\n";
  }
  for (long long f = 0; f < counts[1]; ++f) {
    if (!next_line(tokens))
      fail("the OFF file ends after " + std::to_string(f) + " of its " + std::to_string(counts[1]) + " faces");
    long long size = 0;
    if (!integer(tokens[0], size) || size < 1 || static_cast<std::size_t>(size) >= tokens.size())
      fail("OFF face " + std::to_string(f) + " does not start with its number of vertices and list them");
    plain += tokens[0];
    for (long long i = 1; i <= size; ++i) {
      long long index = 0;
      if (!integer(tokens[static_cast<std::size_t>(i)], index) || index < 0 || index >= counts[0])
        fail("OFF face " + std::to_string(f) + " names vertex '" + tokens[static_cast<std::size_t>(i)] +
             "'; there are " + std::to_string(counts[0]));
      plain += " " + tokens[static_cast<std::size_t>(i)];
    }
    plain += "\n";
  }
  return plain;
}

// CGAL's PLY reader trusts the header more than a reader of arbitrary files
// may (each found by the fuzz target, read_mesh_fuzz.cpp): a `property`
// before any `element` is read into an element that is not there; a vertex
// coordinate of an integer type, or a `halfedge` element's index of a
// floating type, is read through a null pointer; and it loops over an
// element's declared count whatever the file holds (a negative count wraps
// around to 2^64 - n). So the header is
// checked here first: properties follow an element, x, y and z of the
// vertices are float or double, no halfedge element, no count above the
// stream's bytes, list counts of 8 or 16 bits. The stream is left where it was.
void check_ply_header(std::istream& in, const std::string& name) {
  const std::streampos start = in.tellg();
  if (start < 0) return;  // not seekable: nothing to measure against
  in.seekg(0, std::ios::end);
  const std::streamoff bytes = in.tellg() - start;
  in.seekg(start);
  auto fail = [&](const std::string& what) {
    in.clear();
    in.seekg(start);
    throw InvalidArgument(name + ": " + what);
  };
  std::string element;  // the element being declared; empty before the first
  std::string line;
  // Lines counted as CGAL counts them: the first must be "ply", the second
  // is taken for the format line whatever it says ("end_header ascii 0"
  // there does not end the header), an empty line after them is an error.
  for (long long number = 1;; ++number) {
    if (!std::getline(in, line)) break;
    if (number > 100000) fail("the PLY header is longer than 100,000 lines");
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword) && number != 2) fail("line " + std::to_string(number) + " of the PLY header is empty");
    if (number == 1) {
      if (keyword != "ply") fail("not a PLY file (the first line is not 'ply')");
      continue;
    }
    if (number == 2) continue;
    if (keyword == "end_header") break;
    if (keyword == "property") {
      if (element.empty()) fail("a PLY property is declared before any element");
      std::string type, property;
      words >> type >> property;
      if (type == "list") {  // list COUNT_TYPE ITEM_TYPE NAME
        const std::string size_type = property;
        std::string item;
        words >> item >> property;
        // CGAL sizes each list by the count it reads, before reading the
        // items: a 32-bit count can ask for gigabytes. 8- and 16-bit counts
        // (uchar, as every common exporter writes) bound a list to 65,535.
        static const std::set<std::string> kSmall = {"char",  "uchar",  "int8",  "uint8",
                                                     "short", "ushort", "int16", "uint16"};
        if (!kSmall.count(size_type))
          fail("the PLY list " + property + " has " + size_type +
               " counts; 8- or 16-bit counts (such as uchar) are read");
      }
      if ((element == "vertex" || element == "vertices") && (property == "x" || property == "y" || property == "z") &&
          type != "float" && type != "float32" && type != "double" && type != "float64")
        fail("the PLY vertex coordinate " + property + " has type " + type + " (float or double are read)");
    }
    if (keyword == "element") {
      std::string count;
      words >> element >> count;
      if (element.empty()) element = "?";
      if (element == "halfedge") fail("PLY halfedge elements are not read");
      unsigned long long n = 0;
      const auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), n);
      if (ec != std::errc() || end != count.data() + count.size())
        fail("the PLY element " + element + " has count '" + count + "', not a non-negative integer");
      if (static_cast<double>(n) > static_cast<double>(bytes))
        fail("the PLY header declares " + count + " " + element + " elements in a file of " + std::to_string(bytes) +
             " bytes");
    }
  }
  in.clear();
  in.seekg(start);
}

}  // namespace

TriangleMesh read_mesh(std::istream& in, MeshFormat format, const std::string& name) {
  if (format == MeshFormat::Ply) check_ply_header(in, name);
  std::istringstream plain;
  if (format == MeshFormat::Off) plain.str(plain_off(in, name));
  std::istream& source = format == MeshFormat::Off ? plain : in;
  std::vector<CgalPoint> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool ok = false;
  try {
    switch (format) {
      case MeshFormat::Obj:
        ok = CGAL::IO::read_OBJ(source, points, polygons, CGAL::parameters::verbose(false));
        break;
      case MeshFormat::Ply:
        ok = CGAL::IO::read_PLY(source, points, polygons, CGAL::parameters::verbose(false));
        break;
      case MeshFormat::Off:
        ok = CGAL::IO::read_OFF(source, points, polygons, CGAL::parameters::verbose(false));
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
