// libFuzzer target: the GeoJSON polygon reader (pds --polygons). Any bytes
// either give a valid region (at least one polygon, every ring of 3 or more
// finite vertices) or raise InvalidArgument; point tests on what parses
// must not crash.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "pds/error.h"
#include "pds/io/geojson.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  pds::Region region;
  try {
    region = pds::read_geojson(in, "fuzz.geojson");
  } catch (const pds::InvalidArgument&) {
    return 0;
  }
  if (region.polygons.empty()) std::abort();
  for (const pds::Polygon& p : region.polygons) {
    if (p.outer.size() < 3) std::abort();
    for (const auto& v : p.outer)
      if (!std::isfinite(v[0]) || !std::isfinite(v[1])) std::abort();
    (void)region.contains(p.outer[0]);
  }
  (void)region.contains(pds::Point<2>{{0.5, 0.5}});
  return 0;
}
