#pragma once
// Uniform random points: white noise, the "Poisson" pattern of
// E. Agu's CS 563 notes on Poisson disk sampling.

#include <cstdint>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/rng.h"
#include "pds/samplers/low_discrepancy.h"

namespace pds {

struct WhiteNoiseParams {
  std::uint64_t count = 1024;  // number of points, >= 1
  // Optional progress (points written, against the count) and cancellation (pds/progress.h).
  Progress progress;
};

/// `count` points drawn independently and uniformly from the domain.
/// Guarantees: every point in [lo, hi); exactly `count` points; same seed,
/// same points. No minimum distance: points cluster and leave holes.
/// Invalid: count 0 or above the point cap (checked by generate()).
template <int D>
PointSet<D> white_noise(const WhiteNoiseParams& params, const Domain<D>& domain, std::uint64_t seed);

/// The same in a run-time dimension (box.dim(), any), point after point,
/// coordinate after coordinate from one stream: the typed version is this one.
PointCloud white_noise(const WhiteNoiseParams& params, const CloudBox& box, std::uint64_t seed);
void white_noise_fill(const WhiteNoiseParams& params, const CloudBox& box, std::uint64_t seed, double* out);

/// A point drawn uniformly from the domain.
template <int D>
Point<D> uniform_point(Rng& rng, const Domain<D>& domain) {
  Point<D> p;
  for (int i = 0; i < D; ++i) p[i] = rng.uniform(domain.lo[i], domain.hi[i]);
  return p;
}

}  // namespace pds
