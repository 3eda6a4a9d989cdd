#pragma once
// Exact nearest-neighbour and minimum distances, box and torus, in every
// dimension. In 1 to 3 dimensions a background grid with about one point per
// cell, searched in growing radii: expected O(N) for point sets of roughly
// uniform density. In 4 and more dimensions, where a grid's neighbourhood
// grows as 5^D cells and more, an exact k-d tree: O(N log N) expected in low
// dimensions, tending to O(N^2 D) far beyond 10 dimensions (every point is
// about as far as every other there); its queries run on several threads.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
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

/// The same for a dimension known at run time (any dim >= 1, typed up to
/// kMaxDim, through the k-d tree beyond), in the box [lo, hi) or the torus
/// over it. Throws InvalidArgument for bounds of the wrong size or invalid
/// (validate_axis), or a point outside them.
NearestNeighbors nearest_neighbors(const PointCloud& points, std::span<const double> lo, std::span<const double> hi,
                                   bool periodic);
MinDistance min_distance(const PointCloud& points, std::span<const double> lo, std::span<const double> hi,
                         bool periodic);

/// All-pairs O(N^2) reference, for tests and tiny sets.
template <int D>
MinDistance min_distance_brute_force(const PointSet<D>& points, const Domain<D>& domain);

}  // namespace pds
