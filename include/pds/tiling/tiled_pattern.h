#pragma once
// Covering the image plane with copies of one toroidal tile (Mitchell 1991;
// pbrt's best-candidate sampler, Pharr & Humphreys 2004, section 7.5).
//
// A tile is a point set on the unit torus [0,1)^2: computed once, offline if
// need be, with any method run with periodic distances, so that its minimum
// distance holds across its own seams. TiledPattern translates and scales it:
// copy (i, j) occupies the square [i*S, (i+1)*S) x [j*S, (j+1)*S) of the
// plane, in pixels, where S = sqrt(M / spp) for a tile of M points and a
// density of spp samples per pixel. A query returns the samples inside any
// rectangle from the tiles it overlaps only, so the rest of the (infinite)
// plane is never generated.
//
// Guarantees:
//  - the same tile, spp and seed give the same samples, in the same order, for
//    the same rectangle; a sample has the same coordinates whichever
//    rectangle it is found through;
//  - any axis-aligned square of S x S pixels holds exactly M samples, and any
//    rectangle of area A holds spp * A samples within count_bound() of it;
//  - the plane's minimum distance is S times the tile's toroidal minimum
//    distance for M >= 2 (the seams add no closer pair; a one-point tile
//    gives a square grid of spacing S).
// Limits: the plane is exactly periodic with period S, which puts spikes in
// the spectrum at multiples of 1/S cycles per pixel (docs/tiling.md).
//
// Extra dimensions (time, lens position, ...): sample i of the tile carries,
// in each extra dimension, a value of a Latin hypercube over the tile (one
// per stratum of width 1/M, the strata shuffled per dimension); each copy
// adds its own random offset modulo 1 (a Cranley-Patterson rotation drawn from
// (seed, tile index)), so copies do not repeat each other in those dimensions.

#include <cstdint>
#include <vector>

#include "pds/point.h"

namespace pds {

/// An axis-aligned rectangle [x0, x1) x [y0, y1) of the image plane, in pixels.
struct PixelRect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double area() const { return (x1 - x0) * (y1 - y0); }
  bool contains(double x, double y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

struct TiledPatternOptions {
  int extra_dims = 0;      // values per sample beyond (x, y), 0..kMaxExtraDims
  std::uint64_t seed = 0;  // fixes the extra dimensions' strata and per-copy offsets
};

class TiledPattern {
 public:
  static constexpr int kMaxExtraDims = 16;
  /// The plane stays addressable to this many tiles from the origin in each
  /// direction; farther rectangles are rejected (coordinates lose precision).
  static constexpr double kMaxTileIndex = 1e12;

  /// `tile`: at least one point, every coordinate in [0, 1). `spp`: samples per
  /// pixel, positive and finite. Throws InvalidArgument naming the problem.
  TiledPattern(PointSet<2> tile, double spp, TiledPatternOptions options = {});

  std::size_t tile_count() const { return tile_.size(); }
  double spp() const { return spp_; }
  int extra_dims() const { return options_.extra_dims; }
  /// S: the side of one copy, in pixels.
  double tile_size() const { return tile_size_; }

  /// Appends the positions of the samples with x0 <= x < x1, y0 <= y < y1, and
  /// (if `extra` is given) their extra-dimension values, extra_dims() per sample.
  void samples_in(const PixelRect& rect, std::vector<Point<2>>& positions, std::vector<double>* extra = nullptr) const;

  /// The tile's points (sorted by the pattern's internal bins).
  const PointSet<2>& tile() const { return tile_; }

  /// A bound on |count(rect) - spp * area(rect)| for any rectangle, given the
  /// tile's torus discrepancy E (torus_rectangle_discrepancy(tile())). Split
  /// the rectangle, which spans nx + f_x by ny + f_y copies, into nx * ny
  /// squares of S x S (exactly M samples each), nx strips of S x f_y S, ny
  /// strips of f_x S x S and one corner: each strip and the corner is a torus
  /// rectangle, off by at most E. So the bound is (nx + ny + 1) * E.
  double count_bound(const PixelRect& rect, double discrepancy) const;

 private:
  void check(const PixelRect& rect) const;

  PointSet<2> tile_;                      // sorted by bin
  std::vector<std::uint32_t> bin_start_;  // bins_ * bins_ + 1 offsets into tile_
  std::vector<double> extra_base_;        // extra_dims values per tile point
  int bins_ = 1;
  double spp_ = 1;
  double tile_size_ = 1;
  TiledPatternOptions options_;
};

/// E: the largest |count - M * area| over the rectangles of the unit torus
/// (sides at most 1, intervals may wrap) for M points in [0,1)^2, exactly, by a
/// sweep over x-intervals in O(M^3) time. Throws InvalidArgument for more than
/// kMaxDiscrepancyPoints points. E >= 1 for any non-empty set (a vanishing
/// rectangle around one point).
double torus_rectangle_discrepancy(const PointSet<2>& points);
inline constexpr std::size_t kMaxDiscrepancyPoints = 1024;  // about 30 s on this machine

/// The same by direct enumeration of every candidate rectangle (O(M^5)); a
/// test oracle for small sets.
double torus_rectangle_discrepancy_brute_force(const PointSet<2>& points);

}  // namespace pds
