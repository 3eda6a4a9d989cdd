#include "pds/analysis/spacing.h"

#include <cmath>
#include <limits>

#include "pds/analysis/distance.h"
#include "pds/analysis/relative_radius.h"
#include "pds/detail/instantiate.h"

namespace pds {

template <int D>
Spacing spacing(const PointSet<D>& points, const Domain<D>& domain) {
  Spacing s;
  s.min_distance = std::numeric_limits<double>::infinity();
  s.mean_distance = std::numeric_limits<double>::quiet_NaN();
  if (points.size() < 2) return s;
  const NearestNeighbors nn = nearest_neighbors(points, domain);
  double sum = 0;
  for (double d : nn.distance) {
    sum += d;
    s.min_distance = std::min(s.min_distance, d);
  }
  s.mean_distance = sum / static_cast<double>(points.size());
  s.rho_min = relative_radius(s.min_distance, domain.volume(), points.size(), D);
  s.rho_mean = relative_radius(s.mean_distance, domain.volume(), points.size(), D);
  return s;
}

#define PDS_INSTANTIATE(D) template Spacing spacing<D>(const PointSet<D>&, const Domain<D>&);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
