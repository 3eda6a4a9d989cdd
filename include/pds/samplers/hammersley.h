#pragma once
// The Hammersley point set (Hammersley 1960): point i of N is
// (i / N, phi_2(i), phi_3(i), ...), the Halton sequence with its first axis
// replaced by the index. A set of fixed size, not an extensible sequence.

#include <cstdint>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/samplers/low_discrepancy.h"

namespace pds {

struct HammersleyParams {
  std::uint64_t count = 1024;  // points returned, >= 1
  std::uint64_t first = 0;     // index of the first point returned
  std::uint64_t size = 0;      // N, the size of the whole set; 0 means first + count
  Scramble scramble = Scramble::none;
  // Optional progress (points written, against the count) and cancellation (pds/progress.h).
  Progress progress;
};

/// Points first, ..., first + count - 1 of the N-point Hammersley set, mapped
/// from the unit cube to the domain. Scrambling applies to axes 1 and up; axis
/// 0 (i / N) already has exactly one point in each slab of width 1/N.
/// Guarantees: unscrambled, exact (correctly rounded) and seed-independent;
/// in 2D with N = 2^m the set is a (0, m, 2)-net in base 2 (every elementary
/// box of volume 1/N holds one point), scrambled or not. Every point in
/// [lo, hi); same seed, same points.
/// Invalid: first + count above size, or above 2^32.
template <int D>
PointSet<D> hammersley(const HammersleyParams& params, const Domain<D>& domain, std::uint64_t seed);

/// The most axes: i / N, then one prime base each.
inline constexpr int kHammersleyMaxDim = kRadixPrimes + 1;

/// The same in a run-time dimension, 1 to kHammersleyMaxDim (box.dim()), point
/// after point; the typed version is this one.
PointCloud hammersley(const HammersleyParams& params, const CloudBox& box, std::uint64_t seed);
/// Writes the points to out (count * box.dim() doubles).
void hammersley_fill(const HammersleyParams& params, const CloudBox& box, std::uint64_t seed, double* out);

}  // namespace pds
