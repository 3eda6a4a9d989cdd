// The registry's count-to-radius policy (include/pds/registry.h,
// size_request): one relative radius for every radius-only method.
#include "pds/samplers/sizing.h"

#include "pds/registry.h"

namespace pds {

GenerateRequest size_request(const Method& method, GenerateRequest request) {
  if (!request.count || request.radius || method.takes_count || !method.takes_radius) return request;
  request.radius = visit_dim<kMinDim, kMaxDim>(request.dim, [&](auto d) {
    constexpr int D = decltype(d)::value;
    return radius_for_count(*request.count, request.domain<D>(), kCountRelativeRadius);
  });
  request.count.reset();
  return request;
}

}  // namespace pds
