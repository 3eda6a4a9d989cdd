#pragma once
// Render reports (pds/render/metrics.h) as JSON, like report_json.h: the
// `pds render --metrics` and `pds render-sheet` output; docs/rendering.md
// says what each key means.

#include <string>

#include "pds/render/metrics.h"

namespace pds {

/// One rendering and its metrics, indented by `indent` spaces (no trailing newline).
std::string render_report_json(const RenderReport& report, int indent = 2);

/// A comparison sheet: the common settings and one object per panel.
std::string render_sheet_json(const RenderSheetReport& report, int indent = 2);

}  // namespace pds
