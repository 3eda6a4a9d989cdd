#pragma once
// An unbounded, chunk-invariant Poisson disk field: one random set on the whole
// plane (or 3-space) per seed, of which any axis-aligned region can be asked
// for, in any pieces, in any order, with the same samples every time.
// docs/unbounded.md explains the construction and what it guarantees.

#include <array>
#include <cstddef>
#include <cstdint>

#include "pds/domain.h"
#include "pds/limits.h"
#include "pds/point.h"

namespace pds {

struct UnboundedParams {
  double radius = 0.01;  // minimum distance between samples, > 0
  // Expected darts thrown per grid cell (cell edge radius/sqrt(D)) before the
  // cells still open are refined: it changes the work, never the samples'
  // law (the set is maximal for every value; docs/unbounded.md measures it).
  double darts_per_cell = 2.0;
  std::uint64_t max_points = kDefaultMaxPoints;  // refuse regions whose densest packing exceeds this
};

/// What one call to UnboundedField::sample did (measurements, not results).
struct UnboundedStats {
  std::size_t cells_touched = 0;  // cells whose darts were generated (region plus the reach outside it)
  std::size_t darts_settled = 0;  // darts decided (kept or rejected)
  int max_depth = 0;              // deepest chain of ever earlier darts that had to be decided
  int max_level = 0;              // deepest refinement level generated (0: none was needed)
  int margin_cells = 0;           // farthest touched cell outside the region's cells, in cells
                                  // (on a torus: of the wrapped cells, so up to the cells per axis)
};

/// Maximal random sequential adsorption (dart throwing run until no dart
/// fits) on the unbounded plane/space, defined locally so that it can be
/// evaluated in pieces.
///
/// Space is cut into cells of edge radius/sqrt(D), indexed by signed 64-bit
/// coordinates. Each cell owns a Poisson process of darts in time, rate one
/// per cell, until time darts_per_cell; after that, as in ebeida, the
/// sub-cells that no kept disk covers wholly are refined level by level, each
/// with its own stream of darts at the same rate per area, until none is open.
/// Every dart's time and position come from a hash of (seed, cell, level,
/// sub-cell, j). A dart is kept iff no kept dart within `radius` comes earlier
/// in the total order (time, cell, position). Deciding a dart, or whether a
/// sub-cell is open, needs only earlier darts nearby, recursively, so
/// sample(region) settles the darts of the region's cells and, lazily with
/// memoisation, exactly those outside it they depend on.
///
/// Guarantees: sample(region) returns the samples of the one infinite set that
/// lie in [lo, hi), whatever regions were asked for before or alongside (no
/// state is kept between calls; the object is immutable and thread-safe), in
/// lexicographic order of the coordinates; all pairs at least `radius` apart,
/// also across any chunk seams; maximal (every point within `radius` of a
/// sample, up to rounding of the coverage test), also across seams; the same
/// points for the same seed on every platform (portable logarithm, no libm);
/// the law of maximal dart throwing, whatever darts_per_cell.
/// On a torus (the second constructor) the same holds with wrapped cells and
/// distances: the set is maximal dart throwing on that torus.
/// Invalid: a radius that is not positive and finite; darts_per_cell outside
/// (0, 64]; a periodic or empty region; a region farther than 2^40 cells from
/// the origin (positions would lose precision); a region whose densest
/// packing exceeds max_points. Failure: a chain of dependent darts deeper
/// than kMaxUnboundedDepth, or a gap still open at kMaxUnboundedLevel (not
/// seen in testing).
template <int D>
class UnboundedField {
 public:
  UnboundedField(const UnboundedParams& params, std::uint64_t seed);

  /// The same construction on a torus (`torus.periodic` must be set): each
  /// axis of extent L is cut into n = floor(L sqrt(D) / radius) >= 5 cells
  /// that wrap, and distances wrap. sample() then takes boxes inside the
  /// torus. Invalid: fewer than 5 cells or more than 2^40 along an axis.
  UnboundedField(const UnboundedParams& params, std::uint64_t seed, const Domain<D>& torus);

  /// The samples in the box region.lo <= x < region.hi (region must not be
  /// periodic). `stats`, when given, receives the work done.
  PointSet<D> sample(const Domain<D>& region, UnboundedStats* stats = nullptr) const;

  double radius() const { return params_.radius; }
  /// The cells' edge along axis 0 (on a torus each axis has its own).
  double cell_edge() const { return edges_[0]; }
  std::uint64_t seed() const { return seed_; }

 private:
  UnboundedParams params_;
  std::uint64_t seed_;
  bool periodic_ = false;
  Domain<D> torus_{};                  // when periodic_
  std::array<double, D> edges_{};      // cell edge per axis
  std::array<std::int64_t, D> cells_{};  // cells per axis on the torus
};

/// The deepest refinement level (sub-cells of 2^-60 of a cell, far below the
/// rounding of any coordinate): a gap still open there cannot be closed in
/// double precision, and sample() throws Failure (not seen in testing).
inline constexpr int kMaxUnboundedLevel = 60;

/// The bound on the chain of ever earlier darts one decision may recurse
/// through (measured depths are at most 12: docs/unbounded.md); it keeps the
/// recursion's stack to about a megabyte, safe on any thread.
inline constexpr int kMaxUnboundedDepth = 4000;

}  // namespace pds
