// Reader of chunked point sets (pds/io/chunks.h).

#include "pds/io/chunks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <istream>
#include <nlohmann/json.hpp>
#include <type_traits>

#include "pds/error.h"
#include "pds/io/point_file.h"

namespace pds {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& name, const std::string& what) {
  throw InvalidArgument(name + ": " + what);
}

const json& member(const json& object, const char* key, const std::string& where, const std::string& name) {
  const auto it = object.find(key);
  if (it == object.end()) fail(name, where + " has no '" + key + "'");
  return *it;
}

std::uint64_t count_of(const json& value, const std::string& what, const std::string& name) {
  if (!value.is_number_unsigned()) fail(name, what + " is not a non-negative integer");
  return value.get<std::uint64_t>();
}

std::vector<double> corner(const json& value, int dim, const std::string& what, const std::string& name) {
  if (!value.is_array() || value.size() != static_cast<std::size_t>(dim))
    fail(name, what + " is not a list of " + std::to_string(dim) + " numbers");
  std::vector<double> out;
  for (const json& v : value) {
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(name, what + " holds a value that is not a finite number");
    out.push_back(v.get<double>());
  }
  return out;
}

void box(const json& object, int dim, const std::string& what, const std::string& name, std::vector<double>& lo,
         std::vector<double>& hi) {
  if (!object.is_object()) fail(name, what + " is not an object with 'lo' and 'hi'");
  lo = corner(member(object, "lo", what, name), dim, what + ".lo", name);
  hi = corner(member(object, "hi", what, name), dim, what + ".hi", name);
  for (int a = 0; a < dim; ++a)
    if (!(lo[static_cast<std::size_t>(a)] < hi[static_cast<std::size_t>(a)]))
      fail(name, what + " is empty along axis " + std::to_string(a));
}

}  // namespace

ChunkManifest parse_chunk_manifest(std::istream& in, const std::string& name) {
  json j;
  try {
    j = json::parse(in);
  } catch (const json::exception& e) {
    fail(name, std::string("not valid JSON (") + e.what() + ")");
  }
  if (!j.is_object()) fail(name, "not a JSON object");
  const auto format = j.find("format");
  if (format == j.end() || !format->is_string() || format->get<std::string>() != "pds-chunks")
    fail(name, "not a chunk manifest (its 'format' is not \"pds-chunks\")");
  const json& version = member(j, "version", "the manifest", name);
  if (!version.is_number_integer() || version.get<std::int64_t>() != 1)
    fail(name, "manifest version " + version.dump() + " is not supported (1 is)");
  ChunkManifest m;
  const json& dim = member(j, "dim", "the manifest", name);
  if (!dim.is_number_integer() || dim.get<std::int64_t>() < 2 || dim.get<std::int64_t>() > 3)
    fail(name, "'dim' is not 2 or 3");
  m.dim = static_cast<int>(dim.get<std::int64_t>());
  const json& radius = member(j, "radius", "the manifest", name);
  if (!radius.is_number() || !(radius.get<double>() > 0.0) || !std::isfinite(radius.get<double>()))
    fail(name, "'radius' is not a positive finite number");
  m.radius = radius.get<double>();
  m.seed = count_of(member(j, "seed", "the manifest", name), "'seed'", name);
  box(member(j, "region", "the manifest", name), m.dim, "'region'", name, m.lo, m.hi);
  const auto torus = j.find("torus");
  if (torus != j.end() && !torus->is_null()) box(*torus, m.dim, "'torus'", name, m.torus_lo, m.torus_hi);
  m.count = count_of(member(j, "count", "the manifest", name), "'count'", name);
  const json& chunks = member(j, "chunks", "the manifest", name);
  if (!chunks.is_array()) fail(name, "'chunks' is not a list");
  std::uint64_t total = 0;
  for (std::size_t k = 0; k < chunks.size(); ++k) {
    const std::string what = "chunk " + std::to_string(k);
    const json& c = chunks[k];
    if (!c.is_object()) fail(name, what + " is not an object");
    ChunkManifest::Chunk chunk;
    const json& file = member(c, "file", what, name);
    if (!file.is_string()) fail(name, what + ": 'file' is not a string");
    chunk.file = file.get<std::string>();
    if (chunk.file.empty() || chunk.file == "." || chunk.file == ".." ||
        chunk.file.find_first_of("/\\") != std::string::npos || chunk.file.find('\0') != std::string::npos)
      fail(name, what + ": 'file' is not a plain file name in the manifest's directory");
    chunk.lo = corner(member(c, "lo", what, name), m.dim, what + ".lo", name);
    chunk.hi = corner(member(c, "hi", what, name), m.dim, what + ".hi", name);
    chunk.count = count_of(member(c, "count", what, name), what + ": 'count'", name);
    if (chunk.count > m.count - std::min(total, m.count)) fail(name, "the chunks' counts exceed 'count'");
    total += chunk.count;
    m.chunks.push_back(std::move(chunk));
  }
  if (total != m.count)
    fail(name, "the chunks' counts add up to " + std::to_string(total) + ", not 'count' " + std::to_string(m.count));
  return m;
}

ChunkManifest for_each_chunk(const std::string& path,
                             const std::function<void(const ChunkManifest::Chunk&, const PointCloud&)>& f) {
  std::ifstream in(path);
  if (!in) throw InvalidArgument(path + ": cannot open");
  const ChunkManifest m = parse_chunk_manifest(in, path);
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  for (const ChunkManifest::Chunk& chunk : m.chunks) {
    const std::string file = (dir / chunk.file).string();
    const PointCloud points = read_points(file);
    if (points.dim != m.dim)
      throw InvalidArgument(file + ": has dimension " + std::to_string(points.dim) + ", the manifest says " +
                            std::to_string(m.dim));
    if (points.size() != chunk.count)
      throw InvalidArgument(file + ": holds " + std::to_string(points.size()) + " points, the manifest says " +
                            std::to_string(chunk.count));
    for (std::size_t i = 0; i < points.size(); ++i)
      for (int a = 0; a < m.dim; ++a) {
        const double x = points.coords[i * static_cast<std::size_t>(m.dim) + static_cast<std::size_t>(a)];
        if (!(x >= chunk.lo[static_cast<std::size_t>(a)] && x < chunk.hi[static_cast<std::size_t>(a)]))
          throw InvalidArgument(file + ": point " + std::to_string(i) + " lies outside its chunk's box");
      }
    f(chunk, points);
  }
  return m;
}

PointCloud read_chunks(const std::string& path, ChunkManifest* manifest) {
  PointCloud all;
  const ChunkManifest m = for_each_chunk(path, [&](const ChunkManifest::Chunk&, const PointCloud& points) {
    all.coords.insert(all.coords.end(), points.coords.begin(), points.coords.end());
  });
  all.dim = m.dim;
  // The canonical order: the bytes of the region sampled whole.
  const auto sorted = [&](auto d) {
    constexpr int D = decltype(d)::value;
    PointSet<D> points = all.as<D>();
    std::sort(points.begin(), points.end(), [](const Point<D>& a, const Point<D>& b) {
      return static_cast<const std::array<double, D>&>(a) < static_cast<const std::array<double, D>&>(b);
    });
    return PointCloud::from(points);
  };
  all = m.dim == 2 ? sorted(std::integral_constant<int, 2>{}) : sorted(std::integral_constant<int, 3>{});
  if (manifest) *manifest = m;
  return all;
}

}  // namespace pds
