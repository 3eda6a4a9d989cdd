// pds render / pds render-sheet: the anti-aliasing renderer and the slides'
// comparison sheet.

#include "pds/render/render.h"

#include <chrono>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis_common.h"
#include "commands.h"
#include "pds/error.h"
#include "pds/render/png.h"

namespace pds::cli {
namespace {

using Json = nlohmann::ordered_json;

struct RenderCommonOptions {
  std::string scene = "checkerboard";
  std::string size = "512x512";
  std::string filter = "gaussian";
  std::uint64_t seed = 0;
  std::uint64_t tile_count = 4096;
  std::vector<std::string> params;
  int threads = 0;
  int reference_spp = 256;
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
  std::string output;
  std::string error_png, spectrum_png, samples_spectrum_png;
  bool metrics = false;
};

// Error measures of one rendering against the reference, as JSON.
Json measure(const Image& image, const Image& reference, const ImageSampler& sampler, Image* error_out,
             Image* spectrum_out, Image* density_spectrum = nullptr) {
  Json out;
  const double e = rmse(image, reference);
  out["rmse"] = e;
  out["psnr_db"] = std::isfinite(psnr(e)) ? Json(psnr(e)) : Json(nullptr);
  const Image error = difference(image, reference);
  const Image spectrum = power_spectrum(error);
  // White error would put pi * 0.25^2 = 19.6% of its power below a quarter cycle per pixel.
  out["error_low_frequency_share"] = low_frequency_share(spectrum, 0.25);
  // Eight rings of 1/16 cycle per pixel, as multiples of the error's mean power.
  std::vector<double> profile = radial_power_profile(spectrum, 8);
  const double mean_power = e * e;  // Parseval: mean periodogram value = mean squared error
  for (double& v : profile) v = mean_power > 0 ? v / mean_power : 0.0;
  out["error_radial_profile"] = profile;
  if (const TiledPattern* t = sampler.tiled()) {
    out["tile_points"] = t->tile_count();
    out["tile_period_px"] = t->tile_size();
    out["error_tile_peak_ratio"] = period_peak_ratio(spectrum, t->tile_size());
    out["error_power_on_tile_lattice"] = period_power_share(spectrum, t->tile_size());
  }
  if (density_spectrum || sampler.tiled()) {
    // The samples themselves, on a half-pixel grid (whole pixels for the largest
    // images): periodic patterns show
    // their tile frequency here whatever the scene.
    const int cells = std::max(image.width, image.height) <= kMaxImageSide / 2 ? 2 : 1;
    const Image density = power_spectrum(sample_density(sampler, image.width, image.height, cells));
    if (sampler.tiled())
      out["samples_power_on_tile_lattice"] = period_power_share(density, sampler.tiled()->tile_size() * cells);
    out["samples_low_frequency_share"] = low_frequency_share(density, 0.25 / cells);
    if (density_spectrum) *density_spectrum = density;
  }
  if (error_out) *error_out = error;
  if (spectrum_out) *spectrum_out = spectrum;
  return out;
}

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
  cmd->add_option("--output,-o", opt->output, "Output PNG")->required();
  cmd->add_option("--error", opt->error_png, "Also write the error image (grey 0.5 = no error, +-0.25 full scale)");
  cmd->add_option("--spectrum", opt->spectrum_png, "Also write the error's power spectrum (log scale, DC at centre)");
  cmd->add_option("--samples-spectrum", opt->samples_spectrum_png,
                  "Also write the power spectrum of the sample positions (counts on a half-pixel grid, log scale)");
  cmd->add_flag("--metrics", opt->metrics, "Print RMSE and PSNR against the reference as JSON");
  cmd->callback([opt] {
    const auto [w, h] = parse_size(opt->size);
    check_reference_spp(opt->reference_spp, w, h);
    RenderOptions ro{parse_filter(opt->filter), opt->threads};
    const auto scene = make_scene(opt->scene, w, h);
    const auto sampler = make_image_sampler(
        opt->sampler,
        {.spp = opt->spp, .seed = opt->seed, .tile_count = opt->tile_count, .params = parse_params(opt->params)});
    RenderStats stats;
    const auto start = std::chrono::steady_clock::now();
    const Image image = render(*scene, *sampler, w, h, ro, &stats);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_png(opt->output, image);
    if (!opt->metrics && opt->error_png.empty() && opt->spectrum_png.empty() && opt->samples_spectrum_png.empty())
      return;
    const Image reference = render_reference(*scene, w, h, opt->reference_spp, ro);
    Image error, spectrum, density;
    Json out;
    out["scene"] = opt->scene;
    out["sampler"] = opt->sampler;
    out["spp"] = opt->spp;
    out["filter"] = opt->filter;
    out["size"] = {w, h};
    out["seed"] = opt->seed;
    out["reference_spp"] = opt->reference_spp;
    out["samples_evaluated"] = stats.samples;
    out["empty_pixels"] = stats.empty_pixels;
    out["render_seconds"] = seconds;
    out.update(measure(image, reference, *sampler, &error, &spectrum, &density));
    if (!opt->samples_spectrum_png.empty()) write_png(opt->samples_spectrum_png, log_spectrum(density));
    if (!opt->error_png.empty()) write_png(opt->error_png, error, {-0.25, 0.25});
    if (!opt->spectrum_png.empty()) write_png(opt->spectrum_png, log_spectrum(spectrum));
    std::cout << out.dump(2) << std::endl;
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
    const Image reference = render_reference(*scene, w, h, opt->reference_spp, ro);
    const auto params = parse_params(opt->params);
    std::vector<SheetPanel> panels;
    Json rows = Json::array();
    for (int spp : opt->spps)
      for (const std::string& name : opt->samplers) {
        const auto sampler =
            make_image_sampler(name, {.spp = spp, .seed = opt->seed, .tile_count = opt->tile_count, .params = params});
        const Image image = render(*scene, *sampler, w, h, ro);
        Json row;
        row["sampler"] = name;
        row["spp"] = spp;
        row.update(measure(image, reference, *sampler, nullptr, nullptr));
        char label[160];
        std::snprintf(label, sizeof label, "%s, %d spp: RMSE %.4f", name.c_str(), spp, row["rmse"].get<double>());
        panels.push_back({image, label});
        rows.push_back(row);
      }
    std::ostringstream title;
    title << opt->scene << ", " << opt->filter << " filter, error against " << opt->reference_spp
          << " jittered spp, seed " << opt->seed;
    write_sheet(opt->output, panels, static_cast<int>(opt->samplers.size()), title.str());
    Json out;
    out["scene"] = opt->scene;
    out["size"] = {w, h};
    out["filter"] = opt->filter;
    out["reference_spp"] = opt->reference_spp;
    out["panels"] = rows;
    std::cout << out.dump(2) << std::endl;
  });
}

}  // namespace pds::cli
