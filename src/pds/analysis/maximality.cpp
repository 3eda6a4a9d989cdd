#include "pds/analysis/maximality.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "kd_tree.h"
#include "pds/detail/instantiate.h"
#include "pds/grid.h"
#include "pds/limits.h"

namespace pds {
namespace {

bool cells_budget_spent(std::size_t checked, std::size_t max_cells) { return max_cells > 0 && checked >= max_cells; }

template <int D>
struct Cell {
  Point<D> centre;
  Point<D> half;  // half the edge along each axis
};

// The volume of a ball of radius r in `dim` dimensions: pi^(d/2) r^d / Gamma(d/2 + 1).
double ball_volume(double r, int dim) {
  return std::pow(std::numbers::pi, 0.5 * dim) * std::pow(r, dim) / std::tgamma(0.5 * dim + 1.0);
}

/// The samples within a radius of a point: a background grid in 1 to 3
/// dimensions, a k-d tree above (the grid's neighbourhood grows as 5^D cells;
/// kd_tree.h, docs/analysis.md).
template <int D>
class Samples {
 public:
  Samples(const PointSet<D>& points, const Domain<D>& domain, double radius)
      : points_(points),
        grid_(make_grid(points, domain, radius)),
        tree_(D > 3 ? std::make_unique<detail::KdTree>(points.front().data(), points.size(), D, domain.lo.data(),
                                                        domain.hi.data(), domain.periodic)
                    : nullptr) {}

  const Point<D>& operator[](std::int32_t i) const { return points_[static_cast<std::size_t>(i)]; }

  template <class F>
  void for_each_within(const Point<D>& p, double r, F&& f) const {
    if (tree_)
      tree_->for_each_within(p.data(), r, f);
    else
      grid_->for_each_within(p, r, f);
  }

 private:
  static std::unique_ptr<Grid<D>> make_grid(const PointSet<D>& points, const Domain<D>& domain, double radius) {
    if constexpr (D > 3) {
      return nullptr;
    } else {
      auto grid = std::make_unique<Grid<D>>(Grid<D>::for_radius(domain, radius));
      for (const auto& p : points) grid->insert(p);
      return grid;
    }
  }

  const PointSet<D>& points_;
  std::unique_ptr<Grid<D>> grid_;
  std::unique_ptr<detail::KdTree> tree_;
};

}  // namespace

template <int D>
Maximality<D> check_maximality(const PointSet<D>& points, const Domain<D>& domain, double radius, double tolerance,
                               std::size_t max_cells) {
  require_radius(radius);
  double budget_tolerance = 0.0;  // the largest cell diagonal left undecided for want of budget
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

  const Samples<D> samples(points, domain, radius);

  const double r2 = radius * radius;
  // Root cells of edge at most radius / 2 in 1 to 3 dimensions. Above, cells
  // are halved along their longest axis only (2^D children per split would
  // make 256 cells of each one in 8D, most of them decided by their parent's
  // neighbours), so larger roots cost little: edge at most the radius, which
  // keeps the root count below N times the unit ball's volume.
  const double root_edge = D > 3 ? radius : 0.5 * radius;
  std::array<int, D> roots;
  Point<D> root_half;
  for (int i = 0; i < D; ++i) {
    roots[i] = static_cast<int>(std::max(1.0, std::ceil(domain.extent(i) / root_edge)));
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
      // A sample that covers the cell, and one within the radius of the
      // centre, both lie within the radius of the centre.
      samples.for_each_within(cell.centre, radius, [&](std::int32_t j, double d2) {
        nearest2 = std::min(nearest2, d2);
        // Farthest corner of the cell from the sample (an upper bound on a
        // torus, where folding only brings points closer).
        const auto& s = samples[j];
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
        result.budget_exhausted = budget_tolerance > 0.0;
        result.gap = cell.centre;
        result.gap_distance = std::sqrt(best2);
        return result;
      }
      if (2.0 * half_diag <= tolerance) {
        undecided = true;
        continue;
      }
      if (cells_budget_spent(result.cells_checked, max_cells)) {
        // Out of budget: no more splitting; the cell's centre is within the
        // radius of a sample, so all of it is within radius + half diagonal.
        budget_tolerance = std::max(budget_tolerance, 2.0 * half_diag);
        continue;
      }
      if constexpr (D <= 3) {
        for (int child = 0; child < (1 << D); ++child) {
          Cell<D> c;
          for (int i = 0; i < D; ++i) {
            c.half[i] = 0.5 * cell.half[i];
            c.centre[i] = cell.centre[i] + ((child >> i) & 1 ? c.half[i] : -c.half[i]);
          }
          stack.push_back(c);
        }
      } else {
        int axis = 0;
        for (int i = 1; i < D; ++i)
          if (cell.half[i] > cell.half[axis]) axis = i;
        for (const double side : {-1.0, 1.0}) {
          Cell<D> c = cell;
          c.half[axis] = 0.5 * cell.half[axis];
          c.centre[axis] = cell.centre[axis] + side * c.half[axis];
          stack.push_back(c);
        }
      }
    }
    int axis = 0;
    while (axis < D && ++index[axis] == roots[axis]) index[axis++] = 0;
    if (axis == D) break;
  }
  result.maximal = true;
  result.tolerance = std::max(undecided ? tolerance : 0.0, budget_tolerance);
  result.budget_exhausted = budget_tolerance > 0.0;
  return result;
}

#define PDS_INSTANTIATE(D) \
  template Maximality<D> check_maximality<D>(const PointSet<D>&, const Domain<D>&, double, double, std::size_t);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
