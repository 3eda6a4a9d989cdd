// Registry entries of the elementary patterns: white noise, the regular
// grid and the stratified designs.
#include <algorithm>

#include "descriptors.h"
#include "pds/error.h"
#include "pds/samplers/jittered.h"
#include "pds/samplers/latin_hypercube.h"
#include "pds/samplers/multi_jittered.h"
#include "pds/samplers/random.h"
#include "pds/samplers/regular.h"
#include "pds/samplers/strata.h"

namespace pds::registry_detail {
namespace {

/// The request's box in its run-time dimension (validated by generate()).
CloudBox box_of(const GenerateRequest& r) {
  CloudBox box;
  r.bounds(box.lo, box.hi);
  return box;
}

}  // namespace

const Method& white_noise_method() {
  static const Method method{
      .name = "random",
      .family = Family::white_noise,
      .docs = "docs/low-discrepancy.md",
      .summary = "uniform white noise (a Poisson point pattern): independent uniform points",
      .takes_count = true,
      .exact_count = true,
      .compare = true,
      .dims = {1, kMaxCloudDim},
      .memory_ratio = 1,
      .run = [](const GenerateRequest& r) { return white_noise({*r.count, r.progress}, box_of(r), r.seed); },
  };
  return method;
}

const Method& regular_method() {
  static const Method method{
      .name = "regular",
      .family = Family::stratified,
      .docs = "docs/low-discrepancy.md",
      .summary = "regular grid of cell centres; --count N (near-cubic cells) or --radius R (spacing >= R)",
      .takes_count = true,
      .takes_radius = true,
      .min_distance = true,
      .exact_count = true,
      .deterministic = true,
      .dims = {kMinDim, kMaxDim},
      .memory_ratio = 2,
      .run =
          [](const GenerateRequest& r) {
            return run_typed<kMinDim, kMaxDim>(r, [&](const auto& domain) {
              constexpr int D = std::decay_t<decltype(domain.lo)>::dim;
              if (r.count && r.radius) throw InvalidArgument("regular: give --count or --radius, not both");
              const auto cells = r.count ? strata_for_count(domain, *r.count) : strata_for_spacing(domain, *r.radius);
              RegularParams params;
              std::copy(cells.begin(), cells.end(), params.cells.begin());
              params.progress = r.progress;
              double total = 1;
              for (int c : cells) total *= c;
              require_point_budget(total, D, r.max_points, "regular grid");
              return regular(params, domain);
            });
          },
  };
  return method;
}

const Method& jittered_method() {
  static const Method method{
      .name = "jittered",
      .family = Family::stratified,
      .docs = "docs/low-discrepancy.md",
      .summary = "uniform jitter: one uniform point in each cell of a grid of --count near-cubic strata",
      .citation = "R. L. Cook, Stochastic sampling in computer graphics, ACM TOG 5(1), 1986",
      .takes_count = true,
      .exact_count = true,
      .compare = true,
      .dims = {kMinDim, kMaxDim},
      .memory_ratio = 2,
      .run =
          [](const GenerateRequest& r) {
            return run_typed<kMinDim, kMaxDim>(r, [&](const auto& domain) {
              const auto cells = strata_for_count(domain, *r.count);
              JitteredParams params;
              std::copy(cells.begin(), cells.end(), params.cells.begin());
              params.progress = r.progress;
              return jittered(params, domain, r.seed);
            });
          },
  };
  return method;
}

const Method& multi_jittered_method() {
  static const Method method{
      .name = "multi-jittered",
      .family = Family::stratified,
      .docs = "docs/low-discrepancy.md",
      .summary = "(correlated) multi-jittered: one point per stratum of a near-cubic grid and per N-rooks slab",
      .citation =
          "K. Chiu, P. Shirley and C. Wang, Multi-jittered sampling, Graphics Gems IV, 1994; A. Kensler, "
          "Correlated multi-jittered sampling, Pixar Technical Memo 13-01, 2013",
      .takes_count = true,
      .exact_count = true,
      .dims = {kMinDim, kMaxDim},
      .memory_ratio = 2,
      .params = {{.name = "correlated",
                  .default_value = 1,
                  .min = 0,
                  .max = 1,
                  .integer = true,
                  .help = "1: Kensler's correlated shuffle (one per axis); 0: Chiu et al.'s (one per column)"}},
      .run =
          [](const GenerateRequest& r) {
            return run_typed<kMinDim, kMaxDim>(r, [&](const auto& domain) {
              const auto cells = strata_for_count(domain, *r.count);
              MultiJitteredParams params;
              std::copy(cells.begin(), cells.end(), params.cells.begin());
              params.correlated = r.param("correlated", 1) != 0;
              params.progress = r.progress;
              return multi_jittered(params, domain, r.seed);
            });
          },
  };
  return method;
}

const Method& latin_hypercube_method() {
  static const Method method{
      .name = "latin-hypercube",
      .family = Family::stratified,
      .docs = "docs/low-discrepancy.md",
      .summary = "Latin hypercube (N-rooks): one point in every slab of every axis, random across axes",
      .citation = "M. D. McKay, R. J. Beckman and W. J. Conover, Technometrics 21(2), 1979",
      .takes_count = true,
      .exact_count = true,
      .dims = {1, kMaxCloudDim},
      // Measured 1.26 in 1D and 1.10 in 3D (scripts/peak_memory.py --dim).
      .memory_ratio = 1.5,
      .memory_ratio_from_dim = {{2, 1.25}},
      .run = [](const GenerateRequest& r) { return latin_hypercube({*r.count, r.progress}, box_of(r), r.seed); },
  };
  return method;
}

}  // namespace pds::registry_detail
