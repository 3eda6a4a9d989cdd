// Render reports as JSON (include/pds/io/render_json.h), through
// nlohmann::json as report_json.cpp.

#include "pds/io/render_json.h"

#include <nlohmann/json.hpp>

namespace pds {
namespace {

using Json = nlohmann::ordered_json;

void add_metrics(Json& out, const RenderMetrics& m) {
  out["rmse"] = m.rmse;
  out["psnr_db"] = m.psnr_db;
  out["error_low_frequency_share"] = m.error_low_frequency_share;
  out["error_radial_profile"] = m.error_radial_profile;
  if (m.tile) {
    out["tile_points"] = m.tile->tile_points;
    out["tile_period_px"] = m.tile->tile_period_px;
    out["error_tile_peak_ratio"] = m.tile->error_tile_peak_ratio;
    out["error_power_on_tile_lattice"] = m.tile->error_power_on_tile_lattice;
  }
  if (m.tile && m.samples_low_frequency_share)
    out["samples_power_on_tile_lattice"] = m.tile->samples_power_on_tile_lattice;
  if (m.samples_low_frequency_share) out["samples_low_frequency_share"] = *m.samples_low_frequency_share;
}

}  // namespace

std::string render_report_json(const RenderReport& r, int indent) {
  Json out;
  out["scene"] = r.scene;
  out["sampler"] = r.sampler;
  if (!r.tile_file.empty()) out["tile_file"] = r.tile_file;
  out["spp"] = r.spp;
  out["filter"] = r.filter;
  out["size"] = {r.width, r.height};
  out["seed"] = r.seed;
  out["reference_spp"] = r.reference_spp;
  out["samples_evaluated"] = r.samples_evaluated;
  out["empty_pixels"] = r.empty_pixels;
  out["render_seconds"] = r.render_seconds;
  add_metrics(out, r.metrics);
  return out.dump(indent);
}

std::string render_sheet_json(const RenderSheetReport& r, int indent) {
  Json rows = Json::array();
  for (const RenderSheetReport::Panel& p : r.panels) {
    Json row;
    row["sampler"] = p.sampler;
    row["spp"] = p.spp;
    add_metrics(row, p.metrics);
    rows.push_back(row);
  }
  Json out;
  out["scene"] = r.scene;
  out["size"] = {r.width, r.height};
  out["filter"] = r.filter;
  out["reference_spp"] = r.reference_spp;
  out["panels"] = rows;
  return out.dump(indent);
}

}  // namespace pds
