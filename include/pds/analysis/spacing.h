#pragma once
// Nearest-neighbour spacing summarised as relative radii (Lagae & Dutre 2008,
// see relative_radius.h): rho_min from the smallest nearest-neighbour
// distance (their rho), rho_mean from the mean one. Both are 1 for the
// densest packing; white noise has rho_min near 0 and rho_mean near 0.47 in
// 2D (the mean nearest-neighbour distance of uniform points is 0.5 / sqrt(N)
// on the unit square).

#include "pds/domain.h"
#include "pds/point.h"

namespace pds {

struct Spacing {
  double min_distance = 0;   // smallest nearest-neighbour distance (inf for fewer than two points)
  double mean_distance = 0;  // mean nearest-neighbour distance (NaN for fewer than two points)
  double rho_min = 0;        // relative_radius(min_distance)
  double rho_mean = 0;       // relative_radius(mean_distance)
};

/// Exact, through nearest_neighbors(); the points must lie in the domain.
template <int D>
Spacing spacing(const PointSet<D>& points, const Domain<D>& domain);

}  // namespace pds
