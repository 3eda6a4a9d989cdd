// Latin hypercube (N-rooks) sampling.
//
// M. D. McKay, R. J. Beckman and W. J. Conover, A comparison of three methods
// for selecting values of input variables in the analysis of output from a
// computer code, Technometrics 21(2), 1979. In graphics: P. Shirley,
// Discrepancy as a quality measure for sample distributions, Eurographics 1991
// ("N-rooks").
//
// Method: for each axis an independent uniform permutation pi_a of the N slabs;
// point i lies in slab pi_a(i) along axis a, uniformly within it.
// Guarantees: one point per slab on every axis (latin_hypercube.h).
// Complexity: O(N D) time, O(N) extra memory for one permutation at a time;
// one code path for every dimension (latin_hypercube_fill).
// Limits: the projections are perfectly stratified, the joint distribution is
// not (the whole set may cluster); multi-jittered adds the joint strata.

#include "pds/samplers/latin_hypercube.h"

#include <bit>
#include <cmath>
#include <numeric>

#include "mapped_pages.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"
#include "pds/samplers/low_discrepancy.h"

namespace pds {

SlabJitter::SlabJitter(std::uint64_t n) : n_(static_cast<double>(n)) {
  const int bits = 48 - std::bit_width(n);
  shift_ = 64 - bits;
  step_ = std::ldexp(1.0, -bits);
}

std::vector<std::uint32_t> random_permutation(std::uint32_t n, Rng& rng) {
  std::vector<std::uint32_t> p(n);
  std::iota(p.begin(), p.end(), 0u);
  for (std::uint32_t k = n; k > 1; --k) std::swap(p[k - 1], p[rng.below(k)]);
  return p;
}

void latin_hypercube_fill(const LatinHypercubeParams& params, const CloudBox& box, std::uint64_t seed, double* out) {
  const std::uint64_t n = params.count;
  if (n < 1 || n > (std::uint64_t{1} << 32))
    throw InvalidArgument("latin-hypercube: count must be in [1, 2^32], got " + std::to_string(n));
  const auto dim = static_cast<std::size_t>(box.dim());
  const BoxMap map(box);
  const SlabJitter within(n);
  // Axis after axis: progress counts coordinates.
  ProgressReporter progress(params.progress, static_cast<double>(n) * static_cast<double>(dim));
  for (std::size_t a = 0; a < dim; ++a) {
    Rng permute(seed, {0, static_cast<std::uint64_t>(a)});
    Rng jitter(seed, {1, static_cast<std::uint64_t>(a)});
    const std::vector<std::uint32_t> slab = random_permutation(static_cast<std::uint32_t>(n), permute);
    for (std::uint64_t i = 0; i < n; ++i) {
      if ((i & 65535) == 0) progress.update(static_cast<double>(a * n + i));
      out[i * dim + a] = map(static_cast<int>(a), within(slab[i], jitter));
    }
  }
  progress.finish();
}

PointCloud latin_hypercube(const LatinHypercubeParams& params, const CloudBox& box, std::uint64_t seed) {
  return fill_cloud("latin-hypercube", params.count, box, [&](double* out) { latin_hypercube_fill(params, box, seed, out); });
}

template <int D>
PointSet<D> latin_hypercube(const LatinHypercubeParams& params, const Domain<D>& domain, std::uint64_t seed) {
  if (params.count < 1 || params.count > (std::uint64_t{1} << 32))
    throw InvalidArgument("latin-hypercube: count must be in [1, 2^32], got " + std::to_string(params.count));
  PointSet<D> points = detail::output_points<D>(params.count);
  latin_hypercube_fill(params, CloudBox::of(domain), seed, points.data()->data());
  return points;
}

#define PDS_INSTANTIATE(D) \
  template PointSet<D> latin_hypercube<D>(const LatinHypercubeParams&, const Domain<D>&, std::uint64_t);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
