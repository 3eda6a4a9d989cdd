// Image-plane samplers (see include/pds/render/image_sampler.h).
//
// Per-pixel samplers draw a pixel's samples from a generator keyed by (seed,
// pixel), so a pixel's samples do not depend on which rectangle asked for them
// or on the order of the queries. Tiled samplers delegate to TiledPattern.

#include "pds/detail/format.h"
#include "pds/render/image_sampler.h"

#include <algorithm>
#include <cmath>

#include "pds/error.h"
#include "pds/portable_math.h"
#include "pds/registry.h"
#include "pds/rng.h"
#include "pds/samplers/sobol.h"

namespace pds {

std::array<int, 2> pixel_strata(int spp) {
  int a = static_cast<int>(std::sqrt(static_cast<double>(spp)));
  while (a > 1 && spp % a != 0) --a;
  return {a, spp / a};
}

PointSet<2> generate_tile(const std::string& method, std::uint64_t count, std::uint64_t seed,
                          const std::map<std::string, double>& params) {
  GenerateRequest request;
  request.dim = 2;
  request.torus = true;
  request.seed = seed;
  request.params = params;
  request.count = count;
  const PointCloud cloud = generate(method, size_request(find_method(method), request));
  if (cloud.size() == 0) throw Failure("tile: method " + method + " returned no points");
  return cloud.as<2>();
}

namespace {

// Calls f(px, py) for every pixel the rectangle overlaps.
template <class F>
void for_each_pixel(const PixelRect& r, F&& f) {
  if (!(r.x1 > r.x0) || !(r.y1 > r.y0)) return;
  const auto x0 = static_cast<std::int64_t>(std::floor(r.x0)), x1 = static_cast<std::int64_t>(std::ceil(r.x1));
  const auto y0 = static_cast<std::int64_t>(std::floor(r.y0)), y1 = static_cast<std::int64_t>(std::ceil(r.y1));
  for (std::int64_t py = y0; py < y1; ++py)
    for (std::int64_t px = x0; px < x1; ++px) f(px, py);
}

void check_rect(const PixelRect& r) {
  for (double v : {r.x0, r.y0, r.x1, r.y1})
    if (!std::isfinite(v) || std::abs(v) > 1e15)
      throw InvalidArgument("image sampler: rectangle coordinate " + detail::format_number(v) + " is not a usable pixel");
}

// The homogeneous Poisson process of intensity spp: restricted to one pixel it
// is a Poisson(spp) number of independent uniform points, and pixels are
// independent, so each pixel can be drawn on its own.
class RandomSampler : public ImageSampler {
 public:
  RandomSampler(int spp, std::uint64_t seed) : ImageSampler("random", spp), seed_(seed) {}
  void samples_in(const PixelRect& r, std::vector<Point<2>>& out) const override {
    check_rect(r);
    for_each_pixel(r, [&](std::int64_t px, std::int64_t py) {
      Rng rng(seed_, {static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py)});
      // The portable draw (pds/portable_math.h): the same count on every platform.
      const std::uint64_t n = poisson(static_cast<double>(spp()), rng);
      for (std::uint64_t i = 0; i < n; ++i) {
        const double x = static_cast<double>(px) + rng.uniform(), y = static_cast<double>(py) + rng.uniform();
        if (r.contains(x, y)) out.push_back(Point<2>{{x, y}});
      }
    });
  }

 private:
  std::uint64_t seed_;
};

class JitteredSampler : public ImageSampler {
 public:
  JitteredSampler(int spp, std::uint64_t seed)
      : ImageSampler("jittered", spp), seed_(seed), strata_(pixel_strata(spp)) {}
  void samples_in(const PixelRect& r, std::vector<Point<2>>& out) const override {
    check_rect(r);
    const int a = strata_[0], b = strata_[1];  // not a structured binding: clang 14 cannot capture one
    for_each_pixel(r, [&](std::int64_t px, std::int64_t py) {
      Rng rng(seed_, {static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py)});
      for (int j = 0; j < b; ++j)
        for (int i = 0; i < a; ++i) {
          const double x = static_cast<double>(px) + (i + rng.uniform()) / a;
          const double y = static_cast<double>(py) + (j + rng.uniform()) / b;
          if (r.contains(x, y)) out.push_back(Point<2>{{x, y}});
        }
    });
  }

 private:
  std::uint64_t seed_;
  std::array<int, 2> strata_;
};

// Per pixel, the first spp points of a Sobol' (0,2)-sequence with Owen
// scrambling keyed by (seed, pixel): pbrt's (0,2)-sequence sampler. For spp a
// power of two every pixel's samples form a (0,m,2)-net (one in every
// elementary box of the pixel), and pixels are decorrelated by their scrambles.
class SobolPixelSampler : public ImageSampler {
 public:
  SobolPixelSampler(int spp, std::uint64_t seed) : ImageSampler("sobol-pixel", spp), seed_(seed) {}
  void samples_in(const PixelRect& r, std::vector<Point<2>>& out) const override {
    check_rect(r);
    const SobolParams params{.count = static_cast<std::uint64_t>(spp()), .first = 0, .scramble = Scramble::owen};
    for_each_pixel(r, [&](std::int64_t px, std::int64_t py) {
      const std::uint64_t key = mix64(mix64(seed_ ^ static_cast<std::uint64_t>(px)) + static_cast<std::uint64_t>(py));
      for (const Point<2>& u : sobol<2>(params, Domain<2>::unit(), key)) {
        const double x = static_cast<double>(px) + u[0], y = static_cast<double>(py) + u[1];
        if (r.contains(x, y)) out.push_back(Point<2>{{x, y}});
      }
    });
  }

 private:
  std::uint64_t seed_;
};

class TiledSampler : public ImageSampler {
 public:
  TiledSampler(const std::string& name, PointSet<2> tile, const ImageSamplerOptions& o)
      : ImageSampler(name, o.spp), pattern_(std::move(tile), o.spp, TiledPatternOptions{0, o.seed}) {}
  void samples_in(const PixelRect& r, std::vector<Point<2>>& out) const override { pattern_.samples_in(r, out); }
  const TiledPattern* tiled() const override { return &pattern_; }

 private:
  TiledPattern pattern_;
};

void check_spp(int spp) {
  if (spp < 1 || spp > kMaxSpp)
    throw InvalidArgument("spp (samples per pixel) must be in [1, " + std::to_string(kMaxSpp) + "], got " +
                          std::to_string(spp));
}

}  // namespace

std::unique_ptr<ImageSampler> make_tiled_sampler(const std::string& name, PointSet<2> tile,
                                                 const ImageSamplerOptions& options) {
  check_spp(options.spp);
  if (tile.size() > kMaxTileCount)
    throw InvalidArgument("tile count must be in [1, " + std::to_string(kMaxTileCount) + "], got " +
                          std::to_string(tile.size()));
  return std::make_unique<TiledSampler>(name, std::move(tile), options);
}

std::unique_ptr<ImageSampler> make_image_sampler(const std::string& name, const ImageSamplerOptions& options) {
  check_spp(options.spp);
  const bool per_pixel = name == "random" || name == "jittered" || name == "sobol-pixel";
  if (per_pixel && !options.params.empty())
    throw InvalidArgument("sampler " + name + " takes no method parameters (--param is for tiled samplers, got " +
                          options.params.begin()->first + ")");
  if (name == "random") return std::make_unique<RandomSampler>(options.spp, options.seed);
  if (name == "jittered") return std::make_unique<JitteredSampler>(options.spp, options.seed);
  if (name == "sobol-pixel") return std::make_unique<SobolPixelSampler>(options.spp, options.seed);
  const std::string prefix = "tiled:";
  const std::string method = name.rfind(prefix, 0) == 0 ? name.substr(prefix.size()) : name;
  if (options.tile_count < 1 || options.tile_count > kMaxTileCount)
    throw InvalidArgument("tile count must be in [1, " + std::to_string(kMaxTileCount) + "], got " +
                          std::to_string(options.tile_count));
  return std::make_unique<TiledSampler>(name, generate_tile(method, options.tile_count, options.seed, options.params),
                                        options);
}

}  // namespace pds
