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
#include "pds/render/png.h"

namespace pds::cli {
namespace {

// A grey image laid over the plane's bounds, its top row at the upper y bound
// (as the point plots draw it).
struct ImageOnBounds {
  std::shared_ptr<const Image> image;
  double x0, y1, sx, sy;  // pixels per unit along x and (downward) y

  ImageOnBounds(const std::string& path, const std::vector<double>& lo, const std::vector<double>& hi)
      : image(std::make_shared<const Image>(read_png(path))),
        x0(lo[0]),
        y1(hi[1]),
        sx(image->width / (hi[0] - lo[0])),
        sy(image->height / (hi[1] - lo[1])) {}

  // The pixel under x.
  double nearest(const double* x) const {
    const int px = std::clamp(static_cast<int>(std::floor((x[0] - x0) * sx)), 0, image->width - 1);
    const int py = std::clamp(static_cast<int>(std::floor((y1 - x[1]) * sy)), 0, image->height - 1);
    return image->at(px, py);
  }

  // Bilinear between pixel centres, constant beyond the outer ones.
  double smooth(const double* x) const {
    const double u = std::clamp((x[0] - x0) * sx - 0.5, 0.0, image->width - 1.0);
    const double v = std::clamp((y1 - x[1]) * sy - 0.5, 0.0, image->height - 1.0);
    const int i = std::max(0, std::min(static_cast<int>(u), image->width - 2));
    const int j = std::max(0, std::min(static_cast<int>(v), image->height - 2));
    const int i1 = std::min(i + 1, image->width - 1), j1 = std::min(j + 1, image->height - 1);
    const double fu = u - i, fv = v - j;
    const double top = image->at(i, j) * (1 - fu) + image->at(i1, j) * fu;
    const double bottom = image->at(i, j1) * (1 - fu) + image->at(i1, j1) * fu;
    return top * (1 - fv) + bottom * fv;
  }
};

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
    // Darkness t in [0, 1] sets the density 1/r^2 linearly between white's
    // 1/rmax^2 and black's 1/rmin^2, so a stippling's tone follows the image.
    const ImageOnBounds image(o.density, lo, hi);
    const double light = 1.0 / (rmax * rmax), dark = 1.0 / (rmin * rmin);
    c.rmin = rmin;
    c.rmax = rmax;
    c.radius = [image, light, dark, invert = o.invert](const double* x) {
      const double grey = image.smooth(x);
      const double t = invert ? grey : 1.0 - grey;
      return 1.0 / std::sqrt(light + t * (dark - light));
    };
  }
  std::function<bool(const double*)> mask, region;
  if (!o.mask.empty()) {
    const ImageOnBounds image(o.mask, lo, hi);
    mask = [image](const double* x) { return image.nearest(x) < 0.5; };
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
