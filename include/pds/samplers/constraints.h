#pragma once
// Sampling the world as it is: a radius that varies over the domain, a region
// samples must stay in, and points that already exist. Bridson's and dart
// throwing's loops take them (samplers/constrained.h); docs/density.md shows
// each with a picture.
//
// The pair rule (variable radius): two samples a and b conflict when
//
//     distance(a, b) < max(r(a), r(b)),
//
// so every generated sample's ball of its own radius r(x) holds no other
// sample's centre, and no generated sample lies inside another sample's
// ball. With a constant field it is the ordinary minimum distance. The
// larger of the two (rather than the mean or the smaller) is the rule that
// gives this per-sample statement; where the field varies slowly (r changes
// little over one r) the three rules give nearly the same sets. A maximal
// set under the rule has about K / r(x)^D samples per unit volume near x,
// the constant K of a uniform set of the same method.

#include <functional>

#include "pds/point.h"

namespace pds {

template <int D>
struct SamplingConstraints {
  /// r(x), the local minimum distance; empty: the uniform radius of the
  /// sampler's params. Values are clamped into [rmin, rmax]; NaN is an error.
  std::function<double(const Point<D>&)> radius;
  /// Bounds of the field over the domain (with a field: 0 < rmin <= rmax,
  /// both in [kMinRadius, kMaxRadius]); they size the background grids.
  double rmin = 0.0, rmax = 0.0;
  /// Where generated samples may lie; empty: the whole domain. Generated
  /// samples satisfy inside(x) and every guarantee holds among them; nothing
  /// is generated where it is false.
  std::function<bool(const Point<D>&)> inside;
  /// Points that already exist (a user extending a set, or anchors): they
  /// come first in the output, unchanged and in this order, and generated
  /// samples keep the pair rule against them (each at its own r(x)). They
  /// must lie in the domain; the rule is not enforced among them, nor the
  /// mask on them.
  PointSet<D> fixed;

  /// True when anything above departs from a plain uniform run.
  bool active() const { return static_cast<bool>(radius) || static_cast<bool>(inside) || !fixed.empty(); }
};

}  // namespace pds
