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
};

/// Checks whether every point of the domain lies within `radius` of some
/// sample. Samples must lie in the domain. tolerance <= 0 picks 1e-9 radius.
/// Throws InvalidArgument for a radius that is not positive and finite.
template <int D>
Maximality<D> check_maximality(const PointSet<D>& points, const Domain<D>& domain, double radius,
                               double tolerance = 0.0);

}  // namespace pds
