#pragma once
// The Halton sequence (Halton 1960): axis k of point i is the radical inverse
// of i in the k-th prime base (2, 3, 5, ...), optionally scrambled.

#include <cstdint>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/samplers/low_discrepancy.h"

namespace pds {

struct HaltonParams {
  std::uint64_t count = 1024;  // points returned, >= 1
  std::uint64_t first = 0;     // index of the first point; first + count <= 2^32
  Scramble scramble = Scramble::none;
  /// Unscrambled only: SciPy's arithmetic (the default: equal to
  /// scipy.stats.qmc.Halton(d, scramble=False), whose sums of digit * b^-k
  /// are a few ulps off the exact values) or the correctly rounded radical
  /// inverses.
  RadicalRounding rounding = RadicalRounding::scipy;
  // Optional progress (points written, against the count) and cancellation (pds/progress.h).
  Progress progress;
};

/// The most axes: one prime base each.
inline constexpr int kHaltonMaxDim = kRadixPrimes;

/// Points first, ..., first + count - 1 of the D-dimensional Halton sequence,
/// mapped from the unit cube to the domain (a torus changes nothing). Point 0
/// is the origin (lo), as in SciPy: index i here is SciPy's row i.
/// Progressive: any range costs only its own length.
/// Guarantees: unscrambled, point i is (phi_2(i), phi_3(i), ...) as SciPy
/// computes it (rounding scipy) or correctly rounded (rounding correct),
/// whatever the seed; for N = 2^a 3^b points in 2D every
/// box [j 2^-a, (j+1) 2^-a) x [l 3^-b, (l+1) 3^-b) holds exactly one point,
/// and scrambling keeps that. Every point in [lo, hi); same seed, same points.
/// Invalid: first + count above 2^32.
template <int D>
PointSet<D> halton(const HaltonParams& params, const Domain<D>& domain, std::uint64_t seed);

/// The same in a run-time dimension, 1 to kHaltonMaxDim (box.dim()), point
/// after point; the typed version is this one.
PointCloud halton(const HaltonParams& params, const CloudBox& box, std::uint64_t seed);
/// Writes the points to out (count * box.dim() doubles).
void halton_fill(const HaltonParams& params, const CloudBox& box, std::uint64_t seed, double* out);

}  // namespace pds
