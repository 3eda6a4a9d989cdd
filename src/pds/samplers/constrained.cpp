// Bridson's and dart throwing's loops under a radius field, a mask and fixed
// points (R. Bridson, Fast Poisson disk sampling in arbitrary dimensions,
// SIGGRAPH 2007 sketches, with the annulus taken at the active sample's own
// radius; dart throwing: R. L. Cook, Stochastic sampling in computer
// graphics, ACM TOG 5(1), 1986), with the radius a field r(x).
//
// Method: one accepted-set object (ConstrainedSet below) decides whether a
// point may join: inside the mask, then no conflict under the pair rule of
// samplers/constraints.h, found by the radius-level index of
// radius_levels.h. Bridson's loop proposes candidates around active samples;
// dart throwing proposes uniform darts. Both run on one random stream from
// the seed.
//
// Guarantees: see samplers/constrained.h. The pair rule is decided as
// d2 < max(r_a, r_b)^2 with d2 from Domain::distance2, the arithmetic the
// tests' all-pairs oracle uses.
//
// Complexity: a query reads about 3^D cells of its own radius level, and as
// many of each other level flagged in its cell (levels a factor sqrt(2)
// apart: 2 log2(rmax/rmin) + 1 of them; in a smooth field a query searches
// one level); an insert flags the cells of the other levels around it.
// Memory: the level grids with a 32-bit mask a cell, the finest with cells
// of edge sqrt(2) rmin. Measured: docs/benchmarks.md, "Variable density".
//
// Limits: not maximal (Bridson's k candidates and dart throwing's failure
// bound both stop short); the candidate shell is drawn by rejection from a
// cube, which wastes most draws from about 6 dimensions on (it still ends:
// each draw is accepted with a fixed positive probability).

#include "pds/samplers/constrained.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include "pds/detail/format.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"
#include "pds/limits.h"
#include "pds/progress.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"
#include "radius_levels.h"

namespace pds {
namespace {

template <int D>
std::string format_point(const Point<D>& p) {
  std::string s = "(";
  for (int i = 0; i < D; ++i) s += (i ? ", " : "") + detail::format_number(p[i]);
  return s + ")";
}

// The samples so far (fixed ones first) and the test a new one must pass.
template <int D>
class ConstrainedSet {
 public:
  ConstrainedSet(const char* method, double uniform_radius, const SamplingConstraints<D>& c, const Domain<D>& domain)
      : domain_(domain),
        constraints_(c),
        rmin_(c.radius ? c.rmin : uniform_radius),
        rmax_(c.radius ? c.rmax : uniform_radius),
        // validate() runs before the index sizes its grids by rmin and rmax.
        index_((validate(method, uniform_radius), domain), rmin_, rmax_) {
    for (std::size_t i = 0; i < c.fixed.size(); ++i) {
      const Point<D>& p = c.fixed[i];
      if (!domain.contains(p))
        throw InvalidArgument(std::string(method) + ": fixed point " + std::to_string(i + 1) + " " + format_point(p) +
                              " lies outside the domain");
      add(p, radius_at(p));
    }
  }

  double rmin() const { return rmin_; }

  /// r(x), clamped into [rmin, rmax].
  double radius_at(const Point<D>& x) const {
    if (!constraints_.radius) return rmin_;
    const double r = constraints_.radius(x);
    if (std::isnan(r)) throw InvalidArgument("radius field: NaN at " + format_point(x));
    return std::clamp(r, rmin_, rmax_);
  }

  /// Adds x (in the domain) if the mask allows it and it conflicts with no
  /// sample; returns whether it did.
  bool try_add(const Point<D>& x) {
    if (constraints_.inside && !constraints_.inside(x)) return false;
    const double r = radius_at(x);
    if (index_.conflicts(x, r)) return false;
    add(x, r);
    return true;
  }

  std::size_t size() const { return points_.size(); }
  const Point<D>& point(std::size_t i) const { return points_[i]; }
  double radius(std::size_t i) const { return radii_[i]; }
  std::size_t generated() const { return points_.size() - constraints_.fixed.size(); }
  PointSet<D> take() { return std::move(points_); }

 private:
  void validate(const char* method, double uniform_radius) const {
    domain_.validate();
    if (!constraints_.radius) {
      require_radius(uniform_radius);
      return;
    }
    require_radius(constraints_.rmin, "rmin");
    require_radius(constraints_.rmax, "rmax");
    if (!(constraints_.rmin <= constraints_.rmax))
      throw InvalidArgument(std::string(method) + ": radius range needs rmin <= rmax, got " +
                            detail::format_number(constraints_.rmin) + " > " +
                            detail::format_number(constraints_.rmax));
  }

  void add(const Point<D>& x, double r) {
    index_.insert(x, r);
    points_.push_back(x);
    radii_.push_back(r);
  }

  const Domain<D>& domain_;
  const SamplingConstraints<D>& constraints_;
  double rmin_, rmax_;
  detail::RadiusLevels<D> index_;
  PointSet<D> points_;
  std::vector<double> radii_;
};

template <int D>
double norm2(const Point<D>& v) {
  double s = 0.0;
  for (int i = 0; i < D; ++i) s += v[i] * v[i];
  return s;
}

// A point uniform by volume in the shell [r, 2r] around the origin.
template <int D>
Point<D> shell_offset(Rng& rng, double r) {
  for (;;) {
    Point<D> v;
    for (int i = 0; i < D; ++i) v[i] = rng.uniform(-2.0 * r, 2.0 * r);
    const double n2 = norm2(v);
    if (n2 >= r * r && n2 <= 4.0 * r * r) return v;
  }
}

void refuse_count(const char* method, const std::optional<std::uint64_t>& count) {
  if (count)
    throw InvalidArgument(
        std::string(method) +
        ": a count is not taken with a radius field, a mask or fixed points; the radius sizes the set");
}

}  // namespace

template <int D>
PointSet<D> bridson(const BridsonParams& params, const SamplingConstraints<D>& constraints, const Domain<D>& domain,
                    std::uint64_t seed) {
  if (params.k < 1) throw InvalidArgument("bridson: k must be at least 1, got " + std::to_string(params.k));
  refuse_count("bridson", params.count);
  ConstrainedSet<D> set("bridson", params.radius, constraints, domain);
  Rng rng(seed);
  std::vector<std::size_t> active(set.size());
  for (std::size_t i = 0; i < active.size(); ++i) active[i] = i;
  for (;;) {
    while (!active.empty()) {
      const std::size_t slot = static_cast<std::size_t>(rng.uniform() * static_cast<double>(active.size()));
      const std::size_t from = active[slot];
      const Point<D> centre = set.point(from);
      const double r = set.radius(from);
      bool placed = false;
      for (int t = 0; t < params.k && !placed; ++t) {
        const Point<D> v = shell_offset<D>(rng, r);
        Point<D> c;
        for (int i = 0; i < D; ++i) c[i] = centre[i] + v[i];
        c = domain.wrap(c);
        if (!domain.contains(c)) continue;
        placed = set.try_add(c);
      }
      if (placed) {
        active.push_back(set.size() - 1);
      } else {
        active[slot] = active.back();
        active.pop_back();
      }
    }
    // The front is spent: look for space it never reached.
    std::uint64_t misses = 0;
    while (misses < kConstrainedRestartDarts && !set.try_add(uniform_point(rng, domain))) ++misses;
    if (misses == kConstrainedRestartDarts) break;
    active.push_back(set.size() - 1);
  }
  return set.take();
}

template <int D>
PointSet<D> dart_throwing(const DartThrowingParams& params, const SamplingConstraints<D>& constraints,
                          const Domain<D>& domain, std::uint64_t seed) {
  if (params.count && *params.count == 0) throw InvalidArgument("dart-throwing: count must be at least 1, got 0");
  ConstrainedSet<D> set("dart-throwing", params.radius, constraints, domain);
  const std::uint64_t bound = params.max_failures ? params.max_failures : default_dart_failures(domain, set.rmin());
  const std::uint64_t wanted = params.count.value_or(std::numeric_limits<std::uint64_t>::max());
  Rng rng(seed);
  std::uint64_t failures = 0;
  // As the uniform loop reports: the count, or the count at rmin (an upper
  // bound) until the streak of misses takes over as the set fills.
  const double expected =
      params.count ? static_cast<double>(wanted) : typical_count(sizing_volume(domain, set.rmin()), set.rmin(), D);
  ProgressReporter progress(params.progress, expected);
  while (set.generated() < wanted) {
    const auto placed = static_cast<double>(set.generated());
    progress.update(params.count ? placed
                                 : expected * std::max(placed / expected,
                                                       static_cast<double>(failures) / static_cast<double>(bound)));
    if (set.try_add(uniform_point(rng, domain))) {
      failures = 0;
    } else if (++failures >= bound) {
      if (!params.count) break;
      throw InvalidArgument("dart-throwing: placed only " + std::to_string(set.generated()) + " of the " +
                            std::to_string(wanted) + " points requested before " + std::to_string(bound) +
                            " darts in a row were rejected: that many do not fit the field and the mask");
    }
  }
  progress.finish();
  return set.take();
}

#define PDS_INSTANTIATE(D)                                                                                          \
  template PointSet<D> bridson<D>(const BridsonParams&, const SamplingConstraints<D>&, const Domain<D>&,            \
                                  std::uint64_t);                                                                   \
  template PointSet<D> dart_throwing<D>(const DartThrowingParams&, const SamplingConstraints<D>&, const Domain<D>&, \
                                        std::uint64_t);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
