#include "pds/samplers/sizing.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "pds/analysis/relative_radius.h"
#include "pds/detail/format.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"
#include "pds/limits.h"

namespace pds {
template <int D>
double radius_for_count(std::uint64_t count, const Domain<D>& domain, double rho) {
  if (count == 0) throw InvalidArgument("count must be at least 1, got 0");
  if (!(rho > 0.0 && rho <= 1.0)) throw InvalidArgument("rho must be in (0, 1], got " + detail::format_number(rho));
  // In a domain thinner than the radius along some axes the volume to size
  // by grows with the radius (sizing_volume): iterate from the plain volume
  // upward; the radius rises monotonically to the fixed point. Past the
  // longest axis no axis is left to size by (the domain holds about one
  // point), so the radius stops there.
  const auto radius_for = [&](double volume) {
    return 2.0 * rho * max_packing_radius(volume, static_cast<std::size_t>(count), D);
  };
  double longest = 0.0;
  for (int a = 0; a < D; ++a) longest = std::max(longest, domain.extent(a));
  double r = radius_for(domain.volume());
  for (int step = 0; step < 200 && r < longest; ++step) {
    const double next = std::min(radius_for(sizing_volume(domain, r)), longest);
    if (!(next > r * (1.0 + 1e-12))) break;
    r = next;
  }
  return r;
}

template <int D>
void require_count_fits(const char* method, std::uint64_t count, double radius, const Domain<D>& domain) {
  const double most = std::floor(packing_count(sizing_volume(domain, radius), radius, D));
  if (static_cast<double>(count) > most)
    throw InvalidArgument(std::string(method) + ": " + std::to_string(count) + " points cannot fit at radius " +
                          detail::format_number(radius) + " in this domain (the densest packing holds at most about " +
                          detail::format_number(most) + "); ask for fewer points or a smaller radius");
}

#define PDS_INSTANTIATE(D)                                                           \
  template double radius_for_count<D>(std::uint64_t, const Domain<D>&, double); \
  template void require_count_fits<D>(const char*, std::uint64_t, double, const Domain<D>&);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
