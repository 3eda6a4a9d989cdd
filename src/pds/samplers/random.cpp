// Uniform white noise: every coordinate an independent uniform draw from one
// stream, point after point; one code path for every dimension.
#include "pds/samplers/random.h"

#include "mapped_pages.h"
#include "pds/detail/instantiate.h"

namespace pds {

void white_noise_fill(const WhiteNoiseParams& params, const CloudBox& box, std::uint64_t seed, double* out) {
  Rng rng(seed);
  const auto n = static_cast<std::size_t>(box.dim());
  ProgressReporter progress(params.progress, static_cast<double>(params.count));
  for (std::uint64_t i = 0; i < params.count; ++i) {
    if ((i & 4095) == 0) progress.update(static_cast<double>(i));
    for (std::size_t a = 0; a < n; ++a) out[i * n + a] = rng.uniform(box.lo[a], box.hi[a]);
  }
  progress.finish();
}

PointCloud white_noise(const WhiteNoiseParams& params, const CloudBox& box, std::uint64_t seed) {
  return fill_cloud("random", params.count, box, [&](double* out) { white_noise_fill(params, box, seed, out); });
}

template <int D>
PointSet<D> white_noise(const WhiteNoiseParams& params, const Domain<D>& domain, std::uint64_t seed) {
  PointSet<D> points = detail::output_points<D>(params.count);
  white_noise_fill(params, CloudBox::of(domain), seed, points.data()->data());
  return points;
}

#define PDS_INSTANTIATE(D) \
  template PointSet<D> white_noise<D>(const WhiteNoiseParams&, const Domain<D>&, std::uint64_t);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
