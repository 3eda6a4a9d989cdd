#pragma once
// Pair correlation function (radial distribution function) g(r) of point sets
// in a box or on a torus: the density of point pairs at distance r relative
// to that of uniform random points, so white noise has g = 1, and Poisson
// disk sets have g = 0 below their minimum distance and a peak just above it.
//
// Estimator. With lambda^2 estimated by N (N - 1) / V^2 (unbiased for uniform
// points),
//
//   g(r) = sum_{i != j} k_h(r - d_ij) w_ij / (N (N - 1) / V * s_D * I(r)),
//   I(r) = integral over s >= 0 of k_h(r - s) s^(D-1) ds,
//
// where k_h is the Epanechnikov kernel of half-width h,
// k_h(u) = 3/(4h) (1 - (u/h)^2) for |u| < h, s_D is the surface of the unit
// sphere (2 pi, 4 pi) and d_ij the distance (minimum image on a torus).
// Dividing by I(r) rather than r^(D-1) makes the estimator unbiased for
// uniform points at every r, including r < h where the kernel reaches below
// zero. On a torus w_ij = 1. In a box w_ij = V / |W ∩ (W + x_i - x_j)| =
// prod V_a / (L_a - |dx_a|), the translation edge correction (Ohser 1983),
// which compensates for pairs whose partner would fall outside the box.
// The estimate is averaged over the sets.
//
// Defaults, in units of the mean inter-point distance d = (V/N)^(1/D):
// r from 0 to 2.5 d in 200 steps, h = 0.1 d (Schlomer and Heck's PSA uses a
// comparable Gaussian width). r is limited to half the shortest extent (the
// torus distance is at most that).

#include <cstddef>
#include <span>
#include <vector>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

struct PairCorrelationOptions {
  double r_max = 0;      // largest r; 0: 2.5 mean inter-point distances (capped at half the shortest extent)
  double bandwidth = 0;  // kernel half-width h; 0: 0.1 mean inter-point distances
  int steps = 200;       // values of r: r_max * (i + 1) / steps, i = 0..steps-1
};

struct PairCorrelation {
  std::vector<double> r;  // in domain units
  std::vector<double> g;
  double bandwidth = 0;
  double mean_spacing = 0;  // (V/N)^(1/D), N the mean count
  std::size_t sets = 0;
};

/// g(r) averaged over the sets. Each set needs at least two points and must
/// lie in the domain. Throws InvalidArgument for bad options (r_max beyond
/// half the shortest extent, h not positive, steps outside [1, 100000]).
/// Optional progress: points visited over all sets, and cancellation
/// (pds/progress.h).
template <int D>
PairCorrelation pair_correlation(std::span<const PointSet<D>> sets, const Domain<D>& domain,
                                 const PairCorrelationOptions& options = {}, const Progress& progress = {});

}  // namespace pds
