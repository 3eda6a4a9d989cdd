// Dart throwing (the Poisson disk loop of E. Agu's CS 563 notes; R. L. Cook, Stochastic
// sampling in computer graphics, ACM TOG 5(1), 1986; its statistics are those
// of random sequential adsorption, see A. Lagae and P. Dutre, A comparison of
// methods for generating Poisson disk distributions, CGF 27(1), 2008).
//
// Method: draw a uniform point of the domain; reject it if an accepted sample
// lies strictly closer than the radius (distance on the torus is to the
// nearest periodic image), accept it otherwise; repeat.
//
// Guarantees: minimum distance >= radius in the exact arithmetic of
// Domain::distance2; all samples in [lo, hi); each accepted sample is uniform
// over the still-free region, so any prefix is a uniform Poisson disk set.
//
// Termination: the textbook loop runs until N samples are placed, forever if
// they do not fit. Here it stops after a bound on consecutive rejections
// (default max(10^4, packing bound)); with a count, hitting it is an
// error that says how many were placed. When darts keep missing, the free area
// left is about 1/bound of the domain, so the result is near-maximal
// (relative radius ~0.75 in 2D, docs/dart-throwing.md) but not proven maximal.
//
// Complexity: the literal version checks every accepted sample, O(N) a dart;
// the grid version checks the few cells within the radius (background grid of
// edge radius/sqrt(D) in 2D and 3D, radius from 4D: Grid::for_conflicts), O(1)
// a dart. Both take the same decisions on the same
// random stream, so their outputs are identical; a test shows it.

#include "pds/samplers/dart_throwing.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/grid.h"
#include "pds/limits.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"
#include "pds/samplers/sizing.h"
#include "pds/detail/instantiate.h"

namespace pds {
namespace {

// The textbook check: every accepted sample, in order.
template <int D>
class AllPairsCheck {
 public:
  AllPairsCheck(const Domain<D>& domain, double radius) : domain_(domain), radius2_(radius * radius) {}
  bool is_free(const Point<D>& p) const {
    for (const auto& q : points_)
      if (domain_.distance2(p, q) < radius2_) return false;
    return true;
  }
  void add(const Point<D>& p) { points_.push_back(p); }
  void reserve(std::size_t n) { points_.reserve(n); }
  PointSet<D> take() { return std::move(points_); }

 private:
  Domain<D> domain_;
  double radius2_;
  PointSet<D> points_;
};

// The same predicate restricted to the grid cells within the radius.
template <int D>
class GridCheck {
 public:
  GridCheck(const Domain<D>& domain, double radius)
      : grid_(Grid<D>::for_conflicts(domain, radius)), radius_(radius) {}
  bool is_free(const Point<D>& p) const { return !grid_.any_closer_than(p, radius_); }
  void add(const Point<D>& p) { grid_.insert(p); }
  void reserve(std::size_t n) { grid_.reserve(n); }
  PointSet<D> take() { return std::move(grid_).take_points(); }

 private:
  Grid<D> grid_;
  double radius_;
};

template <int D, class Check>
PointSet<D> throw_darts(const DartThrowingParams& params, const Domain<D>& domain, std::uint64_t seed) {
  const std::uint64_t bound = params.max_failures ? params.max_failures : default_dart_failures(domain, params.radius);
  const std::uint64_t wanted = params.count.value_or(UINT64_MAX);
  Check check(domain, params.radius);
  if (params.count) check.reserve(static_cast<std::size_t>(wanted));
  Rng rng(seed);
  std::uint64_t placed = 0, failures = 0;
  // With a radius alone the run ends on a streak of misses: its share of
  // the bound takes over from the count (typical_count) as the set fills.
  const double expected = params.count ? static_cast<double>(wanted) : typical_count(sizing_volume(domain, params.radius), params.radius, D);
  ProgressReporter progress(params.progress, expected);
  while (placed < wanted) {
    progress.update(params.count ? static_cast<double>(placed)
                                 : expected * std::max(static_cast<double>(placed) / expected,
                                                       static_cast<double>(failures) / static_cast<double>(bound)));
    const Point<D> dart = uniform_point(rng, domain);
    if (check.is_free(dart)) {
      check.add(dart);
      ++placed;
      failures = 0;
    } else if (++failures >= bound) {
      if (!params.count) break;
      throw InvalidArgument("dart-throwing: placed only " + std::to_string(placed) + " of the " +
                            std::to_string(wanted) + " points requested at radius " +
                            detail::format_number(params.radius) + " before " + std::to_string(bound) +
                            " darts in a row were rejected: that many do not fit; ask for fewer points or a "
                            "smaller radius");
    }
  }
  progress.finish();
  return check.take();
}

}  // namespace

template <int D>
std::uint64_t default_dart_failures(const Domain<D>& domain, double radius) {
  const double per_packing = static_cast<double>(kDartFailuresPerPoint) * packing_count(sizing_volume(domain, radius), radius, D);
  return std::max<std::uint64_t>(kDartMinFailures, static_cast<std::uint64_t>(std::min(per_packing, 1e18)));
}

template <int D>
PointSet<D> dart_throwing(const DartThrowingParams& params, const Domain<D>& domain, std::uint64_t seed) {
  domain.validate();
  require_radius(params.radius);
  if (params.count) {
    if (*params.count == 0) throw InvalidArgument("dart-throwing: count must be at least 1, got 0");
    require_count_fits("dart-throwing", *params.count, params.radius, domain);
  }
  return params.all_pairs ? throw_darts<D, AllPairsCheck<D>>(params, domain, seed)
                          : throw_darts<D, GridCheck<D>>(params, domain, seed);
}

#define PDS_INSTANTIATE(D)                                                                      \
  template PointSet<D> dart_throwing<D>(const DartThrowingParams&, const Domain<D>&, std::uint64_t); \
  template std::uint64_t default_dart_failures<D>(const Domain<D>&, double);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
