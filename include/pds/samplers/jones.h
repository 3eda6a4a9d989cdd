#pragma once
// Voronoi-based maximal Poisson disk sampling (Jones 2006), 2D.

#include <cstdint>

#include "pds/domain.h"
#include "pds/limits.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

struct JonesParams {
  double radius = 0.01;                          // minimum distance between samples, > 0
  std::uint64_t max_points = kDefaultMaxPoints;  // refuse radii whose densest packing exceeds this
  Progress progress;                             // optional progress report and cancellation (pds/progress.h)
};

/// T. R. Jones, "Efficient generation of Poisson-disk sampling patterns",
/// journal of graphics tools 11(2), 2006.
///
/// Keeps the Voronoi diagram of the samples (CGAL's Delaunay triangulation;
/// the periodic one on a square torus, 9 copies of each sample on an oblong one).
/// The available area of a Voronoi cell is the part of the cell outside the
/// disk of radius `radius` around its site; each new sample is drawn uniformly
/// from the union of all available areas (a cell chosen by area through a sum
/// tree, then a point uniformly inside it), until no area is left.
/// Guarantees: all pairs at least `radius` apart; every point in [lo, hi);
/// maximal up to 1e-10 radius (a cell counts as covered when all its Voronoi
/// vertices are within radius * (1 + 1e-10) of its site); the process is
/// maximal dart throwing (each sample uniform over the uncovered area); same
/// seed, same points. 2D only.
/// Invalid: a radius that is not positive and finite, one whose densest
/// packing exceeds max_points, or on a torus a period shorter than 4 radius.
/// Failure: 10^4 darts in a row missing one cell's free area (a numerical
/// breakdown of the cell geometry; not seen in testing).
PointSet<2> jones(const JonesParams& params, const Domain<2>& domain, std::uint64_t seed);

}  // namespace pds
