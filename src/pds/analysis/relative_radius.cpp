#include "pds/analysis/relative_radius.h"

#include <cmath>
#include <string>

#include "pds/error.h"

namespace pds {

double packing_volume_per_point(double ball_radius, int dim) {
  switch (dim) {
    case 2:
      return 2.0 * std::sqrt(3.0) * ball_radius * ball_radius;
    case 3:
      return 4.0 * std::sqrt(2.0) * ball_radius * ball_radius * ball_radius;
    default:
      throw InvalidArgument("relative radius: dimension " + std::to_string(dim) + " is not supported");
  }
}

double max_packing_radius(double volume, std::size_t n, int dim) {
  const double per_point = volume / static_cast<double>(n);
  switch (dim) {
    case 2:
      return std::sqrt(per_point / (2.0 * std::sqrt(3.0)));
    case 3:
      return std::cbrt(per_point / (4.0 * std::sqrt(2.0)));
    default:
      throw InvalidArgument("relative radius: dimension " + std::to_string(dim) + " is not supported");
  }
}

double relative_radius(double min_distance, double volume, std::size_t n, int dim) {
  if (n < 2 || !std::isfinite(min_distance)) return 0.0;
  return 0.5 * min_distance / max_packing_radius(volume, n, dim);
}

}  // namespace pds
