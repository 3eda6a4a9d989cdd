#pragma once
// Bridson's fast Poisson disk sampling: grow the set from one random sample,
// trying k random candidates in the annulus [r, 2r] around a random active
// sample (R. Bridson, Fast Poisson disk sampling in arbitrary dimensions,
// SIGGRAPH 2007 sketches).

#include <cstdint>
#include <optional>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

/// Relative radius that --count without --radius asks for (radius_for_count);
/// below what a finished Bridson set reaches (0.70 and above, docs/bridson.md),
/// so the set holds the count with room to spare.
inline constexpr double kBridsonCountRho = 0.65;

struct BridsonParams {
  double radius = 0.0;                 // minimum distance between samples, > 0
  int k = 30;                          // candidates around a picked active sample (see scipy), >= 1
  std::optional<std::uint64_t> count;  // return exactly this many (see below)
  /// Candidates on the sphere of radius kSurfaceRadius * radius around the
  /// active sample instead of uniform in the annulus [r, 2r] (SciPy's
  /// PoissonDisk(hypersphere="surface")): each new sample lands just beyond
  /// the radius of one other, a denser set (2D torus, r = 0.02: 2,031
  /// points at relative radius 0.84 against 1,536 at 0.73).
  bool surface = false;
  /// SciPy's loop (scipy.stats.qmc.PoissonDisk) instead of Bridson's: a
  /// picked active sample leaves the pool at once, after exactly k
  /// candidates uniform in the ball of radius 2r (on the sphere with
  /// `surface`), and every free one of them is kept. Bridson's stops at the
  /// first free candidate and keeps the sample active until k fail in a row.
  /// SciPy's law (to 4 dimensions: past them SciPy's neighbour search
  /// misses conflicts), fewer candidates (2D: k 3/4 tried a sample against
  /// about 1.2 k), slightly fewer samples.
  bool scipy = false;
  /// Optional progress (samples placed, against an estimate of the total;
  /// with a count, each radius tried and the final elimination in turn) and
  /// cancellation (pds/progress.h).
  Progress progress;
};

/// The candidates' sphere with BridsonParams::surface, in radii: just beyond
/// r so that rounding never rejects a candidate for being at exactly r (as SciPy).
inline constexpr double kSurfaceRadius = 1.001;

/// Guarantees: no two samples closer than `radius` (checked in the exact
/// double arithmetic of Domain::distance2, so the all-pairs oracle agrees),
/// every sample in [lo, hi); same seed, same points. Without a count the loop
/// runs until no active sample is left (it ends: each round either adds a
/// sample, of which at most the packing bound fit, or retires one), and the
/// set is then near-maximal (not proven maximal: k candidates can all miss a
/// gap). Output order is generation order, which grows outward from the first
/// sample: a prefix is not spread over the domain.
/// With a count N: the radius is searched upward from `radius` until a finished
/// set holds N to 1.02 N samples (at most 8 sets; each radius tried is at
/// least `radius`, so the minimum distance holds), and weighted sample
/// elimination (samplers/elimination.h) removes the surplus from the most
/// crowded places; exactly N samples, in generation order, with the spectrum
/// of a finished set. Fewer than N at `radius` is InvalidArgument. A radius
/// larger than the domain is valid: one sample.
/// Invalid (InvalidArgument): radius not positive and finite, k < 1, a count
/// of 0 or one that does not fit, more than kMaxGridCells background cells.
template <int D>
PointSet<D> bridson(const BridsonParams& params, const Domain<D>& domain, std::uint64_t seed);

}  // namespace pds
