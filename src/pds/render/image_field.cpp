// Grey images as radius fields and masks (include/pds/render/image_field.h).

#include "pds/render/image_field.h"

#include <algorithm>
#include <cmath>

#include "pds/detail/format.h"
#include "pds/error.h"

namespace pds {

ImageOnBounds::ImageOnBounds(Image image, const Point<2>& lo, const Point<2>& hi)
    : image_(std::make_shared<const Image>(std::move(image))) {
  if (image_->width < 1 || image_->height < 1) throw InvalidArgument("image: empty");
  for (int a = 0; a < 2; ++a)
    if (!std::isfinite(lo[a]) || !std::isfinite(hi[a]) || !(hi[a] > lo[a]))
      throw InvalidArgument("image: bounds on axis " + std::to_string(a) + " must be finite with hi > lo, got " +
                            detail::format_number(lo[a]) + ", " + detail::format_number(hi[a]));
  x0_ = lo[0];
  y1_ = hi[1];
  sx_ = image_->width / (hi[0] - lo[0]);
  sy_ = image_->height / (hi[1] - lo[1]);
}

double ImageOnBounds::nearest(const Point<2>& x) const {
  const int px = std::clamp(static_cast<int>(std::floor((x[0] - x0_) * sx_)), 0, image_->width - 1);
  const int py = std::clamp(static_cast<int>(std::floor((y1_ - x[1]) * sy_)), 0, image_->height - 1);
  return image_->at(px, py);
}

double ImageOnBounds::smooth(const Point<2>& x) const {
  const int w = image_->width, h = image_->height;
  const double u = std::clamp((x[0] - x0_) * sx_ - 0.5, 0.0, w - 1.0);
  const double v = std::clamp((y1_ - x[1]) * sy_ - 0.5, 0.0, h - 1.0);
  const int i = std::max(0, std::min(static_cast<int>(u), w - 2)),
            j = std::max(0, std::min(static_cast<int>(v), h - 2));
  const int i1 = std::min(i + 1, w - 1), j1 = std::min(j + 1, h - 1);
  const double fu = u - i, fv = v - j;
  const double top = image_->at(i, j) * (1 - fu) + image_->at(i1, j) * fu;
  const double bottom = image_->at(i, j1) * (1 - fu) + image_->at(i1, j1) * fu;
  return top * (1 - fv) + bottom * fv;
}

std::function<double(const Point<2>&)> radius_from_image(const ImageOnBounds& image, double rmin, double rmax,
                                                         bool invert) {
  const double light = 1.0 / (rmax * rmax), dark = 1.0 / (rmin * rmin);
  return [image, light, dark, invert](const Point<2>& x) {
    const double grey = image.smooth(x);
    const double t = invert ? grey : 1.0 - grey;
    return 1.0 / std::sqrt(light + t * (dark - light));
  };
}

std::function<bool(const Point<2>&)> mask_from_image(const ImageOnBounds& image) {
  return [image](const Point<2>& x) { return image.nearest(x) < 0.5; };
}

}  // namespace pds
