// D. Dunbar and G. Humphreys, "A spatial data structure for fast Poisson-disk
// sample generation", ACM SIGGRAPH 2006 (ACM TOG 25(3), 503-508).
//
// The driver: it validates a request and hands it to one of three variants,
// one data structure idea (the part of a front sample's neighbourhood where a
// new sample may still go). The pieces, one idea a file, in dunbar_humphreys/:
//   cell_grid.h               the background grid (one sample index per cell)
//   scalloped_region.h/.cpp   scalloped sectors: exact areas, inverse CDF
//   sector_sampling.h/.cpp    variants 1 and 2 over those regions
//   boundary.h                variant 0's entry points, one per kernel
//   boundary_loop.h           variant 0's loop and its scalar kernel
//   boundary_scalar.cpp       ... instantiated for any processor
//   boundary_avx512.cpp       ... and with the AVX-512 kernel (x86-64-v4)
//   kernel_select.h/.cpp      the run-time choice; PDS_FORCE_SCALAR=1
//
// Variant 0, the paper's boundary sampling: new samples on the
// circle of radius r around a front sample, uniformly over the arcs no other
// disk covers, until none is left. Fastest; 25% denser than dart throwing.
// Variant 1, the paper's scalloped sectors: new samples uniform
// over the free part of the annulus r..2r of a random front sample, until it
// is empty; 5% denser than dart throwing. Variant 2: the same sectors, each new
// sample uniform over all free annuli at once: dart throwing's statistics,
// O(N log N). All three are maximal (up to 1e-10 r for variant 0, 1e-11 r for
// the others) and keep every pair at least r apart; measured in
// docs/dunbar-humphreys.md.
//
// Limits. 2D only (the paper is 2D). On a torus every period must exceed 4r
// (variant 0) or 6r (variants 1 and 2), so that one nearest image suffices.
#include "pds/samplers/dunbar_humphreys.h"

#include <string>

#include "dunbar_humphreys/boundary.h"
#include "dunbar_humphreys/kernel_select.h"
#include "dunbar_humphreys/sector_sampling.h"
#include "pds/detail/format.h"
#include "pds/error.h"

namespace pds {
namespace detail {
namespace {

/// Throws InvalidArgument when the vector kernel is asked for where there is none.
void check_vector_kernel_request(bool vector_kernel) {
  if (!vector_kernel) return;
#if PDS_HAVE_AVX512_KERNEL
  if (!dunbar_humphreys_has_vector_kernel())
    throw InvalidArgument("dunbar-humphreys: the AVX-512 kernel was asked for on a processor without it");
#else
  throw InvalidArgument("dunbar-humphreys: this build has no vector kernel");
#endif
}

}  // namespace

PointSet<2> dunbar_humphreys_boundary(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed,
                                      bool vector_kernel) {
  domain.validate();
  require_radius_budget(domain, params.radius, params.max_points);
  check_vector_kernel_request(vector_kernel);
#if PDS_HAVE_AVX512_KERNEL
  if (vector_kernel) return dh::boundary_sampling_avx512(params, domain, seed);
#endif
  return dh::boundary_sampling_scalar(params, domain, seed);
}

std::vector<std::array<double, 2>> dunbar_humphreys_free_arcs(const Point<2>& p, const PointSet<2>& neighbours,
                                                              double radius, bool vector_kernel) {
  check_vector_kernel_request(vector_kernel);
#if PDS_HAVE_AVX512_KERNEL
  if (vector_kernel) return dh::free_arcs_avx512(p, neighbours, radius);
#endif
  return dh::free_arcs_scalar(p, neighbours, radius);
}

}  // namespace detail

PointSet<2> dunbar_humphreys(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed) {
  domain.validate();
  const double r = params.radius;
  require_radius_budget(domain, r, params.max_points);
  if (params.variant < 0 || params.variant > 2)
    throw InvalidArgument(
        "dunbar-humphreys: variant must be 0 (boundary), 1 (scalloped sectors) or 2 (global sectors), got " +
        std::to_string(params.variant));
  if (params.variant >= 1) {
    if (domain.periodic)
      for (int i = 0; i < 2; ++i)
        if (domain.extent(i) <= 6.0 * r)  // samples within 3r need one nearest image
          throw InvalidArgument(
              "dunbar-humphreys: variants 1 and 2 on a torus need every period above 6 radius; axis " +
              std::to_string(i) + " has " + detail::format_number(domain.extent(i)) + " for radius " +
              detail::format_number(r));
    return params.variant == 1 ? detail::dh::scalloped_sector_sampling(params, domain, seed)
                               : detail::dh::global_scalloped_sampling(params, domain, seed);
  }
  return detail::dunbar_humphreys_boundary(params, domain, seed, detail::dh::use_vector_kernel());
}

}  // namespace pds
