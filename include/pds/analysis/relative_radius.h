#pragma once
// Relative radius (Lagae & Dutre, "A comparison of methods for generating
// Poisson disk distributions", Computer Graphics Forum 27(1), 2008).
//
//   rho = (d_min / 2) / r_max
//
// where d_min is the smallest distance between two points and r_max is the
// radius of the disks in the densest packing of N equal disks into the
// domain's volume V:
//   2D (hexagonal packing, density pi/(2 sqrt 3)):   r_max = sqrt(V / (2 sqrt(3) N))
//   3D (face-centred cubic, density pi/(3 sqrt 2)):  r_max = cbrt(V / (4 sqrt(2) N))
//   1D: r_max = V / (2 N); 4 to 8 dimensions: the lattices D4, D5, E6, E7, E8
//   (densities pi^2/16, pi^2/(15 sqrt 2), pi^3/(48 sqrt 3), pi^3/105,
//   pi^4/384; Conway & Sloane, table 1.2). Past 8 dimensions the densest
//   packing is not known and these functions throw InvalidArgument.
// rho = 1 is the densest packing; Lagae & Dutre recommend 0.65 <= rho <= 0.85
// for Poisson disk sets. Maximal dart throwing reaches about 0.75, a regular
// square grid 0.93 in 2D, white noise close to 0.

#include <cstddef>

namespace pds {

/// The volume each point occupies in the densest packing of balls of radius
/// `ball_radius` (2 sqrt(3) R^2 in 2D, 4 sqrt(2) R^3 in 3D).
double packing_volume_per_point(double ball_radius, int dim);

/// r_max for n points in the given volume and dimension.
double max_packing_radius(double volume, std::size_t n, int dim);

/// rho = (min_distance / 2) / r_max; 0 for fewer than two points.
double relative_radius(double min_distance, double volume, std::size_t n, int dim);

}  // namespace pds
