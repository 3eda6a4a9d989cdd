// Hammersley point set.
//
// J. M. Hammersley, Monte Carlo methods for solving multivariable problems,
// Annals of the New York Academy of Sciences 86, 1960.
//
// Method: point i of N is (i / N, phi_2(i), phi_3(i)); the radical inverses
// and their scrambling are those of the Halton sequence (low_discrepancy.h).
// Guarantees: star discrepancy O(log^(D-1) N / N), one log better than Halton
// because N is known in advance; in 2D with N = 2^m, a (0, m, 2)-net in base 2,
// and Owen or digit scrambling of axis 1 keeps it one (they permute digits of
// points sharing a prefix alike).
// Complexity: O(count * D). Limits: N fixed in advance (a prefix of the set is
// not well distributed along axis 0); N <= 2^32.

#include "pds/samplers/hammersley.h"

#include "pds/error.h"

namespace pds {

template <int D>
PointSet<D> hammersley(const HammersleyParams& params, const Domain<D>& domain, std::uint64_t seed) {
  static_assert(D - 1 <= static_cast<int>(kPrimes.size()));
  require_index_range("hammersley", params.first, params.count);
  const std::uint64_t size = params.size ? params.size : params.first + params.count;
  if (params.first + params.count > size)
    throw InvalidArgument("hammersley: points first " + std::to_string(params.first) + " + count " +
                          std::to_string(params.count) + " exceed the set's size " + std::to_string(size));
  std::array<std::uint64_t, D> keys;
  for (int a = 0; a < D; ++a) keys[a] = scramble_key(seed, 2, a);
  const double n = static_cast<double>(size);
  PointSet<D> points(params.count);
  fill_radical_inverse_points<D, 1>(points, static_cast<std::uint32_t>(params.first), params.scramble, keys, domain,
                                    [n](std::uint32_t index, Point<D>& u) { u[0] = static_cast<double>(index) / n; });
  return points;
}

template PointSet<2> hammersley<2>(const HammersleyParams&, const Domain<2>&, std::uint64_t);
template PointSet<3> hammersley<3>(const HammersleyParams&, const Domain<3>&, std::uint64_t);

}  // namespace pds
