// The renderer, error measures and error spectra (see include/pds/render/render.h).
//
// Cost: each block evaluates the scene at the samples within the filter
// radius of its pixels (a margin of about 2 R / block more than once) and
// splats each sample into at most (2R + 1)^2 pixels with separable weights,
// so the filter is evaluated 2 (2R + 1) times a sample, not (2R + 1)^2.

#include "pds/detail/format.h"
#include "pds/render/render.h"

#include <fftw3.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <complex>
#include <limits>
#include <mutex>
#include <string>

#include "pds/error.h"
#include "pds/parallel.h"

namespace pds {

namespace {

constexpr std::uint64_t kReferenceSeed = 0x7265666572656e63ULL;  // "referenc": apart from user seeds
constexpr int kMaxFilterTaps = 8;                                // 2R + 1 rounded up, for R <= 2 (+1 for edge cases)

void check_size(int width, int height) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw InvalidArgument("image size must be between 1x1 and " + std::to_string(kMaxImageSide) + "x" +
                          std::to_string(kMaxImageSide) + ", got " + std::to_string(width) + "x" +
                          std::to_string(height));
}

// The 1D weights of the pixels [first, last] that a sample at s reaches;
// returns how many and sets `lo` to the first. The weights are computed over
// the sample's whole support and then clipped, so they are the same bits
// whichever block asks (the Gaussian's recurrence starts at the same pixel).
int taps(const Filter& f, double s, int first, int last, double* w, int& lo) {
  const double r = f.radius();
  const int full_lo = static_cast<int>(std::ceil(s - 0.5 - r));
  const int full_n = std::clamp(static_cast<int>(std::floor(s - 0.5 + r)) - full_lo + 1, 0, kMaxFilterTaps);
  double all[kMaxFilterTaps];
  f.weights(full_lo + 0.5 - s, full_n, all);
  lo = std::max(first, full_lo);
  const int hi = std::min(last, full_lo + full_n - 1);
  const int n = std::max(0, hi - lo + 1);
  for (int k = 0; k < n; ++k) w[k] = all[lo - full_lo + k];
  return n;
}

}  // namespace

Image render(const Scene& scene, const ImageSampler& sampler, int width, int height, const RenderOptions& options,
             RenderStats* stats) {
  check_size(width, height);
  if (options.threads < 0)
    throw InvalidArgument("threads must be 0 (all) or positive, got " + std::to_string(options.threads));
  if (options.block < 1 || options.block > 4096)
    throw InvalidArgument("render block side must be in [1, 4096], got " + std::to_string(options.block));
  const Filter filter = options.filter;
  const double r = filter.radius();
  // Keep a block's samples near 2^20 (16 MB) however large spp is; the image
  // does not depend on the block size (a pixel's samples arrive in the same
  // order from any rectangle: row-major pixels, or copies then bins).
  const int block = std::clamp(static_cast<int>(std::sqrt(double(1 << 20) / sampler.spp())), 1, options.block);
  const int bx_count = (width + block - 1) / block, by_count = (height + block - 1) / block;
  Image image(width, height);
  std::atomic<std::uint64_t> samples{0}, empty{0};

  auto render_block = [&](int b) {
    const int x0 = (b % bx_count) * block, y0 = (b / bx_count) * block;
    const int x1 = std::min(width, x0 + block), y1 = std::min(height, y0 + block);
    const int bw = x1 - x0;
    // Exactly the samples whose filter support reaches a pixel centre of the block.
    const PixelRect reach{x0 + 0.5 - r, y0 + 0.5 - r, x1 - 0.5 + r, y1 - 0.5 + r};
    std::vector<Point<2>> points;
    sampler.samples_in(reach, points);
    std::vector<double> sum(static_cast<std::size_t>(bw) * (y1 - y0), 0.0), weight(sum.size(), 0.0);
    double wx[kMaxFilterTaps], wy[kMaxFilterTaps];
    for (const Point<2>& p : points) {
      const double v = scene.value(p[0], p[1]);
      int lx, ly;
      const int nx = taps(filter, p[0], x0, x1 - 1, wx, lx);
      const int ny = taps(filter, p[1], y0, y1 - 1, wy, ly);
      for (int j = 0; j < ny; ++j) {
        const std::size_t row = static_cast<std::size_t>(ly + j - y0) * bw + (lx - x0);
        for (int i = 0; i < nx; ++i) {
          const double w = wx[i] * wy[j];
          sum[row + i] += w * v;
          weight[row + i] += w;
        }
      }
    }
    std::uint64_t local_empty = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const std::size_t k = static_cast<std::size_t>(y - y0) * bw + (x - x0);
        // Mitchell's negative lobes can cancel; treat a vanishing total as no data.
        if (std::abs(weight[k]) > 1e-12) {
          image.at(x, y) = sum[k] / weight[k];
        } else {
          image.at(x, y) = 0.0;
          ++local_empty;
        }
      }
    samples += points.size();
    empty += local_empty;
  };

  // With a progress callback the blocks go in about a hundred rounds, each
  // reported from this thread once done; the image does not depend on them.
  const auto blocks = static_cast<std::size_t>(bx_count) * static_cast<std::size_t>(by_count);
  const std::size_t round = options.progress ? std::max<std::size_t>(blocks / 100, 64) : blocks;
  ProgressReporter progress(options.progress, static_cast<double>(blocks));
  for (std::size_t start = 0; start < blocks; start += round) {
    parallel_for(start, std::min(blocks, start + round), 1, options.threads, [&](std::size_t first, std::size_t last) {
      for (std::size_t b = first; b != last; ++b) render_block(static_cast<int>(b));
    });
    progress.update(static_cast<double>(std::min(blocks, start + round)));
  }
  progress.finish();
  if (stats) {
    stats->samples = samples.load();
    stats->empty_pixels = empty.load();
  }
  return image;
}

Image render_reference(const Scene& scene, int width, int height, int spp, const RenderOptions& options) {
  const auto sampler = make_image_sampler("jittered", {.spp = spp, .seed = kReferenceSeed});
  return render(scene, *sampler, width, height, options);
}

Image sample_density(const ImageSampler& sampler, int width, int height, int cells) {
  check_size(width, height);
  if (cells < 1 || static_cast<long long>(cells) * std::max(width, height) > kMaxImageSide)
    throw InvalidArgument("sample density: cells per pixel times the image side must be at most " +
                          std::to_string(kMaxImageSide) + ", got " + std::to_string(cells) + " cells");
  Image density(width * cells, height * cells);
  std::vector<Point<2>> points;
  sampler.samples_in({0, 0, static_cast<double>(width), static_cast<double>(height)}, points);
  for (const auto& p : points) {
    const int x = std::min(density.width - 1, static_cast<int>(p[0] * cells));
    const int y = std::min(density.height - 1, static_cast<int>(p[1] * cells));
    density.at(x, y) += 1.0;
  }
  const double mean = static_cast<double>(points.size()) / static_cast<double>(density.pixels.size());
  for (double& v : density.pixels) v -= mean;
  return density;
}

double rmse(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw InvalidArgument("rmse: images differ in size (" + std::to_string(a.width) + "x" + std::to_string(a.height) +
                          " and " + std::to_string(b.width) + "x" + std::to_string(b.height) + ")");
  if (a.pixels.empty()) return 0.0;
  double s = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const double d = a.pixels[i] - b.pixels[i];
    s += d * d;
  }
  return std::sqrt(s / static_cast<double>(a.pixels.size()));
}

double psnr(double rmse) { return rmse > 0 ? -20.0 * std::log10(rmse) : std::numeric_limits<double>::infinity(); }

Image difference(const Image& a, const Image& b) {
  rmse(a, b);  // checks the sizes
  Image d(a.width, a.height);
  for (std::size_t i = 0; i < a.pixels.size(); ++i) d.pixels[i] = a.pixels[i] - b.pixels[i];
  return d;
}

Image power_spectrum(const Image& image) {
  const int w = image.width, h = image.height;
  if (w < 1 || h < 1) throw InvalidArgument("power spectrum: empty image");
  const int wc = w / 2 + 1;
  std::vector<double> in(image.pixels);
  std::vector<std::complex<double>> out(static_cast<std::size_t>(h) * wc);
  {
    // FFTW's planner is not thread-safe; executing a plan is.
    static std::mutex planner;
    std::lock_guard<std::mutex> lock(planner);
    fftw_plan plan = fftw_plan_dft_r2c_2d(h, w, in.data(), reinterpret_cast<fftw_complex*>(out.data()), FFTW_ESTIMATE);
    if (!plan)
      throw Failure("power spectrum: FFTW could not plan a " + std::to_string(w) + "x" + std::to_string(h) +
                    " transform");
    fftw_execute(plan);
    fftw_destroy_plan(plan);
  }
  Image spectrum(w, h);
  const double norm = 1.0 / (static_cast<double>(w) * h);
  for (int ky = 0; ky < h; ++ky)
    for (int kx = 0; kx < w; ++kx) {
      // Bins past the half-spectrum are the conjugates of their mirror images.
      const bool mirrored = kx >= wc;
      const int sx = mirrored ? (w - kx) % w : kx, sy = mirrored ? (h - ky) % h : ky;
      const double p = std::norm(out[static_cast<std::size_t>(sy) * wc + sx]) * norm;
      spectrum.at((kx + w / 2) % w, (ky + h / 2) % h) = p;
    }
  return spectrum;
}

namespace {
// Signed frequency (cycles per pixel) of a shifted spectrum's column/row.
double frequency(int index, int size) { return static_cast<double>(index - size / 2) / size; }
}  // namespace

std::vector<double> radial_power_profile(const Image& spectrum, int bands) {
  if (bands < 1 || bands > 4096)
    throw InvalidArgument("radial profile: bands must be in [1, 4096], got " + std::to_string(bands));
  std::vector<double> sum(bands, 0.0);
  std::vector<std::size_t> count(bands, 0);
  for (int y = 0; y < spectrum.height; ++y)
    for (int x = 0; x < spectrum.width; ++x) {
      const double fx = frequency(x, spectrum.width), fy = frequency(y, spectrum.height);
      const double f = std::sqrt(fx * fx + fy * fy);
      if (f == 0 || f >= 0.5) continue;
      const int band = std::min(bands - 1, static_cast<int>(f / 0.5 * bands));
      sum[band] += spectrum.at(x, y);
      ++count[band];
    }
  for (int b = 0; b < bands; ++b) sum[b] = count[b] ? sum[b] / count[b] : 0.0;
  return sum;
}

double low_frequency_share(const Image& spectrum, double cutoff) {
  double low = 0.0, total = 0.0;
  for (int y = 0; y < spectrum.height; ++y)
    for (int x = 0; x < spectrum.width; ++x) {
      const double fx = frequency(x, spectrum.width), fy = frequency(y, spectrum.height);
      if (fx == 0 && fy == 0) continue;
      const double p = spectrum.at(x, y);
      total += p;
      if (fx * fx + fy * fy < cutoff * cutoff) low += p;
    }
  return total > 0 ? low / total : 0.0;
}

namespace {
struct LatticePower {
  double on = 0.0, off = 0.0;
  std::size_t n_on = 0, n_off = 0;
};

// Power on and off the lattice of multiples of 1 / period cycles per pixel.
LatticePower lattice_power(const Image& spectrum, double period) {
  if (!(period > 0) || !std::isfinite(period))
    throw InvalidArgument("tile lattice: period must be positive, got " + detail::format_number(period));
  // A bin is on the lattice when its frequency is within half a bin of a multiple of 1 / period.
  auto on_lattice = [&](int index, int size) {
    const double cycles = frequency(index, size) * period;
    return std::abs(cycles - std::round(cycles)) * size / period < 0.5;
  };
  LatticePower out;
  for (int y = 0; y < spectrum.height; ++y)
    for (int x = 0; x < spectrum.width; ++x) {
      if (x == spectrum.width / 2 && y == spectrum.height / 2) continue;
      if (on_lattice(x, spectrum.width) && on_lattice(y, spectrum.height)) {
        out.on += spectrum.at(x, y);
        ++out.n_on;
      } else {
        out.off += spectrum.at(x, y);
        ++out.n_off;
      }
    }
  return out;
}
}  // namespace

double period_peak_ratio(const Image& spectrum, double period) {
  const LatticePower p = lattice_power(spectrum, period);
  if (p.n_on == 0 || p.n_off == 0) return 1.0;
  if (p.off == 0) return p.on > 0 ? std::numeric_limits<double>::infinity() : 1.0;
  return (p.on / p.n_on) / (p.off / p.n_off);
}

double period_power_share(const Image& spectrum, double period) {
  const LatticePower p = lattice_power(spectrum, period);
  return p.on + p.off > 0 ? p.on / (p.on + p.off) : 0.0;
}

}  // namespace pds
