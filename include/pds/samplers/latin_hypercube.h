#pragma once
// Latin hypercube sampling, the N-rooks pattern (McKay, Beckman & Conover
// 1979; Shirley 1991): each axis is cut into N equal slabs and every slab of
// every axis holds exactly one of the N points.

#include <cstdint>
#include <vector>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/rng.h"
#include "pds/samplers/low_discrepancy.h"

namespace pds {

struct LatinHypercubeParams {
  std::uint64_t count = 1024;  // N, >= 1 and <= 2^32
  // Optional progress (coordinates written, against count x dimension) and
  // cancellation (pds/progress.h).
  Progress progress;
};

/// N points; along each axis an independent uniformly random permutation
/// assigns the slabs, and each point is uniform within its slab.
/// Guarantees: along every axis, every slab [s/N, (s+1)/N) of the domain holds
/// exactly one point (exact in the unit cube; in a box up to the rounding of
/// lo + x * extent); every point in [lo, hi); same seed, same points.
/// No guarantee across axes: the points may lie near a diagonal.
/// Invalid: count 0 or above 2^32.
template <int D>
PointSet<D> latin_hypercube(const LatinHypercubeParams& params, const Domain<D>& domain, std::uint64_t seed);

/// The same in a run-time dimension (box.dim(), any), point after point; the
/// typed version is this one. Axis a's permutation and jitter come from
/// streams keyed by a alone, so the first axes do not depend on the dimension.
PointCloud latin_hypercube(const LatinHypercubeParams& params, const CloudBox& box, std::uint64_t seed);
void latin_hypercube_fill(const LatinHypercubeParams& params, const CloudBox& box, std::uint64_t seed, double* out);

/// Uniform coordinates within the slabs [s/n, (s+1)/n) of [0, 1), n < 2^40.
/// A coordinate is drawn from 2^b equally spaced values centred in the slab's
/// 2^b equal parts, b = 48 - bit_width(n), so it stays at least 2^-(b+1) slabs
/// from either edge: far more than the rounding of the division by n and of
/// any later multiplication by n, so floor(x * n) == s holds in doubles.
class SlabJitter {
 public:
  explicit SlabJitter(std::uint64_t n);
  double operator()(std::uint64_t slab, Rng& rng) const {
    const double u = (static_cast<double>(rng.next() >> shift_) + 0.5) * step_;
    return (static_cast<double>(slab) + u) / n_;
  }

 private:
  double n_, step_;
  int shift_;
};

/// A uniformly random permutation of 0 ... n-1 (Fisher-Yates with Rng::below).
std::vector<std::uint32_t> random_permutation(std::uint32_t n, Rng& rng);

}  // namespace pds
