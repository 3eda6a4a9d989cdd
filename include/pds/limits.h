#pragma once
// Checks shared by every entry point that takes a count, a radius or a
// domain, so that each bad input gets the same clear message.

#include <cstdint>
#include <string>

#include "pds/detail/format.h"
#include "pds/domain.h"

namespace pds {

/// Default cap on the number of points one request may produce (--max-points).
/// 10^8 points in 3D take 2.4 GB as doubles.
inline constexpr std::uint64_t kDefaultMaxPoints = 100'000'000;

/// The radii every method accepts: squared distances near r^2 (and up to
/// (3r)^2) stay normal doubles, so "at least r apart" is decided exactly.
inline constexpr double kMinRadius = 1e-150, kMaxRadius = 1e150;

/// Throws InvalidArgument unless r is positive, finite and within
/// [kMinRadius, kMaxRadius].
void require_radius(double r, const char* name = "radius");

/// Throws InvalidArgument unless 1 <= n <= max_points.
void require_count(std::uint64_t n, std::uint64_t max_points);

/// Throws InvalidArgument if `points` points in dimension `dim` exceed
/// max_points or would need more memory than this machine has, counting
/// `copies` times the points' doubles (a sampler's working structures: 4).
/// `what` says where the estimate came from, for the message.
void require_point_budget(double points, int dim, std::uint64_t max_points, const std::string& what,
                          double copies = 4.0);

/// The most points a set with minimum distance r can hold in a region of the
/// given volume (densest packing of disks/balls of radius r/2; a box may hold
/// a few more along its faces). Used to estimate the size of radius-driven
/// requests before any memory is committed.
double packing_count(double volume, double r, int dim);

/// The count a set at minimum distance r typically reaches in a region of
/// the given volume when run until (nearly) nothing fits: about 0.6 of
/// packing_count (maximal sets reach relative radius 0.75-0.9). An estimate
/// for progress and memory, not a bound.
double typical_count(double volume, double r, int dim);

/// The volume to size a radius-r request by: the domain's (box or torus),
/// with every axis shorter than r counted as r long. A domain that thin along
/// some axes holds far more points than its volume says (a 1000 x 1e-6 x
/// 1e-6 box holds 10^5 points at r = 0.01, its volume 1e-9 none); growing
/// every axis by r would bound the count strictly, but 80-fold too high in
/// the 8D unit box.
inline double sizing_volume(const double* lo, const double* hi, int dim, double r) {
  double volume = 1.0;
  for (int i = 0; i < dim; ++i) volume *= hi[i] - lo[i] < r ? r : hi[i] - lo[i];
  return volume;
}
template <int D>
double sizing_volume(const Domain<D>& domain, double r) {
  return sizing_volume(domain.lo.data(), domain.hi.data(), D, r);
}

/// Checks r and that the densest packing at r fits the point budget.
template <int D>
void require_radius_budget(const Domain<D>& domain, double r, std::uint64_t max_points) {
  require_radius(r);
  const double volume = sizing_volume(domain, r);
  require_point_budget(
      packing_count(volume, r, D), D, max_points,
      "radius " + detail::format_number(r) + " over a domain of volume " + detail::format_number(domain.volume()) +
          (volume != domain.volume()
               ? " (" + detail::format_number(volume) + " with axes shorter than the radius counted as the radius)"
               : std::string()));
}

}  // namespace pds
