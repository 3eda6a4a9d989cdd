// pds render / pds render-sheet: the anti-aliasing renderer and the slides'
// comparison sheet.

#include "pds/render/render.h"

#include <chrono>
#include <iostream>
#include <memory>
#include <sstream>

#include "analysis_common.h"
#include "commands.h"
#include "pds/error.h"
#include "pds/io/point_file.h"
#include "pds/io/render_json.h"
#include "pds/render/metrics.h"
#include "pds/render/png.h"
#include "terminal.h"

namespace pds::cli {
namespace {

struct RenderCommonOptions {
  std::string scene = "checkerboard";
  std::string size = "512x512";
  std::string filter = "gaussian";
  std::uint64_t seed = 0;
  std::uint64_t tile_count = 4096;
  std::vector<std::string> params;
  int threads = 0;
  int reference_spp = 256;
  bool quiet = false;
};

void add_common(CLI::App& cmd, RenderCommonOptions& o) {
  std::string scenes, filters;
  for (const auto& s : scene_names()) scenes += (scenes.empty() ? "" : ", ") + s;
  for (const auto& f : filter_names()) filters += (filters.empty() ? "" : ", ") + f;
  cmd.add_option("--scene", o.scene, "Scene: " + scenes)->capture_default_str();
  cmd.add_option("--size", o.size, "Image size WIDTHxHEIGHT in pixels")->capture_default_str();
  cmd.add_option("--filter", o.filter, "Reconstruction filter: " + filters)->capture_default_str();
  cmd.add_option("--seed,-s", o.seed, "Random seed; the same seed gives the same image")->capture_default_str();
  cmd.add_option("--tile-count", o.tile_count, "Points in the toroidal tile of tiled samplers")->capture_default_str();
  cmd.add_option("--param,-P", o.params, "Parameter NAME=VALUE of a tiled sampler's method (repeatable)");
  cmd.add_option("--threads,-t", o.threads, "Threads (0: all cores)")->capture_default_str();
  cmd.add_option("--reference-spp", o.reference_spp, "Jittered samples per pixel of the reference image")
      ->capture_default_str();
  cmd.add_flag("--quiet,-q", o.quiet, "No progress bar on the terminal");
}

/// run(options) with a progress bar labelled `label` in options.progress.
template <class F>
Image with_bar(const std::string& label, bool quiet, RenderOptions options, F&& run) {
  const ProgressBar bar(label, quiet);
  options.progress = bar.progress();
  return run(options);
}

std::pair<int, int> parse_size(const std::string& s) {
  int w = 0, h = 0;
  char x = 0, rest = 0;
  std::istringstream is(s);
  if (!(is >> w >> x >> h) || (x != 'x' && x != 'X') || (is >> rest))
    throw InvalidArgument("--size expects WIDTHxHEIGHT, e.g. 512x512, got '" + s + "'");
  if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
    throw InvalidArgument("--size must be between 1x1 and " + std::to_string(kMaxImageSide) + "x" +
                          std::to_string(kMaxImageSide) + ", got '" + s + "'");
  return {w, h};
}

// The reference is the expensive part: at most 2^32 samples (4096 x 4096 at
// 256 spp, minutes on this machine), so a typo cannot start an hours-long run.
void check_reference_spp(int spp, int width, int height) {
  if (spp < 1 || spp > 65536)
    throw InvalidArgument("--reference-spp must be in [1, 65536], got " + std::to_string(spp));
  const double samples = double(width) * height * spp;
  if (samples > 4294967296.0)
    throw InvalidArgument("--reference-spp " + std::to_string(spp) + " at " + std::to_string(width) + "x" +
                          std::to_string(height) + " is more than 2^32 reference samples; lower it");
}

struct RenderOptionsCli : RenderCommonOptions {
  std::string sampler = "jittered";
  int spp = 4;
  std::string tile;  // a tile file from `pds tile`, instead of generating one
  std::string output;
  std::string error_png, spectrum_png, samples_spectrum_png;
  bool metrics = false;
};

}  // namespace

void add_render(CLI::App& app) {
  auto opt = std::make_shared<RenderOptionsCli>();
  CLI::App* cmd = app.add_subcommand("render", "Render a test scene with a sampler and a reconstruction filter (PNG)");
  cmd->footer(
      "Samplers: random, jittered (per pixel), or any registry method (tiled from a toroidal tile; tiled:METHOD\n"
      "for methods named like the per-pixel ones). --error, --spectrum or --metrics also render a reference with\n"
      "--reference-spp jittered samples per pixel and print RMSE and PSNR against it as JSON.");
  add_common(*cmd, *opt);
  cmd->add_option("--sampler", opt->sampler, "Sampler")->capture_default_str();
  cmd->add_option("--spp", opt->spp, "Samples per pixel (any positive integer)")->capture_default_str();
  cmd->add_option("--tile", opt->tile,
                  "Tile the image plane with this toroidal tile (.npy or .csv on the unit torus, e.g. from pds tile) "
                  "instead of generating one");
  cmd->add_option("--output,-o", opt->output, "Output PNG")->required();
  cmd->add_option("--error", opt->error_png, "Also write the error image (grey 0.5 = no error, +-0.25 full scale)");
  cmd->add_option("--spectrum", opt->spectrum_png, "Also write the error's power spectrum (log scale, DC at centre)");
  cmd->add_option("--samples-spectrum", opt->samples_spectrum_png,
                  "Also write the power spectrum of the sample positions (counts on a half-pixel grid, log scale)");
  cmd->add_flag("--metrics", opt->metrics, "Print RMSE and PSNR against the reference as JSON");
  cmd->callback([opt, cmd] {
    const auto [w, h] = parse_size(opt->size);
    check_reference_spp(opt->reference_spp, w, h);
    RenderOptions ro{parse_filter(opt->filter), opt->threads};
    const auto scene = make_scene(opt->scene, w, h);
    const ImageSamplerOptions sampler_options{
        .spp = opt->spp, .seed = opt->seed, .tile_count = opt->tile_count, .params = parse_params(opt->params)};
    std::unique_ptr<ImageSampler> sampler;
    if (!opt->tile.empty()) {
      for (const char* name : {"--sampler", "--tile-count", "--param"})
        if (cmd->get_option(name)->count())
          throw InvalidArgument(std::string("--tile gives the pattern; ") + name + " does not apply");
      const PointCloud tile = read_points(opt->tile);
      if (tile.dim != 2)
        throw InvalidArgument("--tile: '" + opt->tile + "' has dimension " + std::to_string(tile.dim) + ", need 2");
      sampler = make_tiled_sampler("tile", tile.as<2>(), sampler_options);
    } else {
      sampler = make_image_sampler(opt->sampler, sampler_options);
    }
    RenderStats stats;
    const auto start = std::chrono::steady_clock::now();
    const Image image = with_bar("render", opt->quiet, ro, [&, w = w, h = h](const RenderOptions& o) {
      return render(*scene, *sampler, w, h, o, &stats);
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    interrupt_removes(opt->output);  // Cairo writes the file in place: Ctrl-C removes a partial one
    write_png(opt->output, image);
    interrupt_removes("");
    if (!opt->metrics && opt->error_png.empty() && opt->spectrum_png.empty() && opt->samples_spectrum_png.empty())
      return;
    const Image reference = with_bar("reference", opt->quiet, ro, [&, w = w, h = h](const RenderOptions& o) {
      return render_reference(*scene, w, h, opt->reference_spp, o);
    });
    RenderMetricImages images;
    const RenderReport report{.scene = opt->scene,
                              .sampler = opt->tile.empty() ? opt->sampler : "tile",
                              .tile_file = opt->tile,
                              .spp = opt->spp,
                              .filter = opt->filter,
                              .width = w,
                              .height = h,
                              .seed = opt->seed,
                              .reference_spp = opt->reference_spp,
                              .samples_evaluated = stats.samples,
                              .empty_pixels = stats.empty_pixels,
                              .render_seconds = seconds,
                              .metrics = measure_render(image, reference, *sampler, true, &images)};
    if (!opt->samples_spectrum_png.empty()) write_png(opt->samples_spectrum_png, log_spectrum(images.samples_spectrum));
    if (!opt->error_png.empty()) write_png(opt->error_png, images.error, {-0.25, 0.25});
    if (!opt->spectrum_png.empty()) write_png(opt->spectrum_png, log_spectrum(images.error_spectrum));
    std::cout << render_report_json(report) << std::endl;
  });
}

namespace {
struct SheetOptions : RenderCommonOptions {
  std::vector<std::string> samplers{"jittered", "best-candidate", "bridson"};
  std::vector<int> spps{1, 4};
  std::string output;
};
}  // namespace

void add_render_sheet(CLI::App& app) {
  auto opt = std::make_shared<SheetOptions>();
  opt->size = "256x256";
  CLI::App* cmd = app.add_subcommand(
      "render-sheet", "The slides' comparison: one scene through several samplers at several spp, labelled with RMSE");
  add_common(*cmd, *opt);
  cmd->add_option("--samplers", opt->samplers, "Samplers, one column each")->delimiter(',')->capture_default_str();
  cmd->add_option("--spp", opt->spps, "Samples per pixel, one row each")->delimiter(',')->capture_default_str();
  cmd->add_option("--output,-o", opt->output, "Output PNG")->required();
  cmd->callback([opt] {
    const auto [w, h] = parse_size(opt->size);
    check_reference_spp(opt->reference_spp, w, h);
    if (opt->samplers.empty() || opt->spps.empty()) throw InvalidArgument("render-sheet needs samplers and spp values");
    RenderOptions ro{parse_filter(opt->filter), opt->threads};
    const auto scene = make_scene(opt->scene, w, h);
    const Image reference = with_bar("reference", opt->quiet, ro, [&, w = w, h = h](const RenderOptions& o) {
      return render_reference(*scene, w, h, opt->reference_spp, o);
    });
    const auto params = parse_params(opt->params);
    std::vector<SheetPanel> panels;
    RenderSheetReport report{
        .scene = opt->scene, .width = w, .height = h, .filter = opt->filter, .reference_spp = opt->reference_spp};
    for (int spp : opt->spps)
      for (const std::string& name : opt->samplers) {
        const auto sampler =
            make_image_sampler(name, {.spp = spp, .seed = opt->seed, .tile_count = opt->tile_count, .params = params});
        const Image image =
            with_bar(name + " " + std::to_string(spp) + " spp", opt->quiet, ro,
                     [&, w = w, h = h](const RenderOptions& o) { return render(*scene, *sampler, w, h, o); });
        report.panels.push_back({name, spp, measure_render(image, reference, *sampler)});
        char label[160];
        std::snprintf(label, sizeof label, "%s, %d spp: RMSE %.4f", name.c_str(), spp,
                      report.panels.back().metrics.rmse);
        panels.push_back({image, label});
      }
    std::ostringstream title;
    title << opt->scene << ", " << opt->filter << " filter, error against " << opt->reference_spp
          << " jittered spp, seed " << opt->seed;
    interrupt_removes(opt->output);
    write_sheet(opt->output, panels, static_cast<int>(opt->samplers.size()), title.str());
    interrupt_removes("");
    std::cout << render_sheet_json(report) << std::endl;
  });
}

}  // namespace pds::cli
