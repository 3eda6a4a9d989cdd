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

/// The request's box in its run-time dimension (validated by generate()).
CloudBox box_of(const GenerateRequest& r) {
  CloudBox box;
  r.bounds(box.lo, box.hi);
  return box;
}

/// The entry of a sequence that takes `first` and `scramble` (Halton, Sobol):
/// every field but its name, summary, paper, dimensions and extra parameters
/// is the same.
Method sequence_method(std::string name, std::string summary, std::string citation, DimRange dims,
                       PointCloud (*run)(const GenerateRequest&), std::vector<MethodParam> extra = {}) {
  std::vector<MethodParam> params = {scramble_param(), first_param()};
  params.insert(params.end(), extra.begin(), extra.end());
  return Method{.name = std::move(name),
                .family = Family::sequence,
                .docs = "docs/low-discrepancy.md",
                .summary = std::move(summary),
                .citation = std::move(citation),
                .takes_count = true,
                .exact_count = true,
                .progressive = true,
                .deterministic = true,
                .dims = dims,
                .memory_ratio = 1.5,  // sobol 1.1-1.2 in 1D to 100D (scripts/peak_memory.py --dim)
                // Measured 280 bytes an axis (halton, hammersley; 10 points in
                // 10^4 dimensions) and 330 (sobol, scrambled; 21,201).
                .memory_per_axis = 400,
                .params = std::move(params),
                .run = run};
}

/// Params{count, first, scramble} from the request.
template <class Params>
Params sequence_params(const GenerateRequest& r, const char* name) {
  Params params;
  params.count = *r.count;
  params.first = static_cast<std::uint64_t>(r.param("first", 0));
  params.scramble = scramble_from(name, static_cast<int>(r.param("scramble", 0)));
  params.progress = r.progress;
  return params;
}

}  // namespace

const Method& halton_method() {
  static const Method method = sequence_method(
      "halton", "Halton sequence (radical inverses in the first primes, one per axis), optionally scrambled",
      "J. H. Halton, On the efficiency of certain quasi-random sequences of points in evaluating "
      "multi-dimensional integrals, Numerische Mathematik 2, 1960",
      {1, kHaltonMaxDim},
      [](const GenerateRequest& r) {
        auto params = sequence_params<HaltonParams>(r, "halton");
        params.rounding = r.param("rounding", 1) != 0 ? RadicalRounding::scipy : RadicalRounding::correct;
        return halton(params, box_of(r), r.seed);
      },
      {{.name = "rounding",
        .default_value = 1,
        .min = 0,
        .max = 1,
        .integer = true,
        .help = "unscrambled only: 1, SciPy's sums (equal to qmc.Halton(scramble=False)); 0, correctly rounded"}});
  return method;
}

const Method& hammersley_method() {
  static const Method method{
      .name = "hammersley",
      .family = Family::sequence,
      .docs = "docs/low-discrepancy.md",
      .summary = "Hammersley set (i/N, then radical inverses in the first primes), optionally scrambled",
      .citation =
          "J. M. Hammersley, Monte Carlo methods for solving multivariable problems, Annals of the New York "
          "Academy of Sciences 86, 1960",
      .takes_count = true,
      .exact_count = true,
      .deterministic = true,
      .dims = {1, kHammersleyMaxDim},
      .memory_ratio = 1.5,
      .memory_per_axis = 400,  // as the sequences above
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
            auto params = sequence_params<HammersleyParams>(r, "hammersley");
            params.size = static_cast<std::uint64_t>(r.param("size", 0));
            return hammersley(params, box_of(r), r.seed);
          },
  };
  return method;
}

const Method& sobol_method() {
  static const Method method = sequence_method(
      "sobol", "Sobol sequence (Joe-Kuo direction numbers, Gray-code order), optionally Owen-scrambled",
      "I. M. Sobol, On the distribution of points in a cube and the approximate evaluation of integrals, "
      "USSR Comput. Math. Math. Phys. 7(4), 1967; S. Joe and F. Y. Kuo, SIAM J. Sci. Comput. 30(5), 2008",
      {1, kSobolMaxDim},
      [](const GenerateRequest& r) { return sobol(sequence_params<SobolParams>(r, "sobol"), box_of(r), r.seed); });
  return method;
}

}  // namespace pds::registry_detail
