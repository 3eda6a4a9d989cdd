#pragma once
// The region points live in: an axis-aligned box [lo, hi) or the same box with
// periodic boundaries (a torus). Periodicity lives here, not in the samplers:
// every distance a sampler or an analysis takes goes through distance2().

#include <cmath>
#include <ostream>
#include <string>

#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/point.h"

namespace pds {

/// Throws InvalidArgument unless lo and hi are finite, hi > lo, and the
/// extent lies in [1e-150, 1e150], the range of radii (limits.h): squared
/// distances across the domain then stay normal doubles, and a width of a
/// few denormals (which no grid can divide) or one that overflows to
/// infinity is refused here rather than deep inside a sampler.
inline void validate_axis(int axis, double lo, double hi) {
  const auto format = [](double v) { return detail::format_number(v); };
  if (!std::isfinite(lo) || !std::isfinite(hi))
    throw InvalidArgument("bounds: axis " + std::to_string(axis) + " has a non-finite bound");
  if (!(hi > lo))
    throw InvalidArgument("bounds: axis " + std::to_string(axis) + " is empty (lo " + format(lo) + " >= hi " +
                          format(hi) + ")");
  const double extent = hi - lo;
  if (!(extent >= 1e-150 && extent <= 1e150))
    throw InvalidArgument("bounds: axis " + std::to_string(axis) + " has extent " + format(extent) +
                          ", outside [1e-150, 1e150] (scale the domain)");
}

template <int D>
struct Domain {
  Point<D> lo{};
  Point<D> hi = filled(1.0);
  bool periodic = false;

  /// The unit square/cube, as a box or as a torus.
  static Domain unit(bool periodic = false) { return Domain{filled(0.0), filled(1.0), periodic}; }
  static Domain box(const Point<D>& lo, const Point<D>& hi) { return Domain{lo, hi, false}; }
  static Domain torus(const Point<D>& lo, const Point<D>& hi) { return Domain{lo, hi, true}; }
  /// The domain of D run-time bounds (lo[0..D), hi[0..D)); not validated.
  static Domain from_bounds(const double* lo, const double* hi, bool periodic) {
    Domain d{{}, {}, periodic};
    for (int i = 0; i < D; ++i) {
      d.lo[i] = lo[i];
      d.hi[i] = hi[i];
    }
    return d;
  }

  double extent(int axis) const { return hi[axis] - lo[axis]; }

  double volume() const {
    double v = 1.0;
    for (int i = 0; i < D; ++i) v *= extent(i);
    return v;
  }

  /// lo <= x < hi in every coordinate.
  bool contains(const Point<D>& p) const {
    for (int i = 0; i < D; ++i)
      if (!(p[i] >= lo[i] && p[i] < hi[i])) return false;
    return true;
  }

  /// Coordinate difference b - a along one axis; on a torus the shortest one.
  double delta(double a, double b, int axis) const {
    double d = b - a;
    if (periodic) {
      const double L = extent(axis);
      if (d > 0.5 * L)
        d -= L;
      else if (d < -0.5 * L)
        d += L;
    }
    return d;
  }

  /// Squared distance; on a torus, to the nearest periodic image. Both points
  /// must lie in [lo, hi).
  double distance2(const Point<D>& a, const Point<D>& b) const {
    double s = 0.0;
    for (int i = 0; i < D; ++i) {
      const double d = delta(a[i], b[i], i);
      s += d * d;
    }
    return s;
  }

  /// Maps a point into [lo, hi): periodic images on a torus. On a box the
  /// point is returned unchanged (it may lie outside; see contains()).
  Point<D> wrap(Point<D> p) const {
    if (!periodic) return p;
    for (int i = 0; i < D; ++i) {
      const double L = extent(i);
      double x = p[i] - lo[i];
      if (x < 0.0 || x >= L) x -= L * std::floor(x / L);
      // Rounding can land exactly on L (e.g. x = -1e-300); that is lo again.
      if (!(x < L)) x = 0.0;
      p[i] = lo[i] + x;
    }
    return p;
  }

  /// validate_axis() for every axis.
  void validate() const {
    for (int i = 0; i < D; ++i) validate_axis(i, lo[i], hi[i]);
  }

  bool operator==(const Domain&) const = default;

 private:
  static Point<D> filled(double v) {
    Point<D> p;
    p.fill(v);
    return p;
  }
};

template <int D>
std::ostream& operator<<(std::ostream& os, const Domain<D>& d) {
  return os << (d.periodic ? "torus" : "box") << '[' << d.lo << ", " << d.hi << ')';
}

}  // namespace pds
