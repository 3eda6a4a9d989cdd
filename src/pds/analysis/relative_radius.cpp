#include "pds/analysis/relative_radius.h"

#include <cmath>
#include <numbers>
#include <string>

#include "pds/error.h"
#include "pds/point.h"

namespace pds {

namespace {

// The densest known packings of equal balls (Conway & Sloane, "Sphere
// Packings, Lattices and Groups", 3rd ed., table 1.2): the lattices Z, A2,
// A3 = D3, D4, D5, E6, E7, E8, each the densest lattice packing in its
// dimension; in 2, 3 and 8 dimensions proven densest of all packings
// (Thue/Fejes Toth, Hales 2005, Viazovska 2017).
double packing_density(int dim) {
  constexpr double pi = std::numbers::pi;
  switch (dim) {
    case 1: return 1.0;
    case 2: return pi / std::sqrt(12.0);
    case 3: return pi / std::sqrt(18.0);
    case 4: return pi * pi / 16.0;
    case 5: return pi * pi / (15.0 * std::sqrt(2.0));
    case 6: return pi * pi * pi / (48.0 * std::sqrt(3.0));
    case 7: return pi * pi * pi / 105.0;
    case 8: return pi * pi * pi * pi / 384.0;
    default:
      throw InvalidArgument("relative radius: the densest packing is known in 1 to 8 dimensions, not in " +
                            std::to_string(dim));
  }
}

// Volume of the unit ball in dim dimensions.
double unit_ball_volume(int dim) {
  return std::pow(std::numbers::pi, 0.5 * dim) / std::tgamma(0.5 * dim + 1.0);
}

}  // namespace

double packing_volume_per_point(double ball_radius, int dim) {
  // The closed forms of 2D and 3D are kept bit for bit (sizes made from them
  // are pinned by the golden outputs).
  switch (dim) {
    case 2:
      return 2.0 * std::sqrt(3.0) * ball_radius * ball_radius;
    case 3:
      return 4.0 * std::sqrt(2.0) * ball_radius * ball_radius * ball_radius;
    default:
      return unit_ball_volume(dim) * std::pow(ball_radius, dim) / packing_density(dim);
  }
}

double max_packing_radius(double volume, std::size_t n, int dim) {
  const double per_point = volume / static_cast<double>(n);
  switch (dim) {
    case 1:
      return 0.5 * per_point;
    case 2:
      return std::sqrt(per_point / (2.0 * std::sqrt(3.0)));
    case 3:
      return std::cbrt(per_point / (4.0 * std::sqrt(2.0)));
    default:
      return std::pow(per_point * packing_density(dim) / unit_ball_volume(dim), 1.0 / dim);
  }
}

double relative_radius(double min_distance, double volume, std::size_t n, int dim) {
  if (n < 2 || !std::isfinite(min_distance)) return 0.0;
  return 0.5 * min_distance / max_packing_radius(volume, n, dim);
}

}  // namespace pds
