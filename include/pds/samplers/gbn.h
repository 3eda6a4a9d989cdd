#pragma once
// Gaussian blue noise: gradient descent on the sum of a Gaussian kernel over
// all pairs of points, which spreads them into a blue-noise set with a flat,
// very low spectrum below its peak (A. G. M. Ahmed, J. Ren, P. Wonka,
// Gaussian Blue Noise, ACM TOG 41(6), SIGGRAPH Asia 2022).

#include <cstdint>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

struct GbnParams {
  /// Points, >= 2.
  std::uint64_t count = 0;
  /// Gradient steps, >= 1 (docs/gbn.md: how rho and the spectrum grow with them).
  int iterations = 1000;
  /// The kernel's standard deviation in mean spacings, (volume / count)^(1/D); > 0.
  double sigma = 0.7;
  /// The step: a point moves by step x sum over its neighbours j of
  /// (x - x_j) g(x - x_j), g the kernel (gradient descent with the gradient
  /// scaled by the kernel's variance); > 0.
  double step = 0.25;
  /// Threads (0: all); the result does not depend on it.
  int threads = 0;
  /// Optional progress (iterations done) and cancellation (pds/progress.h).
  Progress progress;
};

/// GBN from `count` white-noise points (the seed's stream).
/// Guarantees: exactly `count` points in [lo, hi); same seed, same points,
/// for any number of threads (every step moves all points at once from the
/// previous positions, each sum in a fixed order, and the kernel is
/// pds::exp_neg_table, the same bits on every platform). No minimum distance is
/// promised: the energy spreads points evenly but two may stay close.
/// On a torus distances are to the nearest image and the kernel is cut off
/// at min(kGbnCutoff sigma, half the shortest period); in a box the points
/// also feel the pull of a uniform density over the box (the kernel's
/// integral over it), which keeps them from piling up at the faces.
/// Invalid (InvalidArgument): count < 2, iterations < 1, sigma or step not
/// positive and finite, bad bounds.
template <int D>
PointSet<D> gbn(const GbnParams& params, const Domain<D>& domain, std::uint64_t seed);

/// The same descent from given points (in the domain; at least 2). `count`
/// is ignored.
template <int D>
PointSet<D> gbn_optimize(PointSet<D> points, const Domain<D>& domain, const GbnParams& params);

/// Where the kernel is cut off, in its standard deviations: beyond it a
/// neighbour adds less than e^-12.5 (4e-6) of the kernel's peak.
inline constexpr double kGbnCutoff = 5.0;

}  // namespace pds
