#pragma once
// The analysis report (pds/analysis/report.h) as JSON: one object, keys in
// a fixed order, numbers in their shortest round-trip form, null for
// measures that do not exist (non-finite or skipped). The `pds analyze`
// output; docs/analysis.md and docs/verification.md say what each key means.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pds/analysis/report.h"

namespace pds {

/// Where the analysed sets came from, written before the measures: the files
/// read ("file": the first, "files": all of them when there are several), or
/// the method that generated them and the seed of the first set.
struct AnalysisSource {
  std::vector<std::string> files;
  std::string method;
  std::uint64_t seed = 0;  // with method
};

/// The report as a JSON object indented by `indent` spaces (no trailing newline).
std::string analysis_report_json(const AnalysisReport& report, const AnalysisSource& source = {}, int indent = 2);

}  // namespace pds
