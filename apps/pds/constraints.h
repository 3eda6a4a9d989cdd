#pragma once
// pds generate's spatial constraints (docs/density.md): --density with
// --radius-range and --invert, --mask, --polygons, --fixed, turned into the
// request's RequestConstraints.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "pds/registry.h"

namespace pds::cli {

struct ConstraintOptions {
  std::string density;               // grayscale PNG: dark = small radius (dense)
  std::vector<double> radius_range;  // rmin,rmax for --density
  bool invert = false;               // light = dense
  std::string mask;                  // PNG: samples where the pixel is dark
  std::string polygons;              // GeoJSON: samples inside the polygons
  std::string fixed;                 // CSV/NPY: points kept first in the output
};

void add_constraint_options(CLI::App& command, ConstraintOptions& options);

/// Reads the files the options name into request.constraints (after the
/// request's dimension and bounds are set). Throws InvalidArgument for bad
/// files or options that do not go together.
void apply_constraint_options(const ConstraintOptions& options, GenerateRequest& request);

}  // namespace pds::cli
