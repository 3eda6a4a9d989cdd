#pragma once
// Output in float32 that keeps the promises made in double: every point in
// [lo, hi) and, for a minimum distance r, every pair at least r apart, both
// decided in double on the rounded (float32) coordinates with the domain's
// own metric (Domain::distance2).
//
// Rounding a coordinate to the nearest float32 moves it by at most half the
// float32 spacing u at the domain's largest coordinate; pulling a value that
// rounded onto hi (or below lo) back to the nearest float inside moves it by
// at most one u. A point thus moves by at most sqrt(D) u, a pair comes closer
// by at most 2 sqrt(D) u, and a set sampled at r + 2 sqrt(D) u keeps r after
// rounding. The rounded set is then checked with a neighbour grid; a failure
// (not expected: it would take a bug in that bound) samples again at a
// larger radius, a bounded number of times. Requests whose inflation would
// exceed kFloat32MaxInflation of the radius (a radius under about 280 float32
// spacings in 2D) are refused: float32 cannot hold that distance faithfully.

#include <cstddef>
#include <vector>

#include "pds/point.h"

namespace pds {

/// The largest relative radius inflation a float32 request may need.
inline constexpr double kFloat32MaxInflation = 0.01;

/// The spacing of float32 values at the largest magnitude of the bounds (an
/// upper bound on the spacing anywhere inside them). Throws InvalidArgument
/// when a bound lies beyond float32's range, or when some axis [lo, hi)
/// holds no float32 value.
double float32_spacing(const std::vector<double>& lo, const std::vector<double>& hi);

/// The radius to sample at so that a set at least that far apart stays at
/// least r apart once rounded by round_to_float32: r + 2 sqrt(dim) u (and a
/// relative 1e-12 for the double arithmetic), times 2^attempt for the
/// repair's later attempts. Throws InvalidArgument, naming r, u and the
/// coordinates' magnitude, when the inflation exceeds kFloat32MaxInflation r.
double float32_sampling_radius(double r, int dim, double spacing, int attempt = 0);

/// Rounds every coordinate to the nearest float32, then pulls any that left
/// [lo, hi) back to the nearest float32 inside (float32_spacing has checked
/// that one exists). The doubles of the result are float32 values.
void round_to_float32(PointCloud& points, const std::vector<double>& lo, const std::vector<double>& hi);

/// The first pair closer than r (indices into the cloud), if any, under the
/// box or torus metric; dim must be within [kMinDim, kMaxDim]. Uses a
/// neighbour grid: linear in the number of points.
struct ClosePair {
  std::size_t i = 0, j = 0;
  double distance = 0;
};
bool find_pair_closer_than(const PointCloud& points, const std::vector<double>& lo, const std::vector<double>& hi,
                           bool torus, double r, ClosePair* pair = nullptr);

}  // namespace pds
