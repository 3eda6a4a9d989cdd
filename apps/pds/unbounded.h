#pragma once
// pds generate METHOD --unbounded --region ...: the samples of the unbounded
// field (docs/unbounded.md) in a region, for the methods whose process the
// field is. pds unbounded and pds chunks are declared in commands.h.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "analysis_common.h"

namespace pds::cli {

struct UnboundedGenerateOptions {
  bool unbounded = false;
  std::vector<double> region;  // x0,y0[,z0],x1,y1[,z1]
};

void add_unbounded_generate_options(CLI::App& command, UnboundedGenerateOptions& options);

/// Whether --unbounded or --region was given.
inline bool unbounded_requested(const UnboundedGenerateOptions& options) {
  return options.unbounded || !options.region.empty();
}

/// Samples the field for `method` as the generation options say (--radius,
/// --seed, --max-points; --torus with --bounds for a periodic field) inside
/// --region and writes them to `output`. `command` is asked which options
/// were given: those the field does not take are refused.
void generate_unbounded(const CLI::App& command, const std::string& method, const UnboundedGenerateOptions& options,
                        const GenerationOptions& generation, const std::string& output);

}  // namespace pds::cli
