#pragma once
// Maximality: whether the disks (balls) of radius r around the samples cover
// the whole domain, i.e. no further sample could be added at distance >= r.
//
// The check subdivides the domain adaptively. A cell is covered when a single
// ball contains it entirely (its farthest corner is within r of one sample),
// which is exact. A cell whose centre is farther than r from every sample is
// an uncovered point: the set is not maximal, and that point is returned as a
// witness. Cells that are neither are split, down to a diagonal of
// `tolerance`; a cell still undecided at that size has its centre within r of
// a sample, so all its points are within r + tolerance. The result therefore
// says one of: maximal (proven exactly), not maximal (with a witness), or
// maximal up to `tolerance` (every point within r + tolerance of a sample).
//
// In 1 to 3 dimensions a cell is split into its 2^D halves and the samples
// are found through a background grid; in 4 to 8 dimensions a cell is halved
// along its longest axis and the samples are found through a k-d tree. The
// number of cells grows as (r / (r - c))^D where c is the covering radius
// (the largest distance from a point of the domain to its nearest sample):
// quick for lattices and for sets far from the limit, slow for a maximal set
// whose covering radius is a hair under r in 6 to 8 dimensions. `max_cells`
// bounds the work: past it cells are no longer split and the answer is
// "maximal up to tolerance" with the largest undecided cell's diagonal as the
// tolerance (budget_exhausted says so), or "not maximal" if a gap was found.

#include <cstddef>
#include <optional>

#include "pds/domain.h"
#include "pds/point.h"

namespace pds {

template <int D>
struct Maximality {
  bool maximal = false;
  /// 0 when proven exactly; otherwise every point of the domain is within
  /// radius + tolerance of a sample.
  double tolerance = 0.0;
  /// When not maximal and a witness was found: a point of the domain farther
  /// than the radius from every sample, and its distance to the nearest one.
  std::optional<Point<D>> gap;
  double gap_distance = 0.0;
  std::size_t cells_checked = 0;
  /// The cells stopped being split at max_cells: the tolerance is the budget's.
  bool budget_exhausted = false;
};

/// check_maximality's default budget of cells (about a minute in 8D).
inline constexpr std::size_t kMaxMaximalityCells = std::size_t{1} << 26;

/// Checks whether every point of the domain lies within `radius` of some
/// sample. Samples must lie in the domain. tolerance <= 0 picks 1e-9 radius;
/// max_cells 0 means no bound. Throws InvalidArgument for a radius that is
/// not positive and finite.
template <int D>
Maximality<D> check_maximality(const PointSet<D>& points, const Domain<D>& domain, double radius,
                               double tolerance = 0.0, std::size_t max_cells = kMaxMaximalityCells);

}  // namespace pds
