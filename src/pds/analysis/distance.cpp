#include "pds/analysis/distance.h"

#include <cmath>

#include "pds/grid.h"

namespace pds {

template <int D>
NearestNeighbors nearest_neighbors(const PointSet<D>& points, const Domain<D>& domain) {
  const std::size_t n = points.size();
  NearestNeighbors result{std::vector<double>(n, std::numeric_limits<double>::infinity()),
                          std::vector<std::int32_t>(n, -1)};
  if (n < 2) return result;

  // About one point per cell; the search radius starts at one cell edge and
  // doubles until it holds a neighbour, which is then the nearest (every point
  // within the radius was seen).
  double edge = std::pow(domain.volume() / static_cast<double>(n), 1.0 / D);
  const double max_cells = 4.0 * static_cast<double>(n) + 64.0;
  auto cells_for = [&](double e) {
    double c = 1.0;
    for (int i = 0; i < D; ++i) c *= std::max(1.0, std::ceil(domain.extent(i) / e));
    return c;
  };
  while (cells_for(edge) > max_cells) edge *= 2.0;  // very elongated domains
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

template <int D>
MinDistance min_distance(const PointSet<D>& points, const Domain<D>& domain) {
  const NearestNeighbors nn = nearest_neighbors(points, domain);
  MinDistance m;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (nn.distance[i] < m.distance) {
      m.distance = nn.distance[i];
      m.i = std::min<std::size_t>(i, static_cast<std::size_t>(nn.index[i]));
      m.j = std::max<std::size_t>(i, static_cast<std::size_t>(nn.index[i]));
    }
  return m;
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
PDS_INSTANTIATE(2)
PDS_INSTANTIATE(3)
#undef PDS_INSTANTIATE

}  // namespace pds
