// GeoJSON polygons (include/pds/io/geojson.h), parsed with nlohmann_json.

#include "pds/io/geojson.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "pds/error.h"

namespace pds {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& name, const std::string& what) { throw InvalidArgument(name + ": " + what); }

Ring read_ring(const json& j, const std::string& name) {
  if (!j.is_array()) fail(name, "a ring is not an array of positions");
  Ring ring;
  for (const json& position : j) {
    if (!position.is_array() || position.size() < 2 || !position[0].is_number() || !position[1].is_number())
      fail(name, "a position is not an array of at least two numbers: " + position.dump().substr(0, 60));
    ring.push_back(Point<2>{{position[0].get<double>(), position[1].get<double>()}});
  }
  return ring;
}

Polygon read_polygon(const json& j, const std::string& name) {
  if (!j.is_array() || j.empty()) fail(name, "a polygon's coordinates are not a non-empty array of rings");
  Polygon polygon{read_ring(j[0], name), {}};
  for (std::size_t i = 1; i < j.size(); ++i) polygon.holes.push_back(read_ring(j[i], name));
  return polygon;
}

void read_object(const json& j, const std::string& name, Region& region, int depth) {
  if (depth > 16) fail(name, "collections nested too deeply");
  if (!j.is_object() || !j.contains("type") || !j["type"].is_string())
    fail(name, "expected a GeoJSON object with a \"type\"");
  const std::string type = j["type"].get<std::string>();
  const auto member = [&](const char* key) -> const json& {
    if (!j.contains(key)) fail(name, type + " without \"" + key + "\"");
    return j[key];
  };
  if (type == "Polygon") {
    region.polygons.push_back(read_polygon(member("coordinates"), name));
  } else if (type == "MultiPolygon") {
    const json& polygons = member("coordinates");
    if (!polygons.is_array()) fail(name, "MultiPolygon coordinates are not an array");
    for (const json& p : polygons) region.polygons.push_back(read_polygon(p, name));
  } else if (type == "Feature") {
    read_object(member("geometry"), name, region, depth + 1);
  } else if (type == "FeatureCollection" || type == "GeometryCollection") {
    const json& items = member(type == "FeatureCollection" ? "features" : "geometries");
    if (!items.is_array()) fail(name, type + " members are not an array");
    for (const json& item : items) read_object(item, name, region, depth + 1);
  } else {
    fail(name, "geometry type \"" + type + "\" is not a Polygon or MultiPolygon");
  }
}

}  // namespace

Region read_geojson(std::istream& in, const std::string& name) {
  // No exceptions from the parser: a discarded value says the text is not JSON.
  const json j = json::parse(in, nullptr, false);
  if (j.is_discarded()) fail(name, "not valid JSON");
  Region region;
  read_object(j, name, region, 0);
  region.validate(name);
  return region;
}

Region read_geojson(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidArgument("cannot open " + path);
  return read_geojson(in, path);
}

}  // namespace pds
