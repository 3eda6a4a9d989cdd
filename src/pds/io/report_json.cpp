// The analysis report as JSON (include/pds/io/report_json.h), through
// nlohmann::json, which keeps the keys in insertion order and writes doubles
// in their shortest round-trip form (and non-finite ones as null).

#include "pds/io/report_json.h"

#include <nlohmann/json.hpp>

namespace pds {
namespace {

using Json = nlohmann::ordered_json;

template <class T>
Json optional_or_null(const std::optional<T>& v) {
  return v ? Json(*v) : Json(nullptr);
}

}  // namespace

std::string analysis_report_json(const AnalysisReport& r, const AnalysisSource& source, int indent) {
  Json out;
  if (!source.files.empty()) {
    out["file"] = source.files.front();
    if (source.files.size() > 1) out["files"] = source.files;
  }
  if (!source.method.empty()) {
    out["method"] = source.method;
    out["seed"] = source.seed;
  }
  out["count"] = r.count;
  out["dim"] = r.dim;
  out["domain"] = {{"lo", r.lo}, {"hi", r.hi}, {"torus", r.torus}};
  out["min_distance"] = r.min_distance;
  if (r.min_distance_pair) out["min_distance_pair"] = *r.min_distance_pair;
  out["mean_nn_distance"] = r.mean_nn_distance;
  out["relative_radius"] = r.relative_radius;
  if (!r.relative_radius_note.empty()) out["relative_radius_note"] = r.relative_radius_note;
  out["max_packing_radius"] = r.max_packing_radius;
  if (r.radius) {
    out["radius"] = *r.radius;
    out["min_distance_holds"] = r.min_distance_holds;
    if (r.maximality) {
      const MaximalityReport& mx = *r.maximality;
      out["maximal"] = mx.maximal;
      Json detail;
      detail["exact"] = mx.exact;
      detail["tolerance"] = mx.tolerance;
      if (mx.gap) {
        detail["gap"] = *mx.gap;
        detail["gap_distance"] = mx.gap_distance;
      }
      detail["cells_checked"] = mx.cells_checked;
      if (mx.budget_exhausted) detail["budget_exhausted"] = true;
      out["maximality"] = detail;
    } else if (!r.maximality_note.empty()) {
      out["maximality_note"] = r.maximality_note;
    }
  }
  out["sets"] = r.sets;
  out["rho_min"] = r.rho_min;
  out["rho_mean"] = r.rho_mean;
  out["l2_star_discrepancy"] = optional_or_null(r.l2_star_discrepancy);
  out["star_discrepancy"] = optional_or_null(r.star_discrepancy);
  // SciPy's qmc.discrepancy methods (CD, WD, MD are squares there and here).
  out["centered_discrepancy"] = optional_or_null(r.centered_discrepancy);
  out["wrap_around_discrepancy"] = optional_or_null(r.wrap_around_discrepancy);
  out["mixture_discrepancy"] = optional_or_null(r.mixture_discrepancy);
  if (r.spectrum) {
    const SpectrumSummary& s = *r.spectrum;
    Json spec;
    spec["max_frequency"] = s.max_frequency;
    spec["low_frequency_power"] = s.low_frequency_power;
    spec["peak_frequency"] = s.peak_frequency;
    spec["peak_power"] = s.peak_power;
    spec["mean_anisotropy_db"] = s.mean_anisotropy_db;
    out["spectrum"] = spec;
  } else {
    out["spectrum"] = nullptr;
    if (!r.spectrum_note.empty()) out["spectrum_note"] = r.spectrum_note;
  }
  if (r.pcf)
    out["pcf"] = {
        {"bandwidth", r.pcf->bandwidth}, {"r_max", r.pcf->r_max}, {"peak_r", r.pcf->peak_r}, {"peak_g", r.pcf->peak_g}};
  else
    out["pcf"] = nullptr;
  if (!r.pcf_note.empty()) out["pcf_note"] = r.pcf_note;
  return out.dump(indent);
}

}  // namespace pds
