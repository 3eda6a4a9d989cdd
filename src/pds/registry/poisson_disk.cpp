// Registry entries of the classic Poisson disk methods: dart throwing,
// Bridson, best-candidate, weighted sample elimination; --count without
// --radius goes through the sizing policy.
#include <algorithm>
#include <cmath>
#include <limits>

#include "descriptors.h"
#include "pds/error.h"
#include "pds/limits.h"
#include "pds/samplers/best_candidate.h"
#include "pds/samplers/bridson.h"
#include "pds/samplers/constrained.h"
#include "pds/samplers/dart_throwing.h"
#include "pds/samplers/elimination.h"
#include "pds/samplers/sizing.h"

namespace pds::registry_detail {
namespace {

// --count alone: the sampler runs at the radius of the method's relative
// radius rho; in the rare case that fewer points fit (tiny counts, high
// dimensions), it retries at a 5% smaller radius, at most 20 times.
template <class Sample>
auto with_shrinking_radius(double& radius, Sample&& sample) {
  for (int attempt = 0;; ++attempt) {
    try {
      return sample(attempt);
    } catch (const InvalidArgument&) {
      if (attempt == 20) throw;
      radius *= 0.95;
    }
  }
}

// The three ways a radius-driven sampler runs: under constraints (a density,
// a mask or fixed points; the radius, if any, as given), at --radius, or at
// the radius of relative radius `rho` for --count alone.
// `sample(params)` and `constrained(params)` call the sampler.
template <class Params, int D, class Sample, class Constrained>
PointSet<D> run_radius_method(const GenerateRequest& r, const Domain<D>& domain, Params& params, double rho,
                              Sample&& sample, Constrained&& constrained) {
  if (r.constraints.active()) {
    params.radius = r.radius.value_or(0.0);
    return constrained(params);
  }
  if (r.radius) {
    params.radius = *r.radius;
    return sample(params);
  }
  params.radius = radius_for_count(*r.count, domain, rho);
  // Each attempt reports within its own share, so progress never goes back.
  Progress progress;
  if constexpr (requires { params.progress; }) progress = params.progress;
  return with_shrinking_radius(params.radius, [&](int attempt) {
    if constexpr (requires { params.progress; })
      params.progress = part_of(progress, static_cast<std::size_t>(attempt), 21);
    return sample(params);
  });
}

}  // namespace

const Method& dart_throwing_method() {
  static const Method method{
      .name = "dart-throwing",
      .family = Family::poisson_disk,
      .docs = "docs/dart-throwing.md",
      .summary =
          "Poisson disk by dart throwing (Cook's loop), grid-accelerated; --radius R runs until darts "
          "keep missing, --count N stops at N",
      .citation = "R. L. Cook, Stochastic sampling in computer graphics, ACM TOG 5(1), 1986",
      .takes_count = true,
      .takes_radius = true,
      .min_distance = true,
      .exact_count = true,
      .compare = true,
      .constraints = true,
      // Measured over seeds 1-5: 2D box 0.758-0.761, torus 0.750-0.753; 3D box
      // 0.795-0.803, torus 0.762-0.764 (random sequential adsorption jams at
      // 0.777 in 2D, 0.803 in 3D; a finite failure bound stops a little below).
      .dims = {kMinDim, kMaxDim},
      .rho = {{2, false, 0.02, 0.74, 0.78},
              {2, true, 0.02, 0.73, 0.77},
              {3, false, 0.08, 0.77, 0.83},
              {3, true, 0.08, 0.74, 0.79}},
      // Measured 2.0 in 1D and 2D and 2.7 in 3D (docs/reliability.md).
      .memory_ratio = 3.5,
      .params = {{"all-pairs", 0, 0, 1, true, "1: the literal check against every sample (same output, O(N) a dart)"},
                 {"failures", 0, 0, 1e15, true,
                  "consecutive rejected darts that end the loop; 0: max(10^4, packing bound at the radius)"},
                 {"rho", kDartCountRho, 0.01, 1, false,
                  "relative radius that sets the radius for --count without --radius"}},
      .run =
          [](const GenerateRequest& r) {
            return run_typed<kMinDim, kMaxDim>(r, [&](const auto& domain) {
              DartThrowingParams params;
              params.count = r.count;
              params.all_pairs = r.param("all-pairs", 0) != 0;
              params.max_failures = static_cast<std::uint64_t>(r.param("failures", 0));
              params.progress = r.progress;
              if (r.constraints.active() && params.all_pairs)
                throw InvalidArgument("dart-throwing: all-pairs=1 is not taken with a density, a mask or fixed points");
              return run_radius_method(
                  r, domain, params, r.param("rho", kDartCountRho),
                  [&](const auto& p) { return dart_throwing(p, domain, r.seed); },
                  [&](const auto& p) { return dart_throwing(p, r.constraints.typed(domain), domain, r.seed); });
            });
          },
  };
  return method;
}

const Method& bridson_method() {
  static const Method method{
      .name = "bridson",
      .family = Family::poisson_disk,
      .docs = "docs/bridson.md",
      .summary = "Bridson's fast Poisson disk sampling: k candidates in the annulus [r, 2r] around active samples",
      .citation = "R. Bridson, Fast Poisson disk sampling in arbitrary dimensions, SIGGRAPH 2007 sketches",
      .takes_count = true,
      .takes_radius = true,
      .min_distance = true,
      .exact_count = true,
      .compare = true,
      .constraints = true,
      // Measured over seeds 1-5: 2D box 0.732-0.739, torus 0.728-0.732; 3D box
      // 0.762-0.769, torus 0.738-0.745 (k = 30 leaves more gaps).
      .dims = {kMinDim, kMaxDim},
      .rho = {{2, false, 0.02, 0.71, 0.76},
              {2, true, 0.02, 0.71, 0.75},
              {3, false, 0.08, 0.74, 0.79},
              {3, true, 0.08, 0.72, 0.76}},
      // Measured 5.9 in 2D, 6.2 in 3D (over the estimate's typical count),
      // under 2 from 4D; with a count, its last set and then the elimination
      // of the surplus: 7.0 in 1D, 6.5 in 2D, 17.4 in 3D, 5.8 in 4D.
      .memory_ratio = 7.5,
      .memory_ratio_from_dim = {{4, 6}},
      .count_memory_ratio_from_dim = {{1, 8}, {3, 20}, {4, 7}},
      .params = {{"k", 30, 1, 1e6, true,
                  "candidates around a picked active sample: it retires after k fail in a row (with scipy=1: after k, "
                  "each tried once)"},
                 {"surface", 0, 0, 1, true,
                  "1: candidates on the sphere of radius 1.001 r, not in the annulus [r, 2r] (denser)"},
                 {"scipy", 0, 0, 1, true,
                  "1: SciPy's loop: a picked sample tries exactly k candidates in the ball of radius 2r once, "
                  "keeping every free one (faster, SciPy's law)"},
                 {"rho", kBridsonCountRho, 0.01, 1, false,
                  "relative radius that sets the radius for --count without --radius"}},
      .run =
          [](const GenerateRequest& r) {
            return run_typed<kMinDim, kMaxDim>(r, [&](const auto& domain) {
              BridsonParams params;
              params.k = static_cast<int>(r.param("k", 30));
              params.surface = r.param("surface", 0) != 0;
              params.scipy = r.param("scipy", 0) != 0;
              params.count = r.count;
              params.progress = r.progress;
              if (r.constraints.active() && params.surface)
                throw InvalidArgument("bridson: surface=1 is not taken with a density, a mask or fixed points");
              if (r.constraints.active() && params.scipy)
                throw InvalidArgument("bridson: scipy=1 is not taken with a density, a mask or fixed points");
              return run_radius_method(
                  r, domain, params, r.param("rho", kBridsonCountRho),
                  [&](const auto& p) { return bridson(p, domain, r.seed); },
                  [&](const auto& p) { return bridson(p, r.constraints.typed(domain), domain, r.seed); });
            });
          },
  };
  return method;
}

const Method& best_candidate_method() {
  static const Method method{
      .name = "best-candidate",
      .family = Family::poisson_disk,
      .docs = "docs/best-candidate.md",
      .summary = "Mitchell's best-candidate: each sample the farthest of m*i random candidates; progressive",
      .citation = "D. P. Mitchell, Spectrally optimal sampling for distribution ray tracing, SIGGRAPH 1991",
      .takes_count = true,
      .takes_radius = true,
      .min_distance = true,
      .exact_count = true,
      .progressive = true,
      .compare = true,
      // Measured over seeds 1-5 (m = 10; it stops at the first round whose best
      // candidate is closer than the radius): 2D box 0.746-0.750, torus
      // 0.729-0.740; 3D at r = 0.1, box 0.791-0.801, torus 0.747-0.749.
      .dims = {kMinDim, kMaxDim},
      .rho = {{2, false, 0.02, 0.71, 0.78},
              {2, true, 0.02, 0.70, 0.77},
              {3, false, 0.1, 0.76, 0.83},
              {3, true, 0.1, 0.72, 0.78}},
      // Measured 17.4 in 2D at 10^6 and 16.3 at 10^5, 14.8 in 1D at 10^5,
      // 67 in 3D at 10^4 and 49 at 3 10^4 (16 leaves a sample), under 1
      // from 4D (the literal method holds only the set).
      .memory_ratio = 22,
      .memory_ratio_from_dim = {{3, 90}, {4, 2}},
      .params = {{"m", kBestCandidateDefaultM, 1, 1000, true, "candidates per sample already placed"}},
      .run =
          [](const GenerateRequest& r) {
            return run_typed<kMinDim, kMaxDim>(r, [&](const auto& domain) {
              BestCandidateParams params;
              params.count = r.count;
              params.radius = r.radius;
              params.m = static_cast<int>(r.param("m", kBestCandidateDefaultM));
              params.progress = r.progress;
              return best_candidate(params, domain, r.seed);
            });
          },
  };
  return method;
}

const Method& elimination_method() {
  static const Method method{
      .name = "elimination",
      .family = Family::poisson_disk,
      .docs = "docs/elimination.md",
      .summary =
          "Yuksel's weighted sample elimination: from candidates x N white-noise points, remove the most crowded "
          "until N remain; exact count, progressive, no hard minimum distance",
      .citation = "C. Yuksel, Sample elimination for generating Poisson disk sample sets, Eurographics 2015",
      .takes_count = true,
      .exact_count = true,
      .progressive = true,
      .constraints = true,
      // 1 to 3: from 4D on, prefixes are less even than the progressive
      // conformance test asks (index of dispersion 0.60-0.79 in 4D-8D,
      // against below 0.6); the sampler itself takes every dimension.
      .dims = {1, 3},
      // Measured 13.4 in 1D, 9.6 in 2D, 8.4 in 3D (5N candidates, white
      // noise); 14.2 in 2D under a radius field (a scale a candidate, twice).
      .memory_ratio = 25,
      .memory_ratio_from_dim = {{2, 18}},
      .memory_scales_with = "candidates",  // the candidates are what takes the memory
      .params = {{"candidates", 5, 1, 100, false, "white-noise candidates as a multiple of the count"},
                 {"progressive", 1, 0, 1, true, "1: every prefix well spread (recursive halving); 0: candidate order"},
                 {"levels", 0, 0, 1, true,
                  "1: progressive order built coarse to fine, level by level, most points moved (prefixes at 1% "
                  "steps rho >= ~0.66, at about twice the time); 0: the paper's halvings (prefixes ~0.62)"},
                 {"alpha", 8, 0.1, 64, false, "exponent of the weight function"},
                 {"beta", 0.65, 0, 0.99, false, "weight limit d_min = d_max (1 - (N/M)^gamma) beta; 0: none"},
                 {"gamma", 1.5, 0.1, 10, false, "weight limit exponent"},
                 {"min_rho", 0.72, 0, 0.8, false,
                  "then move points of pairs closer than this relative radius apart; 0: the paper's set, a subset "
                  "of the candidates; not taken with a density, mask or mesh"}},
      .run =
          [](const GenerateRequest& r) {
            return run_typed<1, 3>(r, [&](const auto& domain) {
              EliminationParams params;
              // With a radius field and no count, the field sizes the set.
              params.count = r.count ? *r.count : 0;
              params.candidates = r.param("candidates", 5);
              params.progressive = r.param("progressive", 1) != 0;
              params.levels = r.param("levels", 0) != 0;
              params.weights.alpha = r.param("alpha", 8);
              params.weights.beta = r.param("beta", 0.65);
              params.weights.gamma = r.param("gamma", 1.5);
              params.min_rho = r.param("min_rho", 0.72);
              if (params.levels && (!params.progressive || params.min_rho == 0.0 || r.constraints.active()))
                throw InvalidArgument(
                    "elimination: levels=1 builds the progressive order with the moves of min_rho; it needs "
                    "progressive=1, min_rho above 0 and no density or mask");
              params.progress = r.progress;
              // The candidates, not the output, are what takes the memory.
              require_point_budget(std::ceil(params.candidates * static_cast<double>(params.count)), r.dim,
                                   std::numeric_limits<std::uint64_t>::max(), "elimination's candidates");
              if (r.constraints.active()) {
                // The default applies without constraints only; asked for
                // explicitly it is an error rather than silently dropped.
                if (r.params.count("min_rho"))
                  throw InvalidArgument(
                      "elimination: min_rho is not taken with a density or a mask (each sample stays one of the "
                      "candidates)");
                return elimination(params, r.constraints.typed(domain), domain, r.seed);
              }
              return elimination(params, domain, r.seed);
            });
          },
  };
  return method;
}

}  // namespace pds::registry_detail
