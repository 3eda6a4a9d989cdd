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
// Complexity: O(N D) time, O(N) extra memory for one permutation at a time.
// Limits: the projections are perfectly stratified, the joint distribution is
// not (the whole set may cluster); multi-jittered adds the joint strata.

#include "pds/samplers/latin_hypercube.h"

#include <bit>
#include <cmath>
#include <numeric>

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

template <int D>
PointSet<D> latin_hypercube(const LatinHypercubeParams& params, const Domain<D>& domain, std::uint64_t seed) {
  const std::uint64_t n = params.count;
  if (n < 1 || n > (std::uint64_t{1} << 32))
    throw InvalidArgument("latin-hypercube: count must be in [1, 2^32], got " + std::to_string(n));
  PointSet<D> points(n);
  for (int a = 0; a < D; ++a) {
    Rng permute(seed, {0, static_cast<std::uint64_t>(a)});
    Rng jitter(seed, {1, static_cast<std::uint64_t>(a)});
    const std::vector<std::uint32_t> slab = random_permutation(static_cast<std::uint32_t>(n), permute);
    const SlabJitter within(n);
    for (std::uint64_t i = 0; i < n; ++i) points[i][a] = within(slab[i], jitter);
  }
  map_to_domain(points, domain);
  return points;
}

template PointSet<2> latin_hypercube<2>(const LatinHypercubeParams&, const Domain<2>&, std::uint64_t);
template PointSet<3> latin_hypercube<3>(const LatinHypercubeParams&, const Domain<3>&, std::uint64_t);

}  // namespace pds
