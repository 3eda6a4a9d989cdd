#pragma once
// Sizing for the radius-driven Poisson disk methods: turning a requested
// point count into a radius, and refusing counts that cannot fit.
//
// The conversion inverts the relative radius of Lagae & Dutre (2008),
// rho = (d_min / 2) / r_max(N), with r_max the disk radius of the densest
// packing of N disks (balls) in the domain's volume (hexagonal in 2D, FCC in
// 3D; see analysis/relative_radius.h):
//
//   radius_for_count(N, domain, rho) = 2 * rho * r_max(volume, N, D)
//
// So N points at that minimum distance have relative radius exactly rho. A
// maximal Poisson disk set reaches rho ~ 0.72-0.78 depending on the method
// (docs/dart-throwing.md, docs/bridson.md), so a rho below that leaves room
// for N points.

#include <cstdint>

#include "pds/domain.h"

namespace pds {

/// The minimum distance at which `count` points have relative radius `rho`
/// in the domain. Throws InvalidArgument unless count >= 1 and 0 < rho <= 1.
template <int D>
double radius_for_count(std::uint64_t count, const Domain<D>& domain, double rho);

/// Throws InvalidArgument (naming the method, the count and the radius) if
/// `count` points at minimum distance `radius` cannot fit in the domain, i.e.
/// exceed the densest-packing bound pds::packing_count.
template <int D>
void require_count_fits(const char* method, std::uint64_t count, double radius, const Domain<D>& domain);

}  // namespace pds
