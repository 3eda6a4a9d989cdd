#pragma once
// Fast maximal Poisson disk sampling on a flat quadtree (Ebeida et al.), 2D and 3D.

#include <cstdint>
#include <string>

#include "pds/domain.h"
#include "pds/limits.h"
#include "pds/point.h"

namespace pds {

struct EbeidaParams {
  double radius = 0.01;                          // minimum distance between samples, > 0
  std::uint64_t max_points = kDefaultMaxPoints;  // refuse radii whose densest packing exceeds this
};

/// Maximal Poisson disk sampling as in M. S. Ebeida, S. A. Mitchell, A. Patney,
/// A. A. Davidson, J. D. Owens, "A simple algorithm for maximal Poisson-disk
/// sampling in high dimensions", Computer Graphics Forum 31(2), 2012 (after
/// Ebeida et al., "Efficient maximal Poisson-disk sampling", SIGGRAPH 2011).
///
/// A grid of cells of edge < radius/sqrt(D) (one sample per cell at most)
/// guides dart throwing; cells that no dart can hit any more are dropped, and
/// the rest are split into 2^D sub-cells, keeping only those no single disk
/// covers (a flat quadtree), until nothing is left. Darts arrive as a Poisson
/// process in time on the cells still open, and each is kept if no earlier
/// kept sample lies within `radius`: resolved cell by cell in a sweep, this is
/// exactly sequential dart throwing until no dart fits (maximal random
/// sequential adsorption), not an approximation of it.
/// Guarantees: all pairs at least `radius` apart; every point in [lo, hi);
/// maximal (every point of the domain lies within `radius` of a sample, up to
/// a slack of 1e-12 radius plus a few units of rounding of the coordinates); same
/// seed, same points, on every platform.
/// Invalid: a radius that is not positive and finite, or whose densest packing
/// exceeds max_points. Failure: sub-cells still open after 63 levels in 2D, 41 in 3D (a
/// numerical breakdown; not seen in testing).
template <int D>
PointSet<D> ebeida(const EbeidaParams& params, const Domain<D>& domain, std::uint64_t seed);

namespace detail {
/// Why a flat quadtree over `domain` at radius r may open too many
/// sub-cells, for the Failure that says so: the first axis far shorter than
/// r (each level splits it too, doubling the sub-cells for nothing), or else
/// "numerical breakdown".
template <int D>
std::string quadtree_breakdown_reason(const Domain<D>& domain, double r);
}  // namespace detail

}  // namespace pds
