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

const Method& hammersley_method() {
  static const Method method{
      .name = "hammersley",
      .summary = "Hammersley set (i/N, radical inverses in bases 2, 3), optionally scrambled",
      .citation =
          "J. M. Hammersley, Monte Carlo methods for solving multivariable problems, Annals of the New York "
          "Academy of Sciences 86, 1960",
      .takes_count = true,
      .deterministic = true,
      .params = {scramble_param(),
                 first_param(),
                 {.name = "size",
                  .default_value = 0,
                  .min = 0,
                  .max = static_cast<double>(kSequenceIndexLimit),
                  .integer = true,
                  .help = "N, the size of the whole set when --count asks for a part of it (0: first + count)"}},
      .run =
          [](const GenerateRequest& r) {
            return run_typed(r, [&](const auto& domain) {
              const HammersleyParams params{
                  .count = *r.count,
                  .first = static_cast<std::uint64_t>(r.param("first", 0)),
                  .size = static_cast<std::uint64_t>(r.param("size", 0)),
                  .scramble = scramble_from("hammersley", static_cast<int>(r.param("scramble", 0)))};
              return hammersley(params, domain, r.seed);
            });
          },
  };
  return method;
}

}  // namespace pds
