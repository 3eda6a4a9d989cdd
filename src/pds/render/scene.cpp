// Closed-form test scenes (see include/pds/render/scene.h).

#include "pds/render/scene.h"

#include <cmath>
#include <numbers>

#include "pds/error.h"

namespace pds {

namespace {
// Squares near the bottom of a square image then span about 40 pixels at 512.
constexpr double kCameraHeight = 6.0;
}  // namespace

CheckerboardScene::CheckerboardScene(int width, int height, double horizon)
    : cx_(0.5 * width), horizon_y_(horizon * height), focal_(0.5 * width) {}

double CheckerboardScene::value(double x, double y) const {
  // Camera at height kCameraHeight (in squares) looking along +z; the row at
  // v focal lengths below the horizon sees the ground at depth height / v.
  const double v = (y - horizon_y_) / focal_;
  if (!(v > 0)) return 0.5;
  const double depth = kCameraHeight / v;
  const double across = (x - cx_) / focal_ * depth;
  const auto cell = static_cast<long long>(std::floor(across)) + static_cast<long long>(std::floor(depth));
  return (cell & 1) ? 1.0 : 0.0;
}

ZonePlateScene::ZonePlateScene(int width, int height)
    : cx_(0.5 * width), cy_(0.5 * height), scale_(2.0 * std::numbers::pi / width) {}

double ZonePlateScene::value(double x, double y) const {
  const double dx = x - cx_, dy = y - cy_;
  return 0.5 + 0.5 * std::cos(scale_ * (dx * dx + dy * dy));
}

std::vector<std::string> scene_names() { return {"checkerboard", "zone-plate", "constant"}; }

std::unique_ptr<Scene> make_scene(const std::string& name, int width, int height) {
  if (name == "checkerboard") return std::make_unique<CheckerboardScene>(width, height);
  if (name == "zone-plate") return std::make_unique<ZonePlateScene>(width, height);
  if (name == "constant") return std::make_unique<ConstantScene>(0.5);
  std::string known;
  for (const auto& n : scene_names()) known += (known.empty() ? "" : ", ") + n;
  throw InvalidArgument("unknown scene '" + name + "' (known: " + known + ")");
}

}  // namespace pds
