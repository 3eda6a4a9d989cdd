#pragma once
// Grey images laid over the plane as the fields of the constrained samplers
// (samplers/constraints.h, docs/density.md): a radius field for
// `pds generate --density` and a mask for `--mask`.
//
// The image covers the bounds [lo, hi) of the plane, its top row at the upper
// y bound (y up, as the point plots draw it), each pixel an equal rectangle.

#include <functional>
#include <memory>

#include "pds/point.h"
#include "pds/render/render.h"

namespace pds {

class ImageOnBounds {
 public:
  /// Throws InvalidArgument for an empty image or bounds that are not finite
  /// with hi > lo.
  ImageOnBounds(Image image, const Point<2>& lo, const Point<2>& hi);

  /// The grey level of the pixel under x (clamped to the image).
  double nearest(const Point<2>& x) const;
  /// Bilinear between pixel centres, constant beyond the outer ones.
  double smooth(const Point<2>& x) const;

 private:
  std::shared_ptr<const Image> image_;  // shared: copies go into callbacks
  double x0_, y1_, sx_, sy_;            // pixels per unit along x and (downward) y
};

/// r(x) from the image: the darkness t = 1 - grey (t = grey with `invert`)
/// sets the density 1/r^2 linearly between 1/rmax^2 (t = 0) and 1/rmin^2
/// (t = 1), so dark is dense and a stippling's tone follows the image.
/// Bilinear between pixels. Requires 0 < rmin <= rmax (not checked here; the
/// samplers check them).
std::function<double(const Point<2>&)> radius_from_image(const ImageOnBounds& image, double rmin, double rmax,
                                                         bool invert);

/// On where the pixel under x is dark (grey < 0.5), nearest pixel.
std::function<bool(const Point<2>&)> mask_from_image(const ImageOnBounds& image);

}  // namespace pds
