#pragma once
// pds generate dart-throwing --classes R1,R2,...: several classes of samples
// with their own radii (Wei 2010; docs/density.md, "Several classes").

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "analysis_common.h"

namespace pds::cli {

struct ClassOptions {
  std::vector<double> radii;   // one a class
  std::vector<double> matrix;  // k x k, row-major; empty: Wei's rule
};

void add_class_options(CLI::App& command, ClassOptions& options);

inline bool classes_requested(const ClassOptions& options) { return !options.radii.empty(); }

/// Runs pds::multi_class on the request's domain and writes the coordinates
/// and a `class` column to `output`. Options that do not apply (--count,
/// --radius, the constraints, --mesh, float32) are refused.
void generate_classes(const CLI::App& command, const std::string& method, const ClassOptions& options,
                      const GenerationOptions& generation, const std::string& output);

}  // namespace pds::cli
