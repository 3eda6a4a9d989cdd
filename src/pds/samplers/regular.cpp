#include "pds/samplers/regular.h"

#include <string>

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
  PointSet<D> points(total);
  std::array<int, D> index{};
  for (auto& p : points) {
    for (int i = 0; i < D; ++i) p[i] = stratum_centre(domain, i, index[i], params.cells[i]);
    for (int i = 0; i < D && ++index[i] == params.cells[i]; ++i) index[i] = 0;
  }
  return points;
}

template PointSet<2> regular<2>(const RegularParams&, const Domain<2>&);
template PointSet<3> regular<3>(const RegularParams&, const Domain<3>&);

const Method& regular_method() {
  static const Method method{
      .name = "regular",
      .summary = "regular grid of cell centres; --count N (near-cubic cells) or --radius R (spacing >= R)",
      .takes_count = true,
      .takes_radius = true,
      .deterministic = true,
      .run =
          [](const GenerateRequest& r) {
            return run_typed(r, [&](const auto& domain) {
              constexpr int D = std::decay_t<decltype(domain.lo)>::dim;
              if (r.count && r.radius) throw InvalidArgument("regular: give --count or --radius, not both");
              const auto cells = r.count ? strata_for_count(domain, *r.count) : strata_for_spacing(domain, *r.radius);
              RegularParams params;
              std::copy(cells.begin(), cells.end(), params.cells.begin());
              double total = 1;
              for (int c : cells) total *= c;
              require_point_budget(total, D, r.max_points, "regular grid");
              return regular(params, domain);
            });
          },
  };
  return method;
}

}  // namespace pds
