#pragma once
// The spatial data structure of Dunbar & Humphreys: maximal Poisson disk sets
// in 2D in O(N), by boundary sampling or by scalloped sectors.

#include <array>
#include <cstdint>
#include <vector>

#include "pds/domain.h"
#include "pds/limits.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

struct DunbarHumphreysParams {
  double radius = 0.01;                          // minimum distance between samples, > 0
  std::uint64_t max_points = kDefaultMaxPoints;  // refuse radii whose densest packing exceeds this
  // 0: boundary sampling (new samples on the circle of radius `radius`);
  // 1: the paper's scalloped sectors (new samples uniform over the free part
  // of the annulus radius..2 radius, one front sample filled at a time);
  // 2: the same sectors, each new sample uniform over all free annuli at once
  // (dart throwing's statistics; slower).
  int variant = 0;
  // Optional progress (samples placed, against the usual count at the radius)
  // and cancellation (pds/progress.h).
  Progress progress;
};

/// D. Dunbar and G. Humphreys, "A spatial data structure for fast Poisson-disk
/// sample generation", ACM SIGGRAPH 2006 (TOG 25(3)).
///
/// variant 0 (boundary sampling): each sample, taken from the front in
/// insertion order, keeps the part of the circle of radius `radius` around it
/// that lies outside every other disk (a set of arcs, the one-dimensional case
/// of the paper's scalloped region); new samples are drawn uniformly on those
/// arcs until none is left.
/// variant 1 (scalloped sectors): a random front sample keeps the free part of
/// its annulus radius..2 radius as scalloped sectors with exact areas; new
/// samples are drawn uniformly over it (sector by area, then angle and radius)
/// until it is empty. Maximal up to 1e-11 radius; about 5% denser than
/// saturated dart throwing (rho about 0.80 against 0.78; it fills one annulus
/// at a time), while boundary sampling is 25% denser.
/// variant 2: the same sectors, but each new sample is drawn uniformly over
/// the union of every sample's free annulus (front sample by area through a
/// sum tree, 1 / multiplicity acceptance): maximal, with the density,
/// nearest-neighbour distances and spectrum of maximal dart throwing within
/// statistical error (rho about 0.776); O(N log N).
/// Guarantees: all pairs at least `radius` apart; every point in [lo, hi);
/// maximal up to 1e-10 radius: every point of the domain lies within
/// radius * (1 + 1e-10) of a sample; same seed, same points. The set is denser
/// and more regular than maximal dart throwing (rho about 0.87 rather than
/// 0.78, every nearest neighbour at distance radius; see
/// docs/dunbar-humphreys.md). 2D only.
/// Invalid: a radius that is not positive and finite, one whose densest
/// packing exceeds max_points, on a torus a period of 4 radius or less (6 for
/// variants 1 and 2), a variant other than 0, 1 or 2.
PointSet<2> dunbar_humphreys(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed);

namespace detail {
/// Whether this build and processor have boundary sampling's AVX-512
/// neighbourhood kernel (x86-64 at the x86-64-v4 level: AVX-512 F, BW, CD, DQ,
/// VL); dunbar_humphreys uses it when they do.
bool dunbar_humphreys_has_vector_kernel();
/// Boundary sampling (variant 0) with the vector kernel or the scalar one:
/// the same points, bit for bit (for the test that says so). Asking for the
/// vector kernel where there is none throws InvalidArgument.
PointSet<2> dunbar_humphreys_boundary(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed,
                                      bool vector_kernel);
/// The free arcs (start, length in diamond measure; detail/diamond_arcs.h)
/// of the circle of radius r(1 + 1e-10) around p that the given neighbours
/// (at most 32, plain offsets) leave, by the chosen kernel: for the test that
/// both kernels agree bit for bit on neighbourhoods of any size.
std::vector<std::array<double, 2>> dunbar_humphreys_free_arcs(const Point<2>& p, const PointSet<2>& neighbours,
                                                              double radius, bool vector_kernel);
}  // namespace detail

}  // namespace pds
