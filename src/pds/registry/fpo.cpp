// Registry entry of farthest-point optimization: built only with the CGAL
// component (PDS_WITH_CGAL).
#include "pds/samplers/fpo.h"

#include "descriptors.h"
#include "pds/samplers/elimination.h"

namespace pds::registry_detail {

const Method& fpo_method() {
  static const Method method{
      .name = "fpo",
      .family = Family::optimized,
      .docs = "docs/fpo.md",
      .summary =
          "farthest-point optimization (Schlömer et al.): each point moved to the largest empty circle near it, "
          "sweeps until the spacing stops growing; 2D box or square torus",
      .citation =
          "T. Schlömer, D. Heck, O. Deussen, Farthest-point optimized point sets with maximized minimum "
          "distance, HPG 2011",
      .takes_count = true,
      .exact_count = true,
      .equal_periods = true,
      .dims = {2, 2},
      .memory_ratio = 15,
      .params = {{"sweeps", 1000, 1, 100000, true, "most sweeps (each moves every point once)"},
                 {"tolerance", 1e-5, 0, 1, false,
                  "stop after a sweep that grows neither the minimum nor the mean nearest-neighbour distance by this "
                  "fraction"},
                 {"start", 1, 0, 1, true,
                  "starting set: 0 white noise, 1 sample elimination (half the sweeps, same quality)"}},
      .run =
          [](const GenerateRequest& r) {
            const Domain<2> domain = r.domain<2>();
            FpoParams params;
            params.sweeps = static_cast<int>(r.param("sweeps", 1000));
            params.tolerance = r.param("tolerance", 1e-5);
            params.progress = r.progress;
            if (r.param("start", 1) == 0) return PointCloud::from<2>(fpo(*r.count, domain, params, r.seed).points);
            const PointSet<2> start = elimination<2>({.count = *r.count}, domain, r.seed);
            return PointCloud::from<2>(fpo_optimize(start, domain, params).points);
          },
  };
  return method;
}

}  // namespace pds::registry_detail
