// Halton sequence.
//
// J. H. Halton, On the efficiency of certain quasi-random sequences of points
// in evaluating multi-dimensional integrals, Numerische Mathematik 2, 1960.
// Scrambling: J. Matousek, On the L2-discrepancy for anchored boxes, J.
// Complexity 14, 1998 (random digit permutation); A. B. Owen, Randomly permuted
// (t,m,s)-nets and (t,s)-sequences, 1995 (nested scrambling).
//
// Method: axis k of point i is the radical inverse of i in base p_k, the k-th
// prime; digits are exact integers (low_discrepancy.h), so the unscrambled
// sequence is exact and any index range is computed directly.
// Guarantees: the first N points have star discrepancy O(log^D N / N); in 2D
// the first 2^a 3^b points stratify the 2^a x 3^b grid exactly.
// Complexity: O(count * D), a few operations a coordinate; Owen scrambling
// walks the K digits of a coordinate (K = 32, 21, 14 for bases 2, 3, 5) with a
// hash per node (base 2: per 6 levels).
// Why not GSL's gsl_qrng_halton: it only steps forward from index 1, has no
// scrambling and sums digits in floating point (a few ulps off the exact
// values); the tests use it as a reference.
// Limits: indices below 2^32; higher axes (large primes) correlate visibly in
// short prefixes, which is why renderers scramble them.

#include "pds/samplers/halton.h"

namespace pds {

template <int D>
PointSet<D> halton(const HaltonParams& params, const Domain<D>& domain, std::uint64_t seed) {
  static_assert(D <= static_cast<int>(kPrimes.size()));
  require_index_range("halton", params.first, params.count);
  std::array<std::uint64_t, D> keys;
  for (int a = 0; a < D; ++a) keys[a] = scramble_key(seed, 1, a);
  PointSet<D> points(params.count);
  fill_radical_inverse_points<D>(points, static_cast<std::uint32_t>(params.first), params.scramble, keys, domain,
                                 [](std::uint32_t, Point<D>&) {});
  return points;
}

template PointSet<2> halton<2>(const HaltonParams&, const Domain<2>&, std::uint64_t);
template PointSet<3> halton<3>(const HaltonParams&, const Domain<3>&, std::uint64_t);

}  // namespace pds
