#pragma once
// Parallel Poisson disk sampling (Wei 2008) on the CPU with TBB.

#include <cstdint>

#include "pds/domain.h"
#include "pds/limits.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

struct WeiParams {
  double radius = 0.01;  // minimum distance between samples, > 0
  // k: dart passes per level, >= 1. A pass is one unit of dart-throwing time:
  // each active (sub)cell receives a Poisson(1) number of darts at uniform
  // times in it (see windows).
  int trials = 2;
  // Grid levels, in [1, 10]: level 0 has cells of edge <= radius/sqrt(D); each
  // further level halves them and retries only in cells no single disk covers.
  // With the defaults the output has the density, nearest-neighbour distances
  // and radial spectrum of maximal dart throwing (measured, docs/wei.md);
  // fewer levels leave it less dense.
  int levels = 10;
  // Time windows per pass, in [1, 1000]: windows run in time order and the
  // phase groups in a random order inside each, so only darts of neighbouring
  // cells in the same window are ordered by group rather than time. 1 is a
  // pass in one go, whose first group fills a lattice (spectral spikes at
  // n0/3 cycles per extent); the spikes' power falls fast with windows and
  // grows with N (64 leaves none measurable at 7 10^5 points; docs/wei.md).
  // The darts are sorted by window, not re-visited, so the cost grows only
  // until each dart has a window of its own (64 costs about 1.5x 1 in CPU time
  // at 10^6 points, 1000 about 1.8x; docs/wei.md).
  int windows = 64;
  int threads = 0;                               // worker threads, 0 = all hardware threads; never changes the output
  std::uint64_t max_points = kDefaultMaxPoints;  // refuse radii whose densest packing exceeds this
  // Optional progress (per time window, between the parallel phases: level 0
  // counts for 90% of the total, the finer levels share the rest) and
  // cancellation (pds/progress.h).
  Progress progress;
};

/// The largest `levels` and `windows` wei accepts.
inline constexpr int kWeiMaxLevels = 10;
inline constexpr int kWeiMaxWindows = 1000;

/// L.-Y. Wei, "Parallel Poisson disk sampling", ACM SIGGRAPH 2008 (TOG 27(3)).
///
/// A grid of cells of edge <= radius/sqrt(D) (one sample per cell at most) is
/// split into phase groups whose cells are far enough apart that their darts
/// cannot conflict. Each of `trials` passes is cut into `windows` time
/// windows; every empty cell throws a Poisson number of darts at uniform times
/// in the pass, as dart throwing would, and in each window the groups run one
/// after another in a random order, the cells of a group in parallel. Finer
/// levels halve the cells and retry where no single disk covers a cell yet.
/// With the defaults the radial spectrum is maximal dart throwing's
/// (docs/wei.md). From 4 dimensions the phase groups are built on cells of
/// edge just over r that hold several samples each (2^D groups instead of
/// 4^D, a conflict test of at most 3^D cells instead of (2 sqrt(D) + 3)^D),
/// at the same dart rate; D runs to 8, but the open cells of the finer
/// levels grow about eightfold a dimension (docs/dimensions.md), and a
/// radius whose open cells would need more than 4 GiB is refused.
/// Guarantees: all pairs at least `radius` apart; every point in [lo, hi);
/// same seed, same points for every thread count (each cell's darts come from
/// (seed, level, cell, pass, window), never from the thread). Not maximal:
/// small gaps covered only by the union of several disks can remain (see
/// docs/wei.md for the measured coverage and rho).
/// Invalid: radius not positive/finite or over the point budget (or over the
/// memory bound from 4D), trials < 1,
/// levels outside [1, 10], windows outside [1, 1000], threads < 0.
template <int D>
PointSet<D> wei(const WeiParams& params, const Domain<D>& domain, std::uint64_t seed);

}  // namespace pds
