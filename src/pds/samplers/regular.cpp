#include "pds/samplers/regular.h"

#include <string>

#include "mapped_pages.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"
#include "pds/samplers/strata.h"

namespace pds {

template <int D>
PointSet<D> regular(const RegularParams& params, const Domain<D>& domain) {
  std::size_t total = 1;
  for (int i = 0; i < D; ++i) {
    if (params.cells[i] < 1)
      throw InvalidArgument("regular: cells along axis " + std::to_string(i) + " must be at least 1, got " +
                            std::to_string(params.cells[i]));
    total *= static_cast<std::size_t>(params.cells[i]);
  }
  PointSet<D> points = detail::output_points<D>(total);
  std::array<int, D> index{};
  ProgressReporter progress(params.progress, static_cast<double>(total));
  for (std::size_t k = 0; k < points.size(); ++k) {
    if ((k & 65535) == 0) progress.update(static_cast<double>(k));
    for (int i = 0; i < D; ++i) points[k][i] = stratum_centre(domain, i, index[i], params.cells[i]);
    for (int i = 0; i < D && ++index[i] == params.cells[i]; ++i) index[i] = 0;
  }
  progress.finish();
  return points;
}

#define PDS_INSTANTIATE(D) template PointSet<D> regular<D>(const RegularParams&, const Domain<D>&);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
