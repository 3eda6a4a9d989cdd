#include "pds/render/render.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "pds/error.h"
#include "pds/render/png.h"
#include "pds/rng.h"

namespace pds {
namespace {

constexpr int kSide = 128;

const std::vector<std::string> kSamplers = {"random", "jittered", "sobol-pixel", "tiled:jittered"};

std::unique_ptr<ImageSampler> sampler(const std::string& name, int spp, std::uint64_t seed) {
  return make_image_sampler(name, {.spp = spp, .seed = seed, .tile_count = 1024});
}

// The zone plate's reference, shared by the error tests (about 4 M samples).
const Image& zone_plate_reference() {
  static const Image reference = [] {
    const ZonePlateScene scene(kSide, kSide);
    return render_reference(scene, kSide, kSide, 256, {});
  }();
  return reference;
}

double zone_plate_rmse(const std::string& name, int spp, std::uint64_t seed) {
  const ZonePlateScene scene(kSide, kSide);
  return rmse(render(scene, *sampler(name, spp, seed), kSide, kSide, {}), zone_plate_reference());
}

TEST(Filter, WeightsAgreeWithPointEvaluationAndVanishAtTheRadius) {
  for (const std::string& name : filter_names()) {
    const Filter f = parse_filter(name);
    EXPECT_EQ(filter_name(f), name);
    EXPECT_EQ(f.weight(f.radius() + 1e-9), 0.0) << name;
    EXPECT_EQ(f.weight(-f.radius() - 1e-9), 0.0) << name;
    EXPECT_GT(f.weight(0.0), 0.0) << name;
    Rng rng(3);
    for (int t = 0; t < 100; ++t) {
      const double d0 = rng.uniform(-3.0, 0.0);
      double w[6];
      f.weights(d0, 6, w);
      for (int k = 0; k < 6; ++k) EXPECT_NEAR(w[k], f.weight(d0 + k), 1e-13) << name << " at " << d0 + k;
    }
  }
  // The box counts a sample in exactly the pixel that contains it, edges included.
  const Filter box = parse_filter("box");
  for (double s : {3.0, 3.25, 3.999999}) {
    int pixels = 0;
    for (int p = 0; p < 8; ++p) pixels += box.weight(p + 0.5 - s) > 0 ? 1 : 0;
    EXPECT_EQ(pixels, 1);
    EXPECT_GT(box.weight(std::floor(s) + 0.5 - s), 0.0);
  }
  EXPECT_THROW(parse_filter("lanczos"), InvalidArgument);
}

TEST(Scene, ClosedFormValues) {
  const CheckerboardScene board(512, 512);
  EXPECT_EQ(board.value(10.0, 10.0), 0.5);  // sky above the horizon (row 128)
  for (double y : {200.0, 300.5, 511.9})
    for (double x : {0.5, 100.25, 400.0}) {
      const double v = board.value(x, y);
      EXPECT_TRUE(v == 0.0 || v == 1.0);
    }
  const ZonePlateScene plate(512, 512);
  EXPECT_DOUBLE_EQ(plate.value(256.0, 256.0), 1.0);
  // Phase 2 pi r^2 / width: a whole number of cycles at r^2 = width.
  EXPECT_NEAR(plate.value(256.0 + std::sqrt(512.0), 256.0), 1.0, 1e-12);
  EXPECT_NEAR(plate.value(256.0 + std::sqrt(256.0), 256.0), 0.0, 1e-12);
  EXPECT_THROW(make_scene("teapot", 8, 8), InvalidArgument);
}

TEST(Render, ConstantSceneRendersExactly) {
  const ConstantScene scene(0.5);
  for (const std::string name : {"random", "jittered", "sobol-pixel", "tiled:jittered", "tiled:random"})
    for (const std::string& filter : filter_names())
      for (int spp : {1, 3, 4}) {
        RenderStats stats;
        const Image image = render(scene, *sampler(name, spp, 7), 48, 40, {parse_filter(filter)}, &stats);
        std::uint64_t off = 0;
        for (double v : image.pixels) off += v != 0.5;
        // Only pixels that no sample reached may differ (uniform random leaves holes).
        EXPECT_EQ(off, stats.empty_pixels) << name << " " << filter << " spp " << spp;
        if (name == "jittered") {
          EXPECT_EQ(stats.empty_pixels, 0u);
        }
      }
}

TEST(Render, SameSeedSameImageOnAnyThreadCount) {
  const CheckerboardScene scene(96, 80);
  for (const std::string& name : kSamplers) {
    const auto s = sampler(name, 4, 21);
    const Image one = render(scene, *s, 96, 80, {.threads = 1});
    const Image two = render(scene, *s, 96, 80, {.threads = 2});
    const Image again = render(scene, *sampler(name, 4, 21), 96, 80, {.threads = 0});
    const Image small_blocks = render(scene, *s, 96, 80, {.threads = 2, .block = 7});
    EXPECT_EQ(one.pixels, small_blocks.pixels) << name;
    EXPECT_EQ(one.pixels, two.pixels) << name;
    EXPECT_EQ(one.pixels, again.pixels) << name;
    EXPECT_NE(one.pixels, render(scene, *sampler(name, 4, 22), 96, 80, {}).pixels) << name;
  }
}

TEST(Render, RmseFallsAsSppGrows) {
  // Measured over seeds 1..20 (128 x 128 zone plate, Gaussian filter): random
  // 0.1995 / 0.0977 / ~0.049 at 1 / 4 / 16 spp (ratio 0.49, as 1/sqrt(4)
  // predicts); jittered 0.1866 / 0.0664 / 0.0191 (0.36, 0.29); sobol-pixel
  // 0.1865 / 0.0625 / 0.0140 (0.34, 0.22); the standard
  // deviation of one RMSE is under 0.002 (tiled) and 0.001 (per pixel), so a
  // ratio of 0.6 is more than ten of them away.
  for (const std::string& name : kSamplers) {
    const double e1 = zone_plate_rmse(name, 1, 5), e4 = zone_plate_rmse(name, 4, 5), e16 = zone_plate_rmse(name, 16, 5);
    EXPECT_LT(e4, 0.6 * e1) << name;
    EXPECT_LT(e16, 0.6 * e4) << name;
  }
}

TEST(Render, StratifiedBeatsUniformRandomOnTheZonePlate) {
  // Measured over seeds 1..20: at 1 spp random 0.1995 (sd 0.0011), jittered
  // 0.1866 (sd 0.0009), sobol-pixel 0.1865 (0.0006), tiled jittered 0.1864
  // (sd 0.0012); at 4 spp random 0.0977 (sd 0.0006), jittered 0.0664 (0.0004),
  // sobol-pixel 0.0625 (0.0003), tiled 0.0664 (0.0010).
  // Half the measured gap is over 4 standard deviations of one difference at
  // 1 spp and over 20 at 4 spp.
  for (std::uint64_t seed : {31, 32, 33}) {
    const double r1 = zone_plate_rmse("random", 1, seed), r4 = zone_plate_rmse("random", 4, seed);
    for (const std::string name : {"jittered", "sobol-pixel", "tiled:jittered"}) {
      EXPECT_LT(zone_plate_rmse(name, 1, seed), r1 - 0.5 * 0.0129) << name << " seed " << seed;
      EXPECT_LT(zone_plate_rmse(name, 4, seed), r4 - 0.5 * 0.0313) << name << " seed " << seed;
    }
  }
}

TEST(Render, RejectsBadInput) {
  const ConstantScene scene(0.5);
  const auto s = sampler("jittered", 1, 0);
  EXPECT_THROW(render(scene, *s, 0, 10, {}), InvalidArgument);
  EXPECT_THROW(render(scene, *s, 10, kMaxImageSide + 1, {}), InvalidArgument);
  EXPECT_THROW(render(scene, *s, 10, 10, {.threads = -1}), InvalidArgument);
  EXPECT_THROW(make_image_sampler("jittered", {.spp = 0}), InvalidArgument);
  EXPECT_THROW(make_image_sampler("jittered", {.spp = kMaxSpp + 1}), InvalidArgument);
  EXPECT_THROW(make_image_sampler("no-such-method", {.spp = 1}), InvalidArgument);
  EXPECT_THROW(rmse(Image(4, 4), Image(4, 5)), InvalidArgument);
}

TEST(ImageSampler, PixelCountsFollowTheirDesign) {
  // Jittered: exactly spp per pixel, one per stratum. Random: a Poisson
  // process, so the total over many pixels is near spp * pixels (5 sd) and
  // some pixels are empty at 1 spp (e^-1 of them).
  for (int spp : {1, 2, 3, 4, 6, 7}) {
    std::vector<Point<2>> points;
    sampler("jittered", spp, 1)->samples_in({-3, -3, 5, 5}, points);
    EXPECT_EQ(points.size(), static_cast<std::size_t>(64 * spp));
    const auto [a, b] = pixel_strata(spp);
    EXPECT_EQ(a * b, spp);
    EXPECT_LE(a, b);
  }
  // sobol-pixel at 16 spp: each pixel's samples are a (0,4,2)-net, one sample in
  // every elementary box of 2^-a by 2^-(4-a) of the pixel.
  for (int px = -2; px < 3; ++px) {
    std::vector<Point<2>> net;
    sampler("sobol-pixel", 16, 9)->samples_in({double(px), 5, px + 1.0, 6}, net);
    ASSERT_EQ(net.size(), 16u);
    for (int a = 0; a <= 4; ++a) {
      std::vector<int> boxes(16, 0);
      for (const auto& p : net)
        ++boxes[static_cast<int>((p[0] - px) * (1 << a)) * (1 << (4 - a)) +
                static_cast<int>((p[1] - 5) * (1 << (4 - a)))];
      for (int b : boxes) EXPECT_EQ(b, 1) << "pixel " << px << " boxes 2^-" << a;
    }
  }
  std::vector<Point<2>> points;
  sampler("random", 1, 1)->samples_in({0, 0, 100, 100}, points);
  EXPECT_NEAR(static_cast<double>(points.size()), 10000.0, 5 * 100.0);
  std::vector<int> per_pixel(10000, 0);
  for (const auto& p : points) ++per_pixel[static_cast<int>(p[1]) * 100 + static_cast<int>(p[0])];
  const double empty = static_cast<double>(std::count(per_pixel.begin(), per_pixel.end(), 0));
  EXPECT_NEAR(empty, 10000 * std::exp(-1.0), 5 * std::sqrt(10000 * std::exp(-1.0) * (1 - std::exp(-1.0))));
}

TEST(Spectrum, TiledSamplesPutAllTheirPowerOnTheTileFrequencies) {
  // The known weakness of tiling: a window holding whole copies sees an exactly
  // periodic pattern, so its periodogram lives on multiples of 1 / S. Uniform
  // random samples spread theirs evenly: the window holds 4 x 4 copies, so one
  // bin in 16 is on that lattice and gets about 1/16 of the power (each share
  // sums about 1000 bins, a relative spread near 3%; 1.5 times is far off).
  const auto tiled = make_image_sampler("tiled:random", {.spp = 1, .seed = 3, .tile_count = 256});  // S = 16
  const Image tiled_density = power_spectrum(sample_density(*tiled, 64, 64, 2));
  EXPECT_GT(period_power_share(tiled_density, 32.0), 1.0 - 1e-9);
  const Image random_density = power_spectrum(sample_density(*sampler("random", 1, 3), 64, 64, 2));
  EXPECT_LT(period_power_share(random_density, 32.0), 1.5 / 16);
}

TEST(Spectrum, ParsevalAndPeriodicPeaks) {
  Image noise(64, 48);
  Rng rng(1);
  for (double& v : noise.pixels) v = rng.uniform(-1, 1);
  const Image spectrum = power_spectrum(noise);
  double energy = 0, power = 0;
  for (double v : noise.pixels) energy += v * v;
  for (double p : spectrum.pixels) power += p;
  EXPECT_NEAR(power, energy, 1e-9 * energy);
  EXPECT_NEAR(period_peak_ratio(spectrum, 8.0), 1.0, 0.5);
  // White noise: a flat radial profile at the mean power (about 1/3 for U(-1, 1)).
  for (double band : radial_power_profile(spectrum, 4)) EXPECT_NEAR(band, 1.0 / 3, 0.1);
  // White noise puts pi c^2 of its power below c cycles per pixel.
  EXPECT_NEAR(low_frequency_share(spectrum, 0.25), std::numbers::pi * 0.0625, 0.05);
  // Repeating an 8 x 8 block: all power on multiples of 1/8 cycle per pixel.
  Image periodic(64, 48);
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) periodic.at(x, y) = noise.at(x % 8, y % 8);
  EXPECT_GT(period_peak_ratio(power_spectrum(periodic), 8.0), 1e6);
  EXPECT_NEAR(period_power_share(power_spectrum(periodic), 8.0), 1.0, 1e-12);
  EXPECT_NEAR(period_power_share(spectrum, 8.0), 1.0 / 64, 0.01);
}

TEST(Png, WrittenFilesAreValidPngsWithTheImage) {
  const auto dir = std::filesystem::temp_directory_path() / ("pds_png_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const ZonePlateScene scene(40, 30);
  const Image image = render(scene, *sampler("jittered", 2, 1), 40, 30, {});
  const std::string path = (dir / "plate.png").string();
  write_png(path, image);
  const Image back = read_png(path);
  ASSERT_EQ(back.width, 40);
  ASSERT_EQ(back.height, 30);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    ASSERT_NEAR(back.pixels[i], std::clamp(image.pixels[i], 0.0, 1.0), 0.5 / 255 + 1e-12);
  const std::string sheet = (dir / "sheet.png").string();
  write_sheet(sheet, {{image, "a"}, {image, "b"}, {image, "c"}}, 2, "title");
  const Image s = read_png(sheet);
  EXPECT_GT(s.width, 2 * 40);
  EXPECT_GT(s.height, 2 * 30);
  // The PNG signature, as any decoder checks it.
  std::FILE* f = std::fopen(path.c_str(), "rb");
  ASSERT_NE(f, nullptr);
  unsigned char sig[8] = {};
  ASSERT_EQ(std::fread(sig, 1, 8, f), 8u);
  std::fclose(f);
  const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  EXPECT_TRUE(std::equal(sig, sig + 8, png));
  EXPECT_THROW(read_png((dir / "missing.png").string()), InvalidArgument);
  EXPECT_THROW(write_png((dir / "no" / "such" / "dir.png").string(), image), Failure);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pds
