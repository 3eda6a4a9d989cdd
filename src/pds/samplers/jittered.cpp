#include "pds/samplers/jittered.h"

#include <string>

#include "mapped_pages.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"
#include "pds/rng.h"
#include "pds/samplers/strata.h"

namespace pds {

template <int D>
PointSet<D> jittered(const JitteredParams& params, const Domain<D>& domain, std::uint64_t seed) {
  std::size_t total = 1;
  for (int i = 0; i < D; ++i) {
    if (params.cells[i] < 1)
      throw InvalidArgument("jittered: strata along axis " + std::to_string(i) + " must be at least 1, got " +
                            std::to_string(params.cells[i]));
    total *= static_cast<std::size_t>(params.cells[i]);
  }
  Rng rng(seed);
  PointSet<D> points = detail::output_points<D>(total);
  std::array<int, D> index{};
  ProgressReporter progress(params.progress, static_cast<double>(total));
  for (std::size_t k = 0; k < points.size(); ++k) {
    if ((k & 65535) == 0) progress.update(static_cast<double>(k));
    Point<D>& p = points[k];
    for (int i = 0; i < D; ++i) {
      const double edge = domain.extent(i) / params.cells[i];
      const double lo = domain.lo[i] + index[i] * edge;
      // The last stratum ends exactly at hi, whatever the rounding of lo + edge.
      const double hi = index[i] + 1 == params.cells[i] ? domain.hi[i] : domain.lo[i] + (index[i] + 1) * edge;
      p[i] = rng.uniform(lo, hi);
    }
    for (int i = 0; i < D && ++index[i] == params.cells[i]; ++i) index[i] = 0;
  }
  progress.finish();
  return points;
}

#define PDS_INSTANTIATE(D) template PointSet<D> jittered<D>(const JitteredParams&, const Domain<D>&, std::uint64_t);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
