#pragma once
// Plane regions bounded by polygons with holes, as a mask for the
// constrained samplers (samplers/constraints.h): SamplingConstraints<2>::inside
// = [&](const Point<2>& x) { return region.contains(x); }.
//
// A polygon is an outer ring and any number of hole rings; a ring is its
// vertices in order (closing edge implied; a repeated first vertex at the end,
// as GeoJSON writes it, is harmless). Either orientation. A point is inside a
// ring by the even-odd rule (a ray crossing count), so a self-intersecting
// ring is read the way SVG's evenodd fill reads it. A region is a union of
// polygons (GeoJSON's MultiPolygon): inside when inside some polygon's outer
// ring and none of that polygon's holes. Points exactly on an edge may fall
// either way.

#include <cmath>
#include <string>
#include <vector>

#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/point.h"

namespace pds {

using Ring = std::vector<Point<2>>;

struct Polygon {
  Ring outer;
  std::vector<Ring> holes;
};

/// True when x is inside the ring by the even-odd rule.
inline bool ring_contains(const Ring& ring, const Point<2>& x) {
  bool inside = false;
  const std::size_t n = ring.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point<2>& a = ring[i];
    const Point<2>& b = ring[j];
    // Edges whose ends straddle the horizontal line through x (half-open, so
    // a vertex on the line counts once); the crossing to the right of x flips.
    if ((a[1] > x[1]) != (b[1] > x[1])) {
      const double t = (x[1] - a[1]) / (b[1] - a[1]);
      if (x[0] < a[0] + t * (b[0] - a[0])) inside = !inside;
    }
  }
  return inside;
}

struct Region {
  std::vector<Polygon> polygons;

  bool contains(const Point<2>& x) const {
    for (const Polygon& p : polygons) {
      if (!ring_contains(p.outer, x)) continue;
      bool in_hole = false;
      for (const Ring& h : p.holes) in_hole = in_hole || ring_contains(h, x);
      if (!in_hole) return true;
    }
    return false;
  }

  /// Throws InvalidArgument (naming `what`, e.g. a file) unless every ring
  /// has at least 3 vertices, all finite, and the region has a polygon.
  void validate(const std::string& what) const {
    if (polygons.empty()) throw InvalidArgument(what + ": no polygon");
    for (std::size_t p = 0; p < polygons.size(); ++p) {
      const auto check = [&](const Ring& ring, const std::string& which) {
        const std::string where = what + ": polygon " + std::to_string(p + 1) + " " + which;
        if (ring.size() < 3)
          throw InvalidArgument(where + " has " + std::to_string(ring.size()) + " vertices (at least 3 needed)");
        for (const Point<2>& v : ring)
          if (!std::isfinite(v[0]) || !std::isfinite(v[1]))
            throw InvalidArgument(where + " has a non-finite vertex (" + detail::format_number(v[0]) + ", " +
                                  detail::format_number(v[1]) + ")");
      };
      check(polygons[p].outer, "outer ring");
      for (std::size_t h = 0; h < polygons[p].holes.size(); ++h)
        check(polygons[p].holes[h], "hole " + std::to_string(h + 1));
    }
  }
};

}  // namespace pds
