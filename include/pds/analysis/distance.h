#pragma once
// Exact nearest-neighbour and minimum distances, box and torus, in expected
// O(N) for point sets of roughly uniform density (a background grid with
// about one point per cell, searched in growing radii).

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "pds/domain.h"
#include "pds/point.h"

namespace pds {

struct NearestNeighbors {
  std::vector<double> distance;     // distance from point i to its nearest other point (inf if none)
  std::vector<std::int32_t> index;  // that point's index (-1 if none)
};

struct MinDistance {
  double distance = std::numeric_limits<double>::infinity();  // inf for fewer than two points
  std::size_t i = 0, j = 0;                                   // a pair at that distance (i < j)
};

/// For every point, its exact nearest other point under the domain's metric.
/// Points must lie in the domain (Domain::contains).
template <int D>
NearestNeighbors nearest_neighbors(const PointSet<D>& points, const Domain<D>& domain);

/// The smallest distance between two distinct points, and a pair attaining it.
template <int D>
MinDistance min_distance(const PointSet<D>& points, const Domain<D>& domain);

/// All-pairs O(N^2) reference, for tests and tiny sets.
template <int D>
MinDistance min_distance_brute_force(const PointSet<D>& points, const Domain<D>& domain);

}  // namespace pds
