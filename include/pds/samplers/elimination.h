#pragma once
// Weighted sample elimination: from a larger candidate set, remove the sample
// with the largest weight (a sum over its neighbours that grows as they come
// closer) until the requested number remain (C. Yuksel, Sample elimination
// for generating Poisson disk sample sets, Computer Graphics Forum 34(2),
// Eurographics 2015).

#include <cstdint>
#include <vector>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"
#include "pds/samplers/constraints.h"

namespace pds {

/// The paper's weight function (Yuksel 2015, eq. 1 and section 3.2): a
/// neighbour at distance d < d_max adds (1 - max(d, d_min) / d_max)^alpha,
/// with d_max = 2 r_max (r_max: the packing radius of the output count,
/// analysis/relative_radius.h) and the weight limit
/// d_min = d_max (1 - (N / M)^gamma) beta for N outputs from M candidates.
/// The defaults are the paper's; beta = 0 turns weight limiting off.
struct EliminationWeights {
  double alpha = 8.0;  // > 0; 8 is evaluated by three squarings
  double beta = 0.65;  // in [0, 1)
  double gamma = 1.5;  // > 0
};

struct EliminationParams {
  std::uint64_t count = 0;  // samples to keep, >= 1
  /// Candidates drawn as white noise, as a multiple of the count (the paper
  /// uses 5; more candidates give a slightly larger minimum distance at
  /// proportional cost). At least 1 (1: nothing is eliminated).
  double candidates = 5.0;
  /// Order the output so that every prefix is well spread (the paper's
  /// progressive sampling, section 5): the kept set is eliminated again to
  /// half its size with d_max grown by 2^(1/D), recursively, and each half's
  /// eliminated samples follow the survivors, the last eliminated first.
  bool progressive = true;
  EliminationWeights weights;
  /// After the elimination, move the points of pairs closer than this
  /// relative radius (min_rho x 2 r_max, analysis/relative_radius.h) to the
  /// best of trial places near them: about 4% of the points in 2D at 0.72,
  /// which lifts the minimum distance from the paper's ~0.69 to 0.72. A move
  /// never gives a prefix of the progressive order a closer pair than it had
  /// (only points of the second half move); it takes a point min_rho from
  /// every other, or where none is found, to a better place than its own.
  /// Above ~0.74 there is no more room (0.74 and 0.8 give ~0.73 at 10^5
  /// points, 0.8 at 8 times the cost). 0 keeps the paper's output, a subset
  /// of the candidates. In [0, 0.8].
  double min_rho = 0.72;
  /// With progressive order and min_rho above 0, build the order coarse to
  /// fine instead of by the paper's halvings: counts shrink by sqrt(2) a
  /// level from N down to the first count <= 16, and each level keeps its own
  /// count from its share of the candidates (the first min(candidates, 2) x
  /// its count; all of them for N) by the same elimination around the levels
  /// below (which stay), moves its new points apart to min_rho (below N, from
  /// 2D on, to min_rho - 0.02; with every level at min_rho about three
  /// quarters of them moved: most output points are not candidates) and
  /// appends them farthest first. Measured (2D torus): prefixes at 1% steps
  /// at rho >= ~0.665 (0.67 from 10^5 points; from 32 points on >= ~0.655),
  /// where the halvings' fall to ~0.60; the full set at 0.72 as with the
  /// halvings but with a lower spectral peak; about twice the time
  /// (docs/elimination.md). Ignored, like min_rho, by the overload with a
  /// density or mask. False: the halvings.
  bool levels = false;
  /// Optional progress (candidates removed, over every round) and
  /// cancellation (pds/progress.h).
  Progress progress;
};

/// Draws ceil(candidates * count) white-noise candidates (seeded), keeps
/// `count` of them by eliminate(), then moves the points of its closest
/// pairs apart (params.min_rho).
/// Guarantees: exactly `count` samples in [lo, hi), each one of the
/// candidates when min_rho is 0; same seed, same points (no thread, and the
/// heap breaks ties by index). No minimum distance is promised: the weights
/// push samples apart but nothing bounds the closest pair, and a point that
/// finds no place min_rho from the others ends nearer (none did at 0.72 in
/// the runs of docs/elimination.md). Measured relative radius ~0.69 from 5N
/// candidates without the moves, 0.72 with them, ~0.74 from 10N, in 2D. In a box, samples near the
/// faces have fewer neighbours and lighter weights, so the faces keep
/// slightly more samples (as in the paper without tiling); on a torus every
/// distance is to the nearest periodic image, each candidate counted once.
/// Invalid (InvalidArgument): count 0; candidates below 1 or more than 2^31
/// of them; weights or min_rho out of range.
template <int D>
PointSet<D> elimination(const EliminationParams& params, const Domain<D>& domain, std::uint64_t seed);

/// Elimination with a radius field and a mask (docs/density.md,
/// "Elimination"). Candidates are drawn uniformly and kept with probability
/// (rmin / r(x))^D where the mask allows, so their density follows
/// r(x)^-D; a pair of candidates then uses d_max and d_min times the larger
/// of their two r / rmin (the larger-of-two rule of constraints.h, applied
/// to the weights' reach), with d_max = 2 r_max for N points in the volume
/// weighted by (rmin / r)^D (estimated from the draws). The count is
/// params.count, or with a field and count 0 the count whose samples
/// typically lie r(x) apart: V' / packing_volume_per_point(rmin / 1.38, D),
/// V' the weighted volume estimated from 65,536 uniform draws. min_rho is
/// not applied (each sample stays one of the candidates).
/// Guarantees: exactly that many samples, each where the mask allows; same
/// seed, same points. As without constraints, **no minimum distance** is
/// promised: the pair rule is what the weights aim at, not a bound (the
/// measured share of pairs closer than max(r(a), r(b)) is in
/// docs/density.md). Invalid (InvalidArgument): fixed points; a count of 0
/// without a field; a field whose rmin, rmax are not radii with rmin <=
/// rmax, or that returns NaN; as elimination(). Failure: a mask so small
/// that 64 M (rmax / rmin)^D + 10^6 draws give fewer than M candidates.
template <int D>
PointSet<D> elimination(const EliminationParams& params, const SamplingConstraints<D>& constraints,
                        const Domain<D>& domain, std::uint64_t seed);

/// Weighted sample elimination of a given candidate set: keeps `count` of
/// `candidates` (their coordinates unchanged), ordered as
/// EliminationParams::progressive says, else in the candidates' order.
/// Deterministic. Invalid (InvalidArgument): count 0 or above the number of
/// candidates, a candidate outside the domain, more than 2^31 candidates.
template <int D>
PointSet<D> eliminate(const PointSet<D>& candidates, std::uint64_t count, const Domain<D>& domain,
                      const EliminationWeights& weights = {}, bool progressive = true, const Progress& progress = {});

/// The same on candidates the caller gives up: they are sorted in place
/// instead of copied, so the candidates are held once (at 5N candidates in
/// 2D, 80 of the 240 MB a copy would take at N = 10^6). The same points out.
template <int D>
PointSet<D> eliminate(PointSet<D>&& candidates, std::uint64_t count, const Domain<D>& domain,
                      const EliminationWeights& weights = {}, bool progressive = true, const Progress& progress = {});

}  // namespace pds
