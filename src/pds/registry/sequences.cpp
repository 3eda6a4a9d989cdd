// Registry entries of the low-discrepancy sequences, with the `scramble`
// and `first` parameters they share.
#include <algorithm>

#include "descriptors.h"
#include "pds/samplers/halton.h"
#include "pds/samplers/hammersley.h"
#include "pds/samplers/low_discrepancy.h"
#include "pds/samplers/sobol.h"

namespace pds::registry_detail {
namespace {

MethodParam scramble_param() {
  return {.name = "scramble",
          .default_value = 0,
          .min = 0,
          .max = 2,
          .integer = true,
          .help = "0: the exact sequence (no seed); 1: random digit permutation; 2: Owen scrambling (1, 2 use --seed)"};
}

MethodParam first_param() {
  return {.name = "first",
          .default_value = 0,
          .min = 0,
          .max = static_cast<double>(kSequenceIndexLimit - 1),
          .integer = true,
          .help = "index of the first point: --count points from here continue an earlier run"};
}

/// The entry of a sequence that takes `first` and `scramble` (Halton, Sobol):
/// every field but its name, summary and paper is the same.
template <class Params>
Method sequence_method(std::string name, std::string summary, std::string citation,
                       PointCloud (*run)(const GenerateRequest&)) {
  return Method{.name = std::move(name),
                .family = Family::sequence,
                .docs = "docs/low-discrepancy.md",
                .summary = std::move(summary),
                .citation = std::move(citation),
                .takes_count = true,
                .exact_count = true,
                .progressive = true,
                .deterministic = true,
                .params = {scramble_param(), first_param()},
                .run = run};
}

/// Params{count, first, scramble} from the request, for `sample`.
template <class Params, class Sample>
PointCloud run_sequence(const GenerateRequest& r, const char* name, Sample sample) {
  return run_typed(r, [&](const auto& domain) {
    const Params params{.count = *r.count,
                        .first = static_cast<std::uint64_t>(r.param("first", 0)),
                        .scramble = scramble_from(name, static_cast<int>(r.param("scramble", 0)))};
    return sample(params, domain, r.seed);
  });
}

}  // namespace

const Method& halton_method() {
  static const Method method = sequence_method<HaltonParams>(
      "halton", "Halton sequence (radical inverses in bases 2, 3, 5), optionally scrambled",
      "J. H. Halton, On the efficiency of certain quasi-random sequences of points in evaluating "
      "multi-dimensional integrals, Numerische Mathematik 2, 1960",
      [](const GenerateRequest& r) {
        return run_sequence<HaltonParams>(
            r, "halton", [](const auto& p, const auto& d, std::uint64_t seed) { return halton(p, d, seed); });
      });
  return method;
}

const Method& hammersley_method() {
  static const Method method{
      .name = "hammersley",
      .family = Family::sequence,
      .docs = "docs/low-discrepancy.md",
      .summary = "Hammersley set (i/N, radical inverses in bases 2, 3), optionally scrambled",
      .citation =
          "J. M. Hammersley, Monte Carlo methods for solving multivariable problems, Annals of the New York "
          "Academy of Sciences 86, 1960",
      .takes_count = true,
      .exact_count = true,
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

const Method& sobol_method() {
  static const Method method = sequence_method<SobolParams>(
      "sobol", "Sobol sequence (Joe-Kuo direction numbers, Gray-code order), optionally Owen-scrambled",
      "I. M. Sobol, On the distribution of points in a cube and the approximate evaluation of integrals, "
      "USSR Comput. Math. Math. Phys. 7(4), 1967; S. Joe and F. Y. Kuo, SIAM J. Sci. Comput. 30(5), 2008",
      [](const GenerateRequest& r) {
        return run_sequence<SobolParams>(
            r, "sobol", [](const auto& p, const auto& d, std::uint64_t seed) { return sobol(p, d, seed); });
      });
  return method;
}

}  // namespace pds::registry_detail
