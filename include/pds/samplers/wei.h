#pragma once
// Parallel Poisson disk sampling (Wei 2008) on the CPU with TBB.

#include <cstdint>

#include "pds/domain.h"
#include "pds/limits.h"
#include "pds/point.h"
#include "pds/registry.h"

namespace pds {

struct WeiParams {
  double radius = 0.01;  // minimum distance between samples, > 0
  // k: dart passes per level, >= 1 (each pass visits every phase group, in a
  // random order, and throws one dart per empty cell). With levels = 5, k = 2
  // gives the density and nearest-neighbour distances of maximal dart throwing
  // (measured, docs/wei.md); more levels pack denser than dart throwing can.
  int trials = 2;
  // Grid levels, in [1, 10]: level 0 has cells of edge <= radius/sqrt(D); each
  // further level halves them and retries only in cells no single disk covers.
  int levels = 10;
  int windows = 16;
  int threads = 0;                               // worker threads, 0 = all hardware threads; never changes the output
  std::uint64_t max_points = kDefaultMaxPoints;  // refuse radii whose densest packing exceeds this
};

/// L.-Y. Wei, "Parallel Poisson disk sampling", ACM SIGGRAPH 2008 (TOG 27(3)).
///
/// A grid of cells of edge <= radius/sqrt(D) (one sample per cell at most) is
/// split into phase groups whose cells are far enough apart that their darts
/// cannot conflict. Each of `trials` passes visits the groups one after
/// another in a random order, the cells of a group in parallel, one dart per
/// empty cell. Finer levels halve the cells and retry where no single disk
/// covers a cell yet. The spectrum keeps spikes of the phase-group lattice
/// (docs/wei.md).
/// Guarantees: all pairs at least `radius` apart; every point in [lo, hi);
/// same seed, same points for every thread count (each cell's generator comes
/// from (seed, level, cell), never from the thread). Not maximal: small gaps
/// covered only by the union of several disks can remain (see docs/wei.md for
/// the measured coverage and rho).
/// Invalid: radius not positive/finite or over the point budget, trials < 1,
/// levels outside [1, 10], threads < 0.
template <int D>
PointSet<D> wei(const WeiParams& params, const Domain<D>& domain, std::uint64_t seed);

const Method& wei_method();

}  // namespace pds
