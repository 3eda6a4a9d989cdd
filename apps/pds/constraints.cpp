// pds generate --density/--mask/--polygons/--fixed: images and polygons
// mapped onto --bounds, read into the request's constraints.

#include "constraints.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/io/geojson.h"
#include "pds/io/point_file.h"
#include "pds/render/image_field.h"
#include "pds/render/png.h"

namespace pds::cli {
namespace {

ImageOnBounds image_on_bounds(const std::string& path, const std::vector<double>& lo, const std::vector<double>& hi) {
  return ImageOnBounds(read_png(path), Point<2>{{lo[0], lo[1]}}, Point<2>{{hi[0], hi[1]}});
}

void require_plane(const GenerateRequest& request, const char* option) {
  if (request.dim != 2)
    throw InvalidArgument(std::string(option) +
                          " needs --dim 2 (an image or polygons cover the plane), got dimension " +
                          std::to_string(request.dim));
}

}  // namespace

void add_constraint_options(CLI::App& command, ConstraintOptions& o) {
  command.add_option("--density", o.density,
                     "Grayscale PNG over --bounds: black at rmin (dense), white at rmax; needs --radius-range");
  command.add_option("--radius-range", o.radius_range, "rmin,rmax of --density (instead of --radius)")
      ->delimiter(',')
      ->expected(2);
  command.add_flag("--invert", o.invert, "With --density: white at rmin (dense), black at rmax");
  command.add_option("--mask", o.mask, "PNG over --bounds: samples only where the pixel is dark (grey < 0.5)");
  command.add_option("--polygons", o.polygons, "GeoJSON Polygon/MultiPolygon (holes too): samples only inside");
  command.add_option("--fixed", o.fixed, "CSV/NPY points kept as the first rows of the output; filled around");
}

void apply_constraint_options(const ConstraintOptions& o, GenerateRequest& request) {
  RequestConstraints& c = request.constraints;
  if (o.density.empty() != o.radius_range.empty())
    throw InvalidArgument(o.density.empty() ? "--radius-range needs --density"
                                            : "--density needs --radius-range rmin,rmax");
  if (o.invert && o.density.empty()) throw InvalidArgument("--invert needs --density");
  std::vector<double> lo, hi;
  if (!o.density.empty() || !o.mask.empty() || !o.polygons.empty()) {
    require_plane(request, !o.density.empty() ? "--density" : !o.mask.empty() ? "--mask" : "--polygons");
    request.bounds(lo, hi);
  }
  if (!o.density.empty()) {
    const double rmin = o.radius_range[0], rmax = o.radius_range[1];
    require_radius(rmin, "rmin");
    require_radius(rmax, "rmax");
    if (!(rmin <= rmax))
      throw InvalidArgument("--radius-range needs rmin <= rmax, got " + detail::format_number(rmin) + "," +
                            detail::format_number(rmax));
    const auto field = radius_from_image(image_on_bounds(o.density, lo, hi), rmin, rmax, o.invert);
    c.rmin = rmin;
    c.rmax = rmax;
    c.radius = [field](const double* x) { return field(Point<2>{{x[0], x[1]}}); };
  }
  std::function<bool(const double*)> mask, region;
  if (!o.mask.empty()) {
    mask = [on = mask_from_image(image_on_bounds(o.mask, lo, hi))](const double* x) {
      return on(Point<2>{{x[0], x[1]}});
    };
  }
  if (!o.polygons.empty()) {
    auto polygons = std::make_shared<const Region>(read_geojson(o.polygons));
    region = [polygons](const double* x) { return polygons->contains(Point<2>{{x[0], x[1]}}); };
  }
  if (mask && region)
    c.inside = [mask, region](const double* x) { return mask(x) && region(x); };
  else
    c.inside = mask ? mask : region;
  if (!o.fixed.empty()) {
    c.fixed = read_points(o.fixed);
    if (c.fixed.size() == 0) throw InvalidArgument(o.fixed + ": no points");
  }
}

}  // namespace pds::cli
