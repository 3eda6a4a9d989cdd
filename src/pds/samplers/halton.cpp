// Halton sequence.
//
// J. H. Halton, On the efficiency of certain quasi-random sequences of points
// in evaluating multi-dimensional integrals, Numerische Mathematik 2, 1960.
// Scrambling: J. Matousek, On the L2-discrepancy for anchored boxes, J.
// Complexity 14, 1998 (random digit permutation); A. B. Owen, Randomly permuted
// (t,m,s)-nets and (t,s)-sequences, 1995 (nested scrambling).
//
// Method: axis k of point i is the radical inverse of i in base p_k, the k-th
// prime (fill_radical_inverses, one code path for every dimension); digits
// are exact integers (low_discrepancy.h), so scrambling is exact and any index
// range is computed directly. Unscrambled, the default sums the digits as
// SciPy does (equal to scipy.stats.qmc.Halton(d, scramble=False) bit for bit);
// rounding=correct gives the correctly rounded radical inverses instead.
// Guarantees: the first N points have star discrepancy O(log^D N / N); in 2D
// the first 2^a 3^b points stratify the 2^a x 3^b grid exactly.
// Complexity: O(count * D), a few operations a coordinate; Owen scrambling
// walks the K digits of a coordinate (K = 32, 21, 14 for bases 2, 3, 5) with a
// hash per node (base 2: per 6 levels).
// Why not GSL's gsl_qrng_halton: it only steps forward from index 1, has no
// scrambling and sums digits in floating point (its own order, a few ulps off
// the exact values); the tests use it as a reference.
// Limits: indices below 2^32; 10,000 axes (the first 10,000 primes); higher axes (large primes) correlate visibly in
// short prefixes, which is why renderers scramble them.

#include "pds/samplers/halton.h"

#include "mapped_pages.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"

namespace pds {

void halton_fill(const HaltonParams& params, const CloudBox& box, std::uint64_t seed, double* out) {
  const int dim = box.dim();
  if (dim < 1 || dim > kHaltonMaxDim)
    throw InvalidArgument("halton: dimension " + std::to_string(dim) + " is not supported (supported: 1 to " +
                          std::to_string(kHaltonMaxDim) + ", one prime base per axis)");
  require_index_range("halton", params.first, params.count);
  ProgressReporter progress(params.progress, static_cast<double>(params.count));
  fill_radical_inverses(static_cast<std::uint32_t>(params.first), params.count, dim, 0, params.scramble,
                        params.rounding, seed, 1, BoxMap(box), out, &progress);
  progress.finish();
}

PointCloud halton(const HaltonParams& params, const CloudBox& box, std::uint64_t seed) {
  return fill_cloud("halton", params.count, box, [&](double* out) { halton_fill(params, box, seed, out); });
}

template <int D>
PointSet<D> halton(const HaltonParams& params, const Domain<D>& domain, std::uint64_t seed) {
  require_index_range("halton", params.first, params.count);
  PointSet<D> points = detail::output_points<D>(params.count);
  halton_fill(params, CloudBox::of(domain), seed, points.data()->data());
  return points;
}

#define PDS_INSTANTIATE(D) template PointSet<D> halton<D>(const HaltonParams&, const Domain<D>&, std::uint64_t);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
