#pragma once
// Polygons with holes from GeoJSON (RFC 7946), the mask format of
// `pds generate --polygons FILE` (docs/density.md): a Polygon or
// MultiPolygon geometry, a Feature holding one, or a FeatureCollection or
// GeometryCollection of them (other geometry types are an error, not
// skipped). Each polygon is [outer ring, hole rings...], each ring a list of
// [x, y] positions (a third coordinate, an altitude, is ignored); the
// plane's own coordinates are read as they are, with no map projection.
// Errors name the file and what is wrong (InvalidArgument).

#include <iosfwd>
#include <string>

#include "pds/polygon.h"

namespace pds {

Region read_geojson(std::istream& in, const std::string& name);
Region read_geojson(const std::string& path);

}  // namespace pds
