// Boundary sampling with the scalar neighbourhood kernel: what every
// processor runs, and what PDS_FORCE_SCALAR=1 selects (kernel_select.h).
// Built with -fno-math-errno (the loop's square roots of non-negative
// arguments become the bare instruction) and -ffp-contract=off (no fused
// multiply-add, so the AVX-512 kernel rounds alike); see CMakeLists.txt.
#include "boundary.h"
#include "boundary_loop.h"

namespace pds::detail::dh {

PointSet<2> boundary_sampling_scalar(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed) {
  return boundary_sampling_with<ScalarNeighbours>(params, domain, seed);
}

std::vector<std::array<double, 2>> free_arcs_scalar(const Point<2>& p, const PointSet<2>& neighbours, double radius) {
  return free_arcs_with<ScalarNeighbours>(p, neighbours, radius);
}

}  // namespace pds::detail::dh
