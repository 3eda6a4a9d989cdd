#include "pds/analysis/maximality.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "pds/grid.h"
#include "pds/limits.h"

namespace pds {
namespace {

template <int D>
struct Cell {
  Point<D> centre;
  Point<D> half;  // half the edge along each axis
};

double ball_volume(double r, int dim) {
  return dim == 2 ? std::numbers::pi * r * r : 4.0 / 3.0 * std::numbers::pi * r * r * r;
}

}  // namespace

template <int D>
Maximality<D> check_maximality(const PointSet<D>& points, const Domain<D>& domain, double radius, double tolerance) {
  require_radius(radius);
  if (!(tolerance > 0.0)) tolerance = 1e-9 * radius;
  Maximality<D> result;

  Point<D> centre;
  for (int i = 0; i < D; ++i) centre[i] = 0.5 * (domain.lo[i] + domain.hi[i]);
  if (points.empty()) {
    result.gap = centre;
    result.gap_distance = std::numeric_limits<double>::infinity();
    return result;
  }
  // The balls cannot cover more than their total volume: a quick and certain
  // answer that also bounds the work below to O(N) root cells.
  if (static_cast<double>(points.size()) * ball_volume(radius, D) < domain.volume()) return result;

  Grid<D> grid = Grid<D>::for_radius(domain, radius);
  for (const auto& p : points) grid.insert(p);

  const double r2 = radius * radius;
  // Root cells of edge at most radius / 2.
  std::array<int, D> roots;
  Point<D> root_half;
  for (int i = 0; i < D; ++i) {
    roots[i] = static_cast<int>(std::max(1.0, std::ceil(domain.extent(i) / (0.5 * radius))));
    root_half[i] = 0.5 * domain.extent(i) / roots[i];
  }

  std::vector<Cell<D>> stack;
  std::array<int, D> index{};
  bool undecided = false;
  while (true) {
    Cell<D> root;
    for (int i = 0; i < D; ++i) root.centre[i] = domain.lo[i] + (2 * index[i] + 1) * root_half[i];
    root.half = root_half;
    stack.push_back(root);
    while (!stack.empty()) {
      const Cell<D> cell = stack.back();
      stack.pop_back();
      ++result.cells_checked;
      double half_diag2 = 0.0;
      for (int i = 0; i < D; ++i) half_diag2 += cell.half[i] * cell.half[i];
      const double half_diag = std::sqrt(half_diag2);

      bool covered = false;
      double nearest2 = std::numeric_limits<double>::infinity();
      grid.for_each_within(cell.centre, radius + half_diag, [&](std::int32_t j, double d2) {
        nearest2 = std::min(nearest2, d2);
        // Farthest corner of the cell from the sample (an upper bound on a
        // torus, where folding only brings points closer).
        const auto& s = grid.points()[static_cast<std::size_t>(j)];
        double far2 = 0.0;
        for (int i = 0; i < D; ++i) {
          const double d = std::abs(domain.delta(s[i], cell.centre[i], i)) + cell.half[i];
          far2 += d * d;
        }
        covered = far2 <= r2;
        return !covered;
      });
      if (covered) continue;
      if (nearest2 > r2) {
        // The centre itself is uncovered; find its true nearest sample.
        double best2 = std::numeric_limits<double>::infinity();
        for (const auto& p : points) best2 = std::min(best2, domain.distance2(p, cell.centre));
        result.gap = cell.centre;
        result.gap_distance = std::sqrt(best2);
        return result;
      }
      if (2.0 * half_diag <= tolerance) {
        undecided = true;
        continue;
      }
      for (int child = 0; child < (1 << D); ++child) {
        Cell<D> c;
        for (int i = 0; i < D; ++i) {
          c.half[i] = 0.5 * cell.half[i];
          c.centre[i] = cell.centre[i] + ((child >> i) & 1 ? c.half[i] : -c.half[i]);
        }
        stack.push_back(c);
      }
    }
    int axis = 0;
    while (axis < D && ++index[axis] == roots[axis]) index[axis++] = 0;
    if (axis == D) break;
  }
  result.maximal = true;
  result.tolerance = undecided ? tolerance : 0.0;
  return result;
}

template Maximality<2> check_maximality<2>(const PointSet<2>&, const Domain<2>&, double, double);
template Maximality<3> check_maximality<3>(const PointSet<3>&, const Domain<3>&, double, double);

}  // namespace pds
