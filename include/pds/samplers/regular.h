#pragma once
// The regular grid: points at the centres of equal cells.

#include <array>
#include <cstdint>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

struct RegularParams {
  std::array<int, kMaxDim> cells{1, 1, 1, 1, 1, 1, 1, 1};  // cells per axis (the first D are used), each >= 1
  // Optional progress (points made, against their number) and cancellation (pds/progress.h).
  Progress progress;
};

/// One point at the centre of each cell, axis 0 varying fastest.
/// Guarantees: exactly prod(cells) points, in [lo, hi); the minimum distance
/// is the smallest cell edge (on a torus too: the cells divide the period).
/// Deterministic: there is no randomness.
/// Invalid: a cell count below 1.
template <int D>
PointSet<D> regular(const RegularParams& params, const Domain<D>& domain);

}  // namespace pds
