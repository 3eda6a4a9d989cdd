#pragma once
// Maximal dart throwing, exact and fast: Ebeida et al.'s flat grid and
// quadtree with darts at Poisson times, decided window by window in
// parallel (2D and 3D).

#include <cstdint>

#include "pds/domain.h"
#include "pds/limits.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

struct MaximalDartsParams {
  double radius = 0.01;                          // minimum distance between samples, > 0
  int threads = 0;                               // 0: all hardware threads; the output is the same for every count
  std::uint64_t max_points = kDefaultMaxPoints;  // refuse radii whose densest packing exceeds this
  // Optional progress (samples placed, against the usual count at the radius,
  // reported between the parallel phases) and cancellation (pds/progress.h).
  Progress progress;
};

/// Maximal Poisson disk sampling with the statistics of sequential dart
/// throwing run until no dart fits (random sequential adsorption to
/// saturation), as in M. S. Ebeida, S. A. Mitchell, A. Patney, A. A.
/// Davidson, J. D. Owens, "A simple algorithm for maximal Poisson-disk
/// sampling in high dimensions", Computer Graphics Forum 31(2), 2012: a grid
/// of cells of edge < radius/sqrt(D) holds one sample a cell at most; darts
/// land on the cells (then the sub-cells of a flat quadtree) that no single
/// disk covers. Darts carry Poisson times and are decided a time window at a
/// time: a dart is kept when no dart kept earlier in time lies within
/// `radius`, which is sequential dart throwing exactly, evaluated in
/// parallel (docs/maximal-darts.md).
/// Guarantees: all pairs at least `radius` apart; every point in [lo, hi);
/// maximal (every point of the domain within `radius` of a sample, up to a
/// slack of 1e-12 radius plus rounding, or 5e-10 radius where sub-cells reach
/// the deepest level, 2^-31 cells); same seed, same
/// points, for every thread count and platform.
/// Invalid: a radius that is not positive and finite, whose densest packing
/// exceeds max_points, or so small next to the coordinates that rounding is
/// a millionth of it. Failure: sub-cells of edge 2^-31 cells still open
/// after 1,000 rounds of darts (a numerical breakdown; not seen in testing).
template <int D>
PointSet<D> maximal_darts(const MaximalDartsParams& params, const Domain<D>& domain, std::uint64_t seed);

}  // namespace pds
