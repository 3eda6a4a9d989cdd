#pragma once
// Mitchell's best-candidate sampling: each new sample is the candidate, among
// m*i uniform random ones, farthest from the i samples placed so far
// (D. P. Mitchell, Generating antialiased images at low sampling densities,
// SIGGRAPH 1987; Spectrally optimal sampling for distribution ray tracing,
// SIGGRAPH 1991).

#include <cstdint>
#include <optional>
#include <vector>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

/// Default m: candidates per sample already placed.
inline constexpr int kBestCandidateDefaultM = 10;

/// While m*i is below this, exactly m*i candidates are drawn; from there on
/// the candidates are a Poisson process of mean m*i (see best_candidate()).
inline constexpr std::uint64_t kBestCandidateExactBelow = 256;

struct BestCandidateParams {
  std::optional<std::uint64_t> count;  // samples to place
  std::optional<double> radius;        // stop (or fail, with a count) once the best candidate is closer than this
  int m = kBestCandidateDefaultM;      // candidates per existing sample, >= 1
  Progress progress;                   // optional progress report and cancellation (pds/progress.h)
};

template <int D>
struct BestCandidateResult {
  PointSet<D> points;
  /// distance[i]: the distance from points[i] to the nearest of points[0..i)
  /// when it was chosen (infinity for the first). Their minimum is the set's
  /// minimum distance.
  std::vector<double> distance;
};

/// Progressive: every prefix of the output is itself well spread (the
/// output order is the order of choice).
/// Sizing: a count places exactly that many; a radius alone stops at the
/// first round whose best candidate is closer than the radius (that
/// candidate is not placed), so the minimum distance is >= radius and the set
/// is near-maximal but not guaranteed maximal; both together place `count`
/// samples and fail if a round's best falls below the radius first.
/// Candidates: the first sample is uniform; then exactly m*i uniform
/// candidates while m*i < kBestCandidateExactBelow, and from there on a
/// Poisson process of candidates with mean m*i (count within a few per cent
/// of m*i), which lets the search skip every region that cannot hold the
/// winner. From 4 dimensions every round draws exactly m*i candidates (the
/// literal method, m N^2 / 2 candidates in all; refused past 5e8). Distances are the domain's (nearest periodic image on a torus).
/// Guarantees: samples in [lo, hi); same seed, same points; each reported
/// distance is exact (Domain::distance2).
/// Invalid (InvalidArgument): m < 1; neither count nor radius; count 0;
/// radius not positive and finite; with both, a count that does not fit
/// (the packing bound, or a round's best below the radius: the message says
/// how many were placed).
template <int D>
BestCandidateResult<D> best_candidate_run(const BestCandidateParams& params, const Domain<D>& domain,
                                          std::uint64_t seed);

template <int D>
PointSet<D> best_candidate(const BestCandidateParams& params, const Domain<D>& domain, std::uint64_t seed) {
  return best_candidate_run(params, domain, seed).points;
}

}  // namespace pds
