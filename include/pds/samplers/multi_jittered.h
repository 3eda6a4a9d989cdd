#pragma once
// Multi-jittered sampling (Chiu, Shirley & Wang 1994) and its correlated
// variant (Kensler 2013): jittered strata and N-rooks slabs at once.

#include <array>
#include <cstdint>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

struct MultiJitteredParams {
  // Strata per axis (the first D are used), each >= 1; N = their product.
  std::array<int, kMaxDim> cells{32, 32, 1, 1, 1, 1, 1, 1};
  bool correlated = true;  // Kensler: one shuffle per axis, not one per column (lower variance in practice)
  // Optional progress (points made, against N) and cancellation (pds/progress.h).
  Progress progress;
};

/// N = prod(cells) points, axis 0 varying fastest over the cells.
/// Guarantees: exactly one point in each of the N strata (jitter) and, along
/// every axis, exactly one point in each of the N slabs of width 1/N (N-rooks);
/// exact in the unit cube, in a box up to the rounding of lo + x * extent.
/// Every point in [lo, hi); same seed, same points.
/// Invalid: a stratum count below 1, or N above 2^32.
template <int D>
PointSet<D> multi_jittered(const MultiJitteredParams& params, const Domain<D>& domain, std::uint64_t seed);

}  // namespace pds
