#pragma once
// Fast maximal Poisson disk sampling on a flat quadtree (Ebeida et al.), 1 to 8 dimensions.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "pds/domain.h"
#include "pds/limits.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

struct EbeidaParams {
  double radius = 0.01;                          // minimum distance between samples, > 0
  std::uint64_t max_points = kDefaultMaxPoints;  // refuse radii whose densest packing exceeds this
  // Optional progress (samples placed, against the usual count at the radius)
  // and cancellation (pds/progress.h).
  Progress progress;
};

/// Maximal Poisson disk sampling as in M. S. Ebeida, S. A. Mitchell, A. Patney,
/// A. A. Davidson, J. D. Owens, "A simple algorithm for maximal Poisson-disk
/// sampling in high dimensions", Computer Graphics Forum 31(2), 2012 (after
/// Ebeida et al., "Efficient maximal Poisson-disk sampling", SIGGRAPH 2011).
///
/// A grid of cells of edge < radius/sqrt(D) (one sample per cell at most)
/// guides dart throwing; cells that no dart can hit any more are dropped, and
/// the rest are split into 2^D sub-cells, keeping only those no single disk
/// covers (from 4D, nor a union of disks, by a test of weighted distances)
/// (a flat quadtree), until nothing is left. Darts arrive as a Poisson
/// process in time on the cells still open, and each is kept if no earlier
/// kept sample lies within `radius`: resolved cell by cell in a sweep, this is
/// exactly sequential dart throwing until no dart fits (maximal random
/// sequential adsorption), not an approximation of it.
/// Guarantees: all pairs at least `radius` apart; every point in [lo, hi);
/// maximal (every point of the domain lies within `radius` of a sample, up to
/// a slack of 1e-12 radius plus a few units of rounding of the coordinates); same
/// seed, same points, on every platform.
/// D from 1 to 8: from 5D darts are drawn in sequence from a list of the open
/// sub-cells (the sweep's neighbourhoods hold 16,807 cells there). Past 5D
/// the sub-cells that one disk does not cover multiply nearly 2^D-fold a
/// level and the run slows steeply: tens of samples a second in 7D, about
/// one in 8D on a torus (docs/dimensions.md); for larger sets there, bridson.
/// Invalid: a radius that is not positive and finite, whose densest packing
/// exceeds max_points, or (from 5D) whose sub-cells could need more than 4 GiB.
/// Failure: sub-cells still open after 63 levels in 2D, 41 in 3D, 60 from 5D
/// (a numerical breakdown; not seen in testing), or more open sub-cells a
/// grid cell than the memory bound was sized for (from 6D; not seen in testing
/// at the present bound, seen at half of it on an 8D torus of period r).
template <int D>
PointSet<D> ebeida(const EbeidaParams& params, const Domain<D>& domain, std::uint64_t seed);

namespace detail {
/// The levels each axis of a flat quadtree over cells of n[a] per axis waits
/// before it is split (at most max_level). A cell is as thin as the domain
/// along an axis shorter than the cell's edge elsewhere; splitting that axis
/// with the others would double the open sub-cells each level to no purpose
/// (a 100 x 1e-4 x 1e-4 box at r = 0.01 opened 81,920 at level 7), so it
/// waits until the other axes' sub-cells are as thin, from when on a level's
/// sub-cells stay within a factor 2 of cubic. Cells of two or more along every
/// axis are within that factor already (their edges lie in (r / (2 sqrt D),
/// r / sqrt D]): no delay.
template <int D>
std::array<int, D> quadtree_axis_delays(const Domain<D>& domain, const std::array<int, D>& n, int max_level) {
  double widest = 0.0;
  for (int a = 0; a < D; ++a) widest = std::max(widest, domain.extent(a) / n[a]);
  std::array<int, D> delay{};
  for (int a = 0; a < D; ++a)
    while (delay[a] < max_level && std::ldexp(domain.extent(a) / n[a], delay[a] + 1) <= widest) ++delay[a];
  return delay;
}
}  // namespace detail

}  // namespace pds
