#pragma once
// Boundary sampling with the spatial data structure of Dunbar & Humphreys:
// maximal Poisson disk sets in 2D in O(N).

#include <cstdint>

#include "pds/domain.h"
#include "pds/limits.h"
#include "pds/point.h"
#include "pds/registry.h"

namespace pds {

struct DunbarHumphreysParams {
  double radius = 0.01;                          // minimum distance between samples, > 0
  std::uint64_t max_points = kDefaultMaxPoints;  // refuse radii whose densest packing exceeds this
};

/// D. Dunbar and G. Humphreys, "A spatial data structure for fast Poisson-disk
/// sample generation", ACM SIGGRAPH 2006 (TOG 25(3)), boundary sampling.
///
/// Each sample, taken from the front in insertion order, keeps the part of the
/// circle of radius `radius` around it that lies outside every other disk (a
/// set of arcs, the one-dimensional case of the paper's scalloped region); new
/// samples are drawn uniformly on those arcs until none is left.
/// Guarantees: all pairs at least `radius` apart; every point in [lo, hi);
/// maximal up to 1e-10 radius: every point of the domain lies within
/// radius * (1 + 1e-10) of a sample; same seed, same points. The set is denser
/// and more regular than maximal dart throwing (rho about 0.87 rather than
/// 0.78, every nearest neighbour at distance radius; see
/// docs/dunbar-humphreys.md). 2D only.
/// Invalid: a radius that is not positive and finite, one whose densest
/// packing exceeds max_points, or on a torus a period of 4 radius or less.
PointSet<2> dunbar_humphreys(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed);

const Method& dunbar_humphreys_method();

}  // namespace pds
