#pragma once
// Test scenes for the anti-aliasing renderer: images defined by a closed form
// at every point of the image plane, so a sample costs one evaluation and a
// reference image carries no error beyond its own sample count.
//
// Coordinates are in pixels: pixel (i, j) is the square [i, i+1) x [j, j+1),
// y pointing down. Values are grey levels in [0, 1].

#include <memory>
#include <string>
#include <vector>

namespace pds {

class Scene {
 public:
  virtual ~Scene() = default;
  /// The scene's grey level at image-plane point (x, y), in [0, 1].
  virtual double value(double x, double y) const = 0;
};

/// An infinite checkerboard of unit squares (values 0 and 1) on the ground
/// plane, seen by a pinhole camera six squares above it (focal length half
/// the image width), looking along the plane;
/// the horizon lies `horizon` of the way down the image and the sky is 0.5.
/// Towards the horizon the squares shrink without bound: every sampler aliases
/// there, which is the example of Agu's CS 563 notes.
class CheckerboardScene : public Scene {
 public:
  CheckerboardScene(int width, int height, double horizon = 0.25);
  double value(double x, double y) const override;

 private:
  double cx_, horizon_y_, focal_;
};

/// A zone plate: 0.5 + 0.5 cos(2 pi r^2 / width), r the distance from the
/// image centre in pixels. Its local frequency 2 r / width cycles per pixel
/// grows linearly from 0 at the centre to 1 at the middle of each edge: beyond
/// r = width / 4 it passes the Nyquist rate of one sample a pixel, and rings
/// alias there (the standard aliasing test pattern).
class ZonePlateScene : public Scene {
 public:
  ZonePlateScene(int width, int height);
  double value(double x, double y) const override;

 private:
  double cx_, cy_, scale_;
};

/// The same value everywhere (a check that the renderer adds no error).
class ConstantScene : public Scene {
 public:
  explicit ConstantScene(double value) : value_(value) {}
  double value(double, double) const override { return value_; }

 private:
  double value_;
};

/// Names for make_scene: "checkerboard", "zone-plate", "constant".
std::vector<std::string> scene_names();

/// The scene called `name` for an image of width x height pixels; throws
/// InvalidArgument naming the known scenes.
std::unique_ptr<Scene> make_scene(const std::string& name, int width, int height);

}  // namespace pds
