// Registry entry of Jones's Voronoi-based sampler: built only with the CGAL
// component (PDS_WITH_CGAL).
#include "pds/samplers/jones.h"

#include <algorithm>

#include "descriptors.h"

namespace pds::registry_detail {

const Method& jones_method() {
  static const Method method{
      .name = "jones",
      .family = Family::fast_poisson_disk,
      .docs = "docs/jones.md",
      .summary = "Voronoi-based maximal dart throwing (Jones): cell chosen by free area, 2D, --radius",
      .citation =
          "T. R. Jones, Efficient generation of Poisson-disk sampling patterns, journal of graphics tools "
          "11(2), 2006",
      .takes_radius = true,
      .min_distance = true,
      .maximal = true,
      .compare = true,
      .dims = {2, 2},
      // Measured over seeds 1-5: box 0.783-0.789, torus 0.775-0.780.
      .rho = {{2, false, 0.02, 0.76, 0.81}, {2, true, 0.02, 0.755, 0.80}},
      .memory_ratio = 15.5,
      .run =
          [](const GenerateRequest& r) {
            const JonesParams params{*r.radius, r.max_points, r.progress};
            return PointCloud::from<2>(jones(params, r.domain<2>(), r.seed));
          },
  };
  return method;
}

}  // namespace pds::registry_detail
