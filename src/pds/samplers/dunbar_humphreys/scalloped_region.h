#pragma once
// Scalloped regions, the data structure of Dunbar & Humphreys 2006 ("A
// spatial data structure for fast Poisson-disk sample generation"): the part
// of the annulus r..2r around a sample where a new sample may still go, kept in
// polar coordinates around the sample as scalloped sectors with exact areas,
// and sampled uniformly by inverting their cumulative area. Used by variants
// 1 and 2 of the Dunbar-Humphreys sampler; private to the library (tested in
// scalloped_region_test.cpp).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "pds/rng.h"

namespace pds::detail::dh {

/// A boundary curve of a scalloped sector, in polar coordinates around the
/// front sample p: the ray at angle theta meets it at radius(theta). Either a
/// circle (centre c relative to p, radius rho; branch -1 is the near crossing
/// of the ray, +1 the far one; a circle centred at p has d = 0) or a wall, the
/// line {x : x . (cos psi, sin psi) = h}.
struct Curve {
  bool line = false;
  double cx = 0.0, cy = 0.0, rho = 0.0, branch = 1.0, d = 0.0, phi = 0.0;  // circle
  double h = 0.0, psi = 0.0;                                               // line

  static Curve circle(double cx, double cy, double rho, double branch);
  static Curve wall(double h, double psi);

  /// Where the ray at angle theta meets the curve (theta where it does).
  double radius(double theta) const {
    if (line) return h / std::cos(theta - psi);
    if (d == 0.0) return rho;
    const double u = theta - phi, s = d * std::sin(u);
    return d * std::cos(u) + branch * std::sqrt(std::max(0.0, rho * rho - s * s));
  }
  /// An antiderivative of radius(theta)^2 / 2 (the area swept by the ray),
  /// continuous over any angular range where the curve is defined and that
  /// stays within pi of the circle's direction phi (the wall's normal psi).
  /// Closed form: for a circle of radius a at distance d, with u = theta -
  /// phi and w = d sin u, (a^2 u + d^2 sin(2u) / 2 + branch (w sqrt(a^2 -
  /// w^2) + a^2 asin(w / a))) / 2; for a wall, h^2 tan(theta - psi) / 2.
  double primitive(double theta) const {
    if (line) return 0.5 * h * h * std::tan(wrap_angle(theta - psi));
    if (d == 0.0) return 0.5 * rho * rho * theta;
    // r^2 = rho^2 + d^2 cos 2u + 2 branch d cos u sqrt(rho^2 - d^2 sin^2 u);
    // with w = d sin u the last term integrates to w sqrt(rho^2 - w^2) + rho^2 asin(w / rho).
    const double u = wrap_angle(theta - phi), w = d * std::sin(u);
    const double root = std::sqrt(std::max(0.0, rho * rho - w * w));
    const double arc = std::asin(std::clamp(w / rho, -1.0, 1.0));
    return 0.5 * (rho * rho * u + 0.5 * d * d * std::sin(2.0 * u) + branch * (w * root + rho * rho * arc));
  }
  /// u wrapped into (-pi, pi]: neighbour circles and walls span less than pi
  /// around their direction, so the primitive is continuous inside a sector.
  static double wrap_angle(double u) {
    if (u > std::numbers::pi) return u - 2.0 * std::numbers::pi;
    if (u <= -std::numbers::pi) return u + 2.0 * std::numbers::pi;
    return u;
  }
};

/// Appends the angles in [0, 2 pi) of the points where the geometric
/// circles/lines of two curves meet (both branches of a circle; extra angles
/// are harmless to the caller, which only splits sectors there).
void crossings(const Curve& a, const Curve& b, std::vector<double>& out);

/// The available region of one front sample: the annulus r..2r around it
/// minus the disks of radius r around its neighbours and minus the half-planes
/// beyond walls, as scalloped sectors {theta in [t0, t1], inner(theta) <= rho
/// <= outer(theta)} with their exact areas. Pieces narrower than 1e-12 rad
/// are dropped (slivers under 1e-11 r wide).
class ScallopedRegion {
 public:
  /// The full annulus r..2r.
  void reset(double r);
  bool empty() const { return sectors_.empty(); }
  /// The exact area (the sum of the sectors' closed-form areas).
  double area() const;
  std::size_t sectors() const { return sectors_.size(); }

  /// Removes the disk of radius r centred at (cx, cy) relative to the sample
  /// (at distance >= r from it; no effect beyond 3r).
  void remove_disk(double cx, double cy, double r);
  /// Removes the half-plane beyond the wall x . (cos psi, sin psi) = h, h > 0.
  void remove_beyond_wall(double h, double psi);

  /// A point (angle, radius) uniformly distributed over the region:
  /// position(U1, U2) for two uniforms drawn in that order; requires !empty().
  std::pair<double, double> sample(Rng& rng) const;
  /// The inverse of the region's cumulative distribution: u in [0, 1) is a
  /// fraction of the area, taken from the sectors in their order and within
  /// the chosen sector by angle (Newton steps on the swept area, kept inside a
  /// bisection bracket); v in [0, 1) places the radius between the inner and
  /// outer curves uniformly in area, sqrt(a^2 + v (b^2 - a^2)). Requires !empty().
  std::pair<double, double> position(double u, double v) const;
  /// The forward map: for a point (theta, radius) of the region, the (u, v)
  /// that position() takes to it; nullopt when no sector holds the point.
  std::optional<std::pair<double, double>> cdf(double theta, double radius) const;

 private:
  struct Sector {
    double t0, t1;
    int inner, outer;
    double area = 0.0;
  };

  void add(Sector s, std::vector<Sector>& to) const;
  double area(const Sector& s) const;
  void cut(int near, int far, double centre, double half);

  std::vector<Curve> curves_;  // 0: circle r, 1: circle 2r, then walls and neighbours
  std::vector<Sector> sectors_, next_;
  std::vector<double> breaks_;
};

}  // namespace pds::detail::dh
