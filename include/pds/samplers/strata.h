#pragma once
// Splitting a domain into a grid of equal cells (strata), shared by the
// regular grid, jittered sampling and the other stratified patterns.

#include <array>
#include <cstdint>

#include "pds/domain.h"

namespace pds {

/// The widest a stratum may be relative to its narrowest side.
inline constexpr double kMaxStratumAspect = 2.0;

/// Cells per axis whose product is exactly `count`, chosen so that the cells
/// are as close to cubes as the domain allows. Throws InvalidArgument when no
/// split keeps the cell aspect within kMaxStratumAspect (a prime count over a
/// square, say), naming the nearest counts below and above that work.
template <int D>
std::array<int, D> strata_for_count(const Domain<D>& domain, std::uint64_t count);

/// Centre of cell j of n along one axis. The regular grid's points are these.
template <int D>
double stratum_centre(const Domain<D>& domain, int axis, int j, int n) {
  return domain.lo[axis] + (j + 0.5) * (domain.extent(axis) / n);
}

/// Cells per axis, as many as fit (at most floor(extent / spacing), at least
/// 1), such that the computed cell centres (stratum_centre) are at least
/// `spacing` apart in floating point, across the seam on a torus too.
template <int D>
std::array<int, D> strata_for_spacing(const Domain<D>& domain, double spacing);

/// Cell aspect ratio (longest edge / shortest edge) of a split.
template <int D>
double strata_aspect(const Domain<D>& domain, const std::array<int, D>& cells);

}  // namespace pds
