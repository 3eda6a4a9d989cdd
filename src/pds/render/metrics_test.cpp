#include "pds/render/metrics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pds/error.h"

namespace pds {
namespace {

struct Rendered {
  std::unique_ptr<ImageSampler> sampler;
  Image image;
};

Rendered render_with(const std::string& sampler_name, int spp, int side) {
  const auto scene = make_scene("zone-plate", side, side);
  auto sampler = make_image_sampler(sampler_name, {.spp = spp, .seed = 5, .tile_count = 256});
  Image image = render(*scene, *sampler, side, side, {parse_filter("box"), 1});
  return {std::move(sampler), std::move(image)};
}

TEST(RenderMetrics, AgainstItselfNoError) {
  const Rendered r = render_with("jittered", 4, 32);
  const RenderMetrics m = measure_render(r.image, r.image, *r.sampler);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr_db));
  ASSERT_EQ(m.error_radial_profile.size(), 8u);
  for (double v : m.error_radial_profile) EXPECT_EQ(v, 0.0);
  EXPECT_FALSE(m.tile);
  EXPECT_FALSE(m.samples_low_frequency_share);
}

TEST(RenderMetrics, ErrorImageIsTheDifferenceAndParsevalHolds) {
  const int side = 32;
  const Rendered r = render_with("random", 1, side);
  const Image reference =
      render_reference(*make_scene("zone-plate", side, side), side, side, 16, {parse_filter("box"), 1});
  RenderMetricImages images;
  const RenderMetrics m = measure_render(r.image, reference, *r.sampler, true, &images);
  ASSERT_EQ(images.error.pixels.size(), r.image.pixels.size());
  double squares = 0, power = 0;
  for (std::size_t i = 0; i < r.image.pixels.size(); ++i) {
    EXPECT_EQ(images.error.pixels[i], r.image.pixels[i] - reference.pixels[i]);
    squares += images.error.pixels[i] * images.error.pixels[i];
  }
  for (double p : images.error_spectrum.pixels) power += p;
  EXPECT_NEAR(m.rmse, std::sqrt(squares / r.image.pixels.size()), 1e-15);
  EXPECT_NEAR(power / images.error_spectrum.pixels.size(), m.rmse * m.rmse, 1e-12);  // Parseval
  EXPECT_NEAR(m.psnr_db, -20 * std::log10(m.rmse), 1e-9);
  EXPECT_GT(m.error_low_frequency_share, 0.0);
  EXPECT_LT(m.error_low_frequency_share, 1.0);
  ASSERT_TRUE(m.samples_low_frequency_share);  // asked for
  EXPECT_EQ(images.samples_spectrum.width, 2 * side);
}

TEST(RenderMetrics, TiledSamplerShowsItsPeriod) {
  // 256 white-noise points at 4 spp: a tile of 8 x 8 pixels, 16 half-pixel
  // cells, so the sample density of a 64 x 64 image is exactly periodic and
  // all its power (but the mean's) lies on the tile lattice. (A jittered tile
  // would put one sample in every cell: no power at all.)
  const Rendered r = render_with("tiled:random", 4, 64);
  const RenderMetrics m = measure_render(r.image, r.image, *r.sampler);
  ASSERT_TRUE(m.tile);
  EXPECT_EQ(m.tile->tile_points, 256u);
  EXPECT_EQ(m.tile->tile_period_px, 8.0);
  EXPECT_GT(m.tile->samples_power_on_tile_lattice, 0.999);
  ASSERT_TRUE(m.samples_low_frequency_share);
}

TEST(RenderMetrics, RejectsImagesOfDifferentSizes) {
  const Rendered r = render_with("jittered", 1, 16);
  EXPECT_THROW(measure_render(r.image, Image(8, 8), *r.sampler), InvalidArgument);
}

TEST(TiledSampler, GivenTileGivesTheSameSamplesAsTheMethod) {
  const ImageSamplerOptions options{.spp = 3, .seed = 9, .tile_count = 300};
  const auto by_method = make_image_sampler("best-candidate", options);
  const auto by_tile = make_tiled_sampler("tile", generate_tile("best-candidate", 300, 9), options);
  std::vector<Point<2>> a, b;
  by_method->samples_in({-7.5, 3, 40, 51}, a);
  by_tile->samples_in({-7.5, 3, 40, 51}, b);
  EXPECT_EQ(a, b);
  EXPECT_FALSE(a.empty());
  EXPECT_THROW(make_tiled_sampler("tile", PointSet<2>{{0.5, 1.0}}, options), InvalidArgument);
  EXPECT_THROW(make_tiled_sampler("tile", PointSet<2>{}, options), InvalidArgument);
}

}  // namespace
}  // namespace pds
