#pragma once
// Error measures of a rendering against its reference (docs/rendering.md),
// as plain structs any front end fills by one call (`pds render`, `pds
// render-sheet`, a Python module) and writes as it likes (JSON:
// pds/io/report_json.h).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pds/render/image_sampler.h"
#include "pds/render/render.h"

namespace pds {

/// What a tiled sampler's period does to the error and to the samples
/// (docs/tiling.md): power on the lattice of multiples of 1 / tile period.
struct TileMetrics {
  std::size_t tile_points = 0;
  double tile_period_px = 0;                 // S, the side of one copy of the tile
  double error_tile_peak_ratio = 0;          // period_peak_ratio of the error's spectrum
  double error_power_on_tile_lattice = 0;    // period_power_share of the error's spectrum
  double samples_power_on_tile_lattice = 0;  // period_power_share of the samples' density spectrum
};

struct RenderMetrics {
  double rmse = 0;
  double psnr_db = 0;  // inf for an image equal to its reference
  /// Share of the error's power below a quarter cycle per pixel; white error
  /// puts pi * 0.25^2 = 19.6% there.
  double error_low_frequency_share = 0;
  /// Eight rings of 1/16 cycle per pixel, as multiples of the error's mean
  /// power (so 1 throughout for white error).
  std::vector<double> error_radial_profile;
  std::optional<TileMetrics> tile;  // tiled samplers only
  /// low_frequency_share of the samples' density spectrum, below a quarter
  /// cycle per pixel; measured for tiled samplers and when asked for.
  std::optional<double> samples_low_frequency_share;
};

/// The images the metrics were taken from, for pictures.
struct RenderMetricImages {
  Image error;             // image - reference
  Image error_spectrum;    // power_spectrum(error)
  Image samples_spectrum;  // power spectrum of the sample density; empty unless measured
};

/// Measures `image` (rendered with `sampler`) against `reference`.
/// `samples_spectrum` asks for the spectrum of the sample positions for
/// untiled samplers too (tiled ones always get it): on a half-pixel grid, or
/// whole pixels for images wider than kMaxImageSide / 2. Fills `images`, if
/// given. Throws InvalidArgument for images of different sizes.
RenderMetrics measure_render(const Image& image, const Image& reference, const ImageSampler& sampler,
                             bool samples_spectrum = false, RenderMetricImages* images = nullptr);

/// One rendering and its measures, as `pds render --metrics` reports it.
struct RenderReport {
  std::string scene;
  std::string sampler;
  std::string tile_file;  // the tile a tiled sampler read, if it read one
  int spp = 0;
  std::string filter;
  int width = 0, height = 0;
  std::uint64_t seed = 0;
  int reference_spp = 0;
  std::uint64_t samples_evaluated = 0;
  std::uint64_t empty_pixels = 0;
  double render_seconds = 0;
  RenderMetrics metrics;
};

/// A comparison sheet: one scene through several samplers at several spp.
struct RenderSheetReport {
  struct Panel {
    std::string sampler;
    int spp = 0;
    RenderMetrics metrics;
  };
  std::string scene;
  int width = 0, height = 0;
  std::string filter;
  int reference_spp = 0;
  std::vector<Panel> panels;
};

}  // namespace pds
