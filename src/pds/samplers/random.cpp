#include "pds/samplers/random.h"

namespace pds {

template <int D>
PointSet<D> white_noise(const WhiteNoiseParams& params, const Domain<D>& domain, std::uint64_t seed) {
  Rng rng(seed);
  PointSet<D> points(params.count);
  for (auto& p : points) p = uniform_point(rng, domain);
  return points;
}

template PointSet<2> white_noise<2>(const WhiteNoiseParams&, const Domain<2>&, std::uint64_t);
template PointSet<3> white_noise<3>(const WhiteNoiseParams&, const Domain<3>&, std::uint64_t);

}  // namespace pds
