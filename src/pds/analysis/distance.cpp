#include "pds/analysis/distance.h"

#include <cmath>
#include <string>

#include "kd_tree.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"
#include "pds/grid.h"
#include "pds/parallel.h"

namespace pds {
namespace {

/// Up to this dimension a background grid answers the queries; above it a
/// k-d tree does (kd_tree.h; the crossover measured in docs/analysis.md).
constexpr int kGridUpToDim = 3;

/// Every point's nearest other point through a k-d tree, queries spread over
/// threads (each writes its own slot, so the result is the same for any
/// thread count).
NearestNeighbors nearest_by_tree(const double* coords, std::size_t n, int dim, const double* lo, const double* hi,
                                 bool periodic) {
  NearestNeighbors result{std::vector<double>(n, std::numeric_limits<double>::infinity()),
                          std::vector<std::int32_t>(n, -1)};
  if (n < 2) return result;
  if (n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw InvalidArgument("nearest neighbours: more than 2^31 - 1 points");
  const detail::KdTree tree(coords, n, dim, lo, hi, periodic);
  parallel_for(0, n, 256, 0, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i != last; ++i) {
      const auto [j, d2] = tree.nearest(coords + i * static_cast<std::size_t>(dim), static_cast<std::int64_t>(i));
      result.distance[i] = std::sqrt(d2);
      result.index[i] = j;
    }
  });
  return result;
}

MinDistance smallest(const NearestNeighbors& nn) {
  MinDistance m;
  for (std::size_t i = 0; i < nn.distance.size(); ++i)
    if (nn.distance[i] < m.distance) {
      m.distance = nn.distance[i];
      m.i = std::min<std::size_t>(i, static_cast<std::size_t>(nn.index[i]));
      m.j = std::max<std::size_t>(i, static_cast<std::size_t>(nn.index[i]));
    }
  return m;
}

template <int D>
NearestNeighbors nearest_by_grid(const PointSet<D>& points, const Domain<D>& domain) {
  const std::size_t n = points.size();
  NearestNeighbors result{std::vector<double>(n, std::numeric_limits<double>::infinity()),
                          std::vector<std::int32_t>(n, -1)};
  if (n < 2) return result;
  // About one point per cell; the search radius starts at one cell edge and
  // doubles until it holds a neighbour, which is then the nearest (every point
  // within the radius was seen).
  double edge = std::pow(domain.volume() / static_cast<double>(n), 1.0 / D);
  const double max_cells = 4.0 * static_cast<double>(n) + 64.0;
  edge = Grid<D>::edge_for_at_most(domain, edge, max_cells);  // very elongated domains
  Grid<D> grid(domain, edge, static_cast<std::size_t>(max_cells));
  for (const auto& p : points) grid.insert(p);

  double diameter2 = 0.0;
  for (int i = 0; i < D; ++i) {
    const double e = domain.periodic ? 0.5 * domain.extent(i) : domain.extent(i);
    diameter2 += e * e;
  }
  const double diameter = std::sqrt(diameter2);

  for (std::size_t i = 0; i < n; ++i) {
    double best = std::numeric_limits<double>::infinity();
    std::int32_t best_index = -1;
    for (double r = edge;; r *= 2.0) {
      grid.for_each_within(points[i], r, [&](std::int32_t j, double d2) {
        if (static_cast<std::size_t>(j) != i && d2 < best) {
          best = d2;
          best_index = j;
        }
        return true;
      });
      if (best_index >= 0 || r > diameter) break;
    }
    result.distance[i] = std::sqrt(best);
    result.index[i] = best_index;
  }
  return result;
}

}  // namespace


template <int D>
NearestNeighbors nearest_neighbors(const PointSet<D>& points, const Domain<D>& domain) {
  if constexpr (D > kGridUpToDim)
    return nearest_by_tree(points.empty() ? nullptr : points.front().data(), points.size(), D, domain.lo.data(),
                           domain.hi.data(), domain.periodic);
  else
    return nearest_by_grid(points, domain);
}

template <int D>
MinDistance min_distance(const PointSet<D>& points, const Domain<D>& domain) {
  return smallest(nearest_neighbors(points, domain));
}

NearestNeighbors nearest_neighbors(const PointCloud& points, std::span<const double> lo, std::span<const double> hi,
                                   bool periodic) {
  const int dim = points.dim;
  if (dim < 1) throw InvalidArgument("nearest neighbours: dimension " + std::to_string(dim) + " is not positive");
  if (lo.size() != static_cast<std::size_t>(dim) || hi.size() != static_cast<std::size_t>(dim))
    throw InvalidArgument("nearest neighbours: the bounds have " + std::to_string(lo.size()) + " and " +
                          std::to_string(hi.size()) + " coordinates, the points " + std::to_string(dim));
  for (int k = 0; k < dim; ++k) validate_axis(k, lo[k], hi[k]);
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < dim; ++k) {
      const double x = points.point(i)[k];
      if (!(x >= lo[k] && x < hi[k]))
        throw InvalidArgument("nearest neighbours: point " + std::to_string(i) + " lies outside the domain (axis " +
                              std::to_string(k) + ")");
    }
  if (dim >= kMinDim && dim <= kMaxDim)
    return visit_dim<kMinDim, kMaxDim>(dim, [&](auto d) {
      constexpr int D = decltype(d)::value;
      const Domain<D> domain = Domain<D>::from_bounds(lo.data(), hi.data(), periodic);
      return nearest_neighbors<D>(points.as<D>(), domain);
    });
  return nearest_by_tree(points.coords.data(), n, dim, lo.data(), hi.data(), periodic);
}

MinDistance min_distance(const PointCloud& points, std::span<const double> lo, std::span<const double> hi,
                         bool periodic) {
  return smallest(nearest_neighbors(points, lo, hi, periodic));
}

template <int D>
MinDistance min_distance_brute_force(const PointSet<D>& points, const Domain<D>& domain) {
  MinDistance m;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      const double d2 = domain.distance2(points[i], points[j]);
      if (d2 < best) {
        best = d2;
        m.i = i;
        m.j = j;
      }
    }
  m.distance = std::sqrt(best);
  return m;
}

#define PDS_INSTANTIATE(D)                                                              \
  template NearestNeighbors nearest_neighbors<D>(const PointSet<D>&, const Domain<D>&); \
  template MinDistance min_distance<D>(const PointSet<D>&, const Domain<D>&);           \
  template MinDistance min_distance_brute_force<D>(const PointSet<D>&, const Domain<D>&);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
