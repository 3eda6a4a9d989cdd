#pragma once
// Where a renderer puts its samples on the image plane. Every sampler answers
// "which samples lie in this rectangle?" without generating the rest of the
// plane, deterministically for its seed, so an image can be rendered block by
// block on any number of threads and come out the same.
//
// Names (make_image_sampler):
//   random     uniform random (the "Poisson" pattern of Agu's CS 563 notes): a Poisson process
//              of spp points per pixel on average; pixel counts vary, so some
//              pixels get none (holes) and others several (clusters)
//   jittered   each pixel split into a x b strata (a * b = spp, a the largest
//              divisor of spp not above sqrt(spp)), one uniform point in each
//   sobol-pixel  per pixel, the first spp points of an Owen-scrambled Sobol'
//              (0,2)-sequence keyed by (seed, pixel), as pbrt's (0,2)-sequence
//              sampler: for spp = 2^m one sample in every elementary box
//   METHOD     any other registry method (best-candidate, bridson, halton, ...):
//              a tile of about tile_count points generated on the unit torus
//              (pds::generate with torus = true) and repeated over the plane by
//              TiledPattern, spp samples per pixel on average
//   tiled:METHOD  the same for a method whose name is taken above (tiled:jittered)
// Methods that take --count get tile_count; radius-only methods are sized by
// the registry's policy (pds::size_request: the radius at which tile_count
// points have relative radius kCountRelativeRadius), and the tile keeps
// however many points they place.

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "pds/point.h"
#include "pds/tiling/tiled_pattern.h"

namespace pds {

/// Largest spp a sampler accepts (a 512 x 512 image at this density is 2.7e11 samples).
inline constexpr int kMaxSpp = 1 << 20;

/// Largest tile a tiled sampler accepts (256 MiB of points).
inline constexpr std::uint64_t kMaxTileCount = std::uint64_t{1} << 24;

struct ImageSamplerOptions {
  int spp = 1;  // samples per pixel, >= 1
  std::uint64_t seed = 0;
  std::uint64_t tile_count = 4096;       // M, for tiled samplers
  std::map<std::string, double> params;  // method parameters, for tiled samplers
};

class ImageSampler {
 public:
  virtual ~ImageSampler() = default;
  /// Appends the positions (pixels) of the samples with x0 <= x < x1, y0 <= y < y1.
  virtual void samples_in(const PixelRect& rect, std::vector<Point<2>>& out) const = 0;
  /// The pattern behind a tiled sampler, or null.
  virtual const TiledPattern* tiled() const { return nullptr; }
  const std::string& name() const { return name_; }
  int spp() const { return spp_; }

 protected:
  ImageSampler(std::string name, int spp) : name_(std::move(name)), spp_(spp) {}

 private:
  std::string name_;
  int spp_;
};

/// The sampler called `name` (see above). Throws InvalidArgument for an
/// unknown name, spp < 1 or a tile_count the method rejects.
std::unique_ptr<ImageSampler> make_image_sampler(const std::string& name, const ImageSamplerOptions& options);

/// A tiled sampler called `name` over a given tile: a pattern on the unit
/// torus (at least one point, every coordinate in [0, 1)), e.g. one written
/// by `pds tile`. options.tile_count and options.params are not used; the
/// same tile, spp and seed give the same samples as make_image_sampler for
/// the method and count that made the tile. Throws InvalidArgument for spp
/// out of range or a tile TiledPattern rejects.
std::unique_ptr<ImageSampler> make_tiled_sampler(const std::string& name, PointSet<2> tile,
                                                 const ImageSamplerOptions& options);

/// Strata per pixel for jittered sampling: {a, b} with a * b = spp, a <= b.
std::array<int, 2> pixel_strata(int spp);

/// Generates the tile a tiled sampler uses: `method` on the unit torus with
/// about `count` points (see above); the same request as `pds tile METHOD
/// --count N`.
PointSet<2> generate_tile(const std::string& method, std::uint64_t count, std::uint64_t seed,
                          const std::map<std::string, double>& params = {});

}  // namespace pds
