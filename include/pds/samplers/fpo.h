#pragma once
// Farthest-point optimization: each point in turn is moved to the farthest
// point from the others (the centre of the largest empty circle of their
// Delaunay triangulation, near its old place), sweep after sweep, which
// drives the minimum distance up to relative radius ~0.93 (T. Schlömer,
// D. Heck, O. Deussen, Farthest-point optimized point sets with maximized
// minimum distance, High Performance Graphics 2011).

#include <cstdint>
#include <vector>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

struct FpoParams {
  /// Sweeps at most (each moves every point once, along a Hilbert curve
  /// through the starting set), >= 1.
  int sweeps = 1000;
  /// Stop rule: stop after a sweep that grows neither the minimum distance
  /// nor the mean nearest-neighbour distance by this fraction (0: stop only
  /// when neither grows at all), >= 0. (The minimum alone can stand still for
  /// a sweep while the set is still far from its end.)
  /// The minimum distance keeps growing slowly long after the mean spacing
  /// has settled (2D torus, 4096 points: relative radius 0.907 after 100
  /// sweeps, 0.924 after 300, 0.930 after 1000): 1e-5 stops near 0.928 at
  /// 1024-4096 points, where 1e-4 stopped near 0.916 (docs/fpo.md).
  double tolerance = 1e-5;
  /// Optional progress (points visited out of sweeps x count) and cancellation (pds/progress.h).
  Progress progress;
};

/// What one sweep left: over all points, the smallest and the mean distance
/// to the nearest other point, and how many points moved.
struct FpoSweep {
  double min_distance = 0;
  double mean_nn_distance = 0;
  std::size_t moved = 0;
};

struct FpoResult {
  PointSet<2> points;
  /// sweeps[0] is the starting set (moved = 0), then one entry per sweep.
  std::vector<FpoSweep> sweeps;
};

/// Optimizes `start` on a square torus (CGAL's periodic Delaunay
/// triangulation takes square periods only) or in a box of any shape. Each
/// step removes point x from the triangulation and takes, among the faces
/// incident to x's former neighbours (the hole and its ring), the one with
/// the largest circumcircle (in a box: whose centre is inside it, and also
/// the points where those neighbours' Voronoi cells meet a side or hold a
/// corner); x moves to the farthest of these if its nearest neighbour there
/// is farther than at its old place (Domain::distance2), else stays.
/// Guarantees: the points stay in [lo, hi) and keep their count and order;
/// the minimum distance never decreases from one sweep to the next (a move
/// takes x only where its nearest neighbour is farther than before, so no
/// new pair is closer than the old minimum), and each sweep's figures are
/// exact for the set it left; deterministic (no randomness).
/// Invalid (InvalidArgument): fewer than 2 points, a torus whose periods
/// differ, a point outside the domain or two equal points, sweeps < 1,
/// tolerance < 0.
FpoResult fpo_optimize(const PointSet<2>& start, const Domain<2>& domain, const FpoParams& params);

/// fpo_optimize from `count` white-noise points drawn from `seed`.
FpoResult fpo(std::uint64_t count, const Domain<2>& domain, const FpoParams& params, std::uint64_t seed);

}  // namespace pds
