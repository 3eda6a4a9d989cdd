#pragma once
// Uniform jitter (stratified sampling): the domain is split into a grid of
// equal strata and one uniform random point is drawn in each (Cook 1986).

#include <array>
#include <cstdint>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

struct JitteredParams {
  std::array<int, kMaxDim> cells{1, 1, 1, 1, 1, 1, 1, 1};  // strata per axis (the first D are used), each >= 1
  // Optional progress (points made, against their number) and cancellation (pds/progress.h).
  Progress progress;
};

/// One uniform point in each stratum, axis 0 varying fastest.
/// Guarantees: exactly prod(cells) points, exactly one in each stratum, all in
/// [lo, hi); same seed, same points. No minimum distance: neighbours in
/// adjacent strata can be arbitrarily close (the clusters that Cook 1986 and Mitchell 1991 note).
/// Invalid: a stratum count below 1.
template <int D>
PointSet<D> jittered(const JitteredParams& params, const Domain<D>& domain, std::uint64_t seed);

}  // namespace pds
