// Error measures of a rendering (include/pds/render/metrics.h).

#include "pds/render/metrics.h"

#include <algorithm>

namespace pds {

RenderMetrics measure_render(const Image& image, const Image& reference, const ImageSampler& sampler,
                             bool samples_spectrum, RenderMetricImages* images) {
  RenderMetrics out;
  const double e = rmse(image, reference);
  out.rmse = e;
  out.psnr_db = psnr(e);
  Image error = difference(image, reference);
  Image spectrum = power_spectrum(error);
  out.error_low_frequency_share = low_frequency_share(spectrum, 0.25);
  std::vector<double> profile = radial_power_profile(spectrum, 8);
  const double mean_power = e * e;  // Parseval: mean periodogram value = mean squared error
  for (double& v : profile) v = mean_power > 0 ? v / mean_power : 0.0;
  out.error_radial_profile = std::move(profile);
  const TiledPattern* tiled = sampler.tiled();
  if (tiled)
    out.tile = TileMetrics{.tile_points = tiled->tile_count(),
                           .tile_period_px = tiled->tile_size(),
                           .error_tile_peak_ratio = period_peak_ratio(spectrum, tiled->tile_size()),
                           .error_power_on_tile_lattice = period_power_share(spectrum, tiled->tile_size())};
  Image density;
  if (samples_spectrum || tiled) {
    // The samples themselves, on a half-pixel grid (whole pixels for the
    // largest images): periodic patterns show their tile frequency here
    // whatever the scene.
    const int cells = std::max(image.width, image.height) <= kMaxImageSide / 2 ? 2 : 1;
    density = power_spectrum(sample_density(sampler, image.width, image.height, cells));
    if (tiled) out.tile->samples_power_on_tile_lattice = period_power_share(density, tiled->tile_size() * cells);
    out.samples_low_frequency_share = low_frequency_share(density, 0.25 / cells);
  }
  if (images) *images = {std::move(error), std::move(spectrum), std::move(density)};
  return out;
}

}  // namespace pds
