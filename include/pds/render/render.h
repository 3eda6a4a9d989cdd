#pragma once
// The anti-aliasing renderer: samples from an ImageSampler, a closed-form
// Scene evaluated at each, and a reconstruction Filter. A pixel's value is the
// filter-weighted sum of the samples within the filter's radius of its centre
// divided by the sum of their weights (as pbrt-v3's film does); a pixel whose
// weights sum to zero (no sample in its support) is 0 and counted.
//
// The image is cut into square blocks rendered in parallel (TBB); each block
// asks the sampler for the samples that can reach its pixels and writes only
// its own pixels, so the result does not depend on the number of threads.

#include <cstdint>
#include <string>
#include <vector>

#include "pds/progress.h"
#include "pds/render/filter.h"
#include "pds/render/image_sampler.h"
#include "pds/render/scene.h"

namespace pds {

/// A grey image, row by row, y down.
struct Image {
  int width = 0, height = 0;
  std::vector<double> pixels;

  Image() = default;
  Image(int w, int h, double fill = 0.0) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, fill) {}
  double& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  double at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

struct RenderOptions {
  Filter filter;
  int threads = 0;    // 0: all hardware threads
  int block = 32;     // pixels per block side
  Progress progress;  // blocks rendered out of all of them (pds/progress.h)
};

struct RenderStats {
  std::uint64_t samples = 0;       // scene evaluations
  std::uint64_t empty_pixels = 0;  // pixels no sample reached
};

/// Largest image side render() accepts: an image of doubles at this size is
/// 128 MiB, and a measured rendering holds four (image, reference, error, spectrum).
inline constexpr int kMaxImageSide = 4096;

/// Renders `scene` at width x height. Throws InvalidArgument for a size out of
/// [1, kMaxImageSide] or bad options.
Image render(const Scene& scene, const ImageSampler& sampler, int width, int height, const RenderOptions& options,
             RenderStats* stats = nullptr);

/// The reference for error measurements: the same scene and filter with
/// `spp` jittered samples per pixel (seeded apart from any test image).
Image render_reference(const Scene& scene, int width, int height, int spp, const RenderOptions& options);

/// Root mean square difference of two images of the same size.
double rmse(const Image& a, const Image& b);
/// Peak signal-to-noise ratio in dB for grey levels in [0, 1]: 20 log10(1 / rmse).
double psnr(double rmse);

/// a - b, pixel by pixel.
Image difference(const Image& a, const Image& b);

/// The periodogram |DFT|^2 / (width * height) of an image (FFTW), shifted so
/// that frequency 0 lies at pixel (width / 2, height / 2).
Image power_spectrum(const Image& image);

/// The share of the spectrum's power (frequency 0 excluded) at radial
/// frequencies below `cutoff` cycles per pixel. White noise puts
/// pi * cutoff^2 of it there; blue-noise error puts less.
double low_frequency_share(const Image& spectrum, double cutoff);

/// Mean power in `bands` rings of equal width between radial frequency 0 and
/// 0.5 cycles per pixel (frequency 0 and the corners beyond 0.5 excluded): the
/// radially averaged spectrum, flat for white error, rising for blue.
std::vector<double> radial_power_profile(const Image& spectrum, int bands);

/// The sampler's samples counted on a grid of `cells` x `cells` cells per
/// pixel over width x height pixels, minus the mean count: an image whose
/// power spectrum is the sampling pattern's periodogram up to the cell size.
Image sample_density(const ImageSampler& sampler, int width, int height, int cells = 2);

/// Mean power at the spectrum bins on the lattice of multiples of 1 / period
/// cycles per pixel (0 excluded) divided by the mean over all other bins;
/// about 1 for aperiodic error, far above 1 when the error repeats with that period.
double period_peak_ratio(const Image& spectrum, double period);

/// The share of the spectrum's power (frequency 0 excluded) on that lattice:
/// 1 for an exactly periodic image, about 1 / period^2 for white noise.
double period_power_share(const Image& spectrum, double period);

}  // namespace pds
