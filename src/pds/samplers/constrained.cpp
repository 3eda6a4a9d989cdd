// Bridson's and dart throwing's loops under a radius field, a mask and fixed
// points (R. Bridson, Fast Poisson disk sampling in arbitrary dimensions,
// SIGGRAPH 2007 sketches, with the annulus taken at the active sample's own
// radius; dart throwing: R. L. Cook, Stochastic sampling in computer
// graphics, ACM TOG 5(1), 1986), with the radius a field r(x).
//
// Method: one accepted-set object (ConstrainedSet below) decides whether a
// point may join: not in the index's cover (a cell wholly inside some
// sample's own ball: a conflict whatever the point's radius), inside the
// mask, then no conflict under the pair rule of samplers/constraints.h,
// found by the radius-level index (flat_levels.h in 1 to 3 dimensions,
// radius_levels.h from 4). Bridson's loop proposes candidates around active
// samples; dart throwing proposes uniform darts. The mask and the field are
// read only where the cover does not decide (the pair rule does not need
// r(x) there).
//
// Random numbers: Bridson's shell offsets are the uniform loop's
// (annulus_offsets.h: per-axis streams split from the seed, drawn ahead in
// branch-free batches) at radius 1, scaled by the picked sample's radius;
// the picks and the darts come from the seed's own stream. Speed: where the
// cover outgrows the caches near the core, a picked sample's rows of the
// cover are fetched early and darts are drawn ahead from a copy of the
// stream with their words of the cover fetched early; restart darts are
// aimed at the cells the cover leaves open once it holds most of the domain
// (ConstrainedSet::restart: the law of uniform darts, fewer numbers).
//
// Guarantees: see samplers/constrained.h. The pair rule is decided as
// d2 < max(r_a, r_b)^2 with d2 from Domain::distance2, the arithmetic the
// tests' all-pairs oracle uses.
//
// Complexity: a candidate or dart the cover decides costs one bit; the others
// read a fixed list of cells of their own radius level (24 in 2D) and the
// levels flagged near them (levels a factor sqrt(2) apart: about
// 2 log2(rmax/rmin) + 1 of them; in a smooth field mostly none); an insert
// sets the cover's bits within its radius and flags the other levels around
// it. Memory and measured speed: flat_levels.h and docs/benchmarks.md,
// "Variable density".
//
// Limits: not maximal (Bridson's k candidates and dart throwing's failure
// bound both stop short); the candidate shell is drawn by rejection from a
// cube, which wastes most draws from about 6 dimensions on (it still ends:
// each draw is accepted with a fixed positive probability).

#include "pds/samplers/constrained.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>

#include "annulus_offsets.h"
#include "flat_levels.h"
#include "pds/detail/format.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"
#include "pds/limits.h"
#include "pds/portable_math.h"
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

// RadiusLevels behind FlatLevels's interface (4 dimensions and more).
template <int D>
class LinkedLevels {
 public:
  struct Query {
    Point<D> x;
    double r;
    int level;
  };
  LinkedLevels(const Domain<D>& domain, double rmin, double rmax) : index_(domain, rmin, rmax) {}
  Query query(const Point<D>& x, double r, int) const { return {x, r, 0}; }
  struct Spot {};
  Spot spot(const Point<D>&) const { return {}; }
  bool covered(const Spot&) const { return false; }
  std::size_t cover_bytes() const { return 0; }
  void prefetch(const Spot&) const {}
  void prefetch_cover(const Point<D>&, double) const {}
  bool insert_if_free(const Query& q) { return index_.insert_if_free(q.x, q.r); }
  void insert(const Point<D>& x, double r) { index_.insert(x, r); }

 private:
  detail::RadiusLevels<D> index_;
};

// The samples so far (fixed ones first) and the test a new one must pass.
template <int D>
class ConstrainedSet {
  // The flat grids in 1 to 3 dimensions; from 4 the linked grids of edge
  // about r, whose 3^D blocks stay small (as bridson.cpp's ConflictGrid).
  using Index = std::conditional_t<(D <= 3), detail::FlatLevels<D>, LinkedLevels<D>>;

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

  /// The usual count (pds::typical_count) of the room the mask and the field
  /// leave: the volume weighted by (rmin / r(x))^D, estimated from 4,096
  /// points of a stream of its own (the output's stream is not touched). For
  /// progress only: it reads the field where the sampler may not.
  double typical_generated(std::size_t pilot = 4096) const {
    Rng rng(0x70726f6772657373ULL, {static_cast<std::uint64_t>(D)});
    double sum = 0.0;
    for (std::size_t i = 0; i < pilot; ++i) {
      const Point<D> x = uniform_point(rng, domain_);
      if (constraints_.inside && !constraints_.inside(x)) continue;
      sum += std::pow(rmin_ / radius_at(x), D);
    }
    const double volume = sizing_volume(domain_, rmin_) * sum / static_cast<double>(pilot);
    return std::max(1.0, typical_count(volume, rmin_, D));
  }

  /// r(x), clamped into [rmin, rmax].
  double radius_at(const Point<D>& x) const {
    if (!constraints_.radius) return rmin_;
    const double r = constraints_.radius(x);
    if (std::isnan(r)) throw InvalidArgument("radius field: NaN at " + format_point(x));
    return std::clamp(r, rmin_, rmax_);
  }

  /// Adds x (in the domain) if the mask allows it and it conflicts with no
  /// sample; returns whether it did.
  /// First the index's cover: where a sample's own ball holds x's whole
  /// cell, x conflicts whatever r(x) is, and neither the mask nor the field
  /// is read (most candidates and darts end there).
  [[gnu::always_inline]] bool try_add(const Point<D>& x) { return try_add(x, index_.spot(x)); }

  [[gnu::always_inline]] bool try_add(const Point<D>& x, const typename Index::Spot& spot) {
    return !index_.covered(spot) && try_add_uncovered(x);
  }

  bool try_add_uncovered(const Point<D>& x) {
    if (constraints_.inside && !constraints_.inside(x)) return false;
    const double r = radius_at(x);
    const auto q = index_.query(x, r, hint_);
    hint_ = q.level;
    if (!index_.insert_if_free(q)) return false;
    points_.push_back(x);
    radii_.push_back(r);
    return true;
  }

  /// Darts uniform over the domain from rng, tested in turn by
  /// try_add_dart() as try_add(uniform_point(rng, domain)) would. Where the
  /// cover is larger than 4 MB (beyond the caches near the core) they are
  /// drawn kDartsAhead ahead from a copy of the stream, their words of the
  /// cover fetched early (a dart lands anywhere, so it would otherwise wait
  /// for its own cache miss); rng makes a dart's D draws as it is tested, so
  /// it stays where drawing them one by one leaves it. Call start_darts()
  /// again after drawing anything else from it.
  void start_darts(const Rng& rng) {
    if (!darts_ahead_) return;
    ahead_ = rng;
    for (Dart& dart : darts_) draw_ahead(dart);
    next_dart_ = 0;
  }

  bool try_add_dart(Rng& rng) { return throw_dart(rng) == Landing::added; }

  /// Darts uniform over the domain from rng until one adds a sample (true)
  /// or `bound` miss in a row (false): in law what calling try_add_dart()
  /// until then does. Once the cover holds most of the domain (at most one
  /// dart in kAimShare of a window of kAimWindow landed outside it), darts
  /// are aimed: the cells not covered then are listed, and the darts that
  /// would land in covered cells (certain misses) are only counted, their
  /// number between two aimed darts drawn from its geometric law (a dart
  /// lands in a listed cell with probability listed / all cells); an aimed
  /// dart is uniform in a listed cell chosen uniformly, a miss when the
  /// cell has since been covered (it then leaves the list). Cells outside
  /// the list stay covered (bits are only set), so the law is the plain
  /// darts'; the numbers drawn are not. A restart after Bridson's front
  /// dies throws hundreds of thousands of darts, mostly into covered cells.
  bool restart(Rng& rng, std::uint64_t bound) {
    std::uint64_t misses = 0;
    if (!aimed_) {
      start_darts(rng);
      std::uint64_t window = 0, open = 0;
      for (;;) {
        if (misses == bound) return false;
        const Landing landing = throw_dart(rng);
        if (landing == Landing::added) return true;
        ++misses;
        open += landing != Landing::covered;
        if (++window < kAimWindow) continue;
        if (kAimable && open * kAimShare <= kAimWindow) break;
        window = open = 0;
      }
      aim();
    }
    if constexpr (kAimable) {
      const auto cells = static_cast<double>(index_.cover_cells());
      while (misses < bound) {
        if (uncovered_.empty()) return false;  // every dart would land in a covered cell
        const double p = static_cast<double>(uncovered_.size()) / cells;
        if (p < 1.0) {
          // Geometric, by inversion with the portable logarithm (the same bits everywhere).
          const double skipped = std::floor(neg_log(1.0 - rng.uniform()) / neg_log(1.0 - p));
          if (!(skipped < static_cast<double>(bound - misses))) return false;
          misses += static_cast<std::uint64_t>(skipped);
        }
        const std::size_t j = rng.below(uncovered_.size());
        const std::uint32_t cell = uncovered_[j];
        if (index_.covered(index_.cover_spot(cell))) {
          uncovered_[j] = uncovered_.back();
          uncovered_.pop_back();
        } else if (try_add_uncovered(index_.uniform_in_cover_cell(cell, rng))) {
          return true;
        }
        ++misses;
      }
    }
    return false;
  }

  /// Asks for the cover around a picked sample (2D covers beyond the caches).
  void prefetch_around(const Point<D>& x, double reach) const {
    if (darts_ahead_) index_.prefetch_cover(x, reach);
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

  enum class Landing { added, covered, refused };

  // try_add_dart(), saying whether the dart fell in the cover.
  Landing throw_dart(Rng& rng) {
    Point<D> x;
    typename Index::Spot spot;
    if (!darts_ahead_) {
      x = uniform_point(rng, domain_);
      spot = index_.spot(x);
    } else {
      Dart& dart = darts_[next_dart_];
      next_dart_ = (next_dart_ + 1) % kDartsAhead;
      for (int i = 0; i < D; ++i) rng.next();  // the draws of the dart's D coordinates
      x = dart.x;
      spot = dart.spot;
      draw_ahead(dart);
    }
    if (index_.covered(spot)) return Landing::covered;
    return try_add_uncovered(x) ? Landing::added : Landing::refused;
  }

  // Lists the cells the cover leaves open, once: restart() aims at them from then on.
  void aim() {
    aimed_ = true;
    if constexpr (kAimable) index_.for_each_uncovered([&](std::uint32_t cell) { uncovered_.push_back(cell); });
  }

  // Aimed darts need the cover (flat levels, 1 to 3 dimensions).
  static constexpr bool kAimable = D <= 3;
  static constexpr std::uint64_t kAimWindow = 1024, kAimShare = 16;
  bool aimed_ = false;
  std::vector<std::uint32_t> uncovered_;

  static constexpr std::size_t kDartsAhead = 16;
  struct Dart {
    Point<D> x;
    typename Index::Spot spot;
  };

  void draw_ahead(Dart& dart) {
    dart.x = uniform_point(ahead_, domain_);
    dart.spot = index_.spot(dart.x);
    index_.prefetch(dart.spot);
  }

  const Domain<D>& domain_;
  const SamplingConstraints<D>& constraints_;
  double rmin_, rmax_;
  Index index_;
  int hint_ = 0;  // the level of the last query: a neighbour's is most often the same
  PointSet<D> points_;
  std::vector<double> radii_;
  Rng ahead_{0};
  std::array<Dart, kDartsAhead> darts_{};
  std::size_t next_dart_ = 0;
  // Drawn ahead only where the cover outgrows the caches near the core
  // (measured: at 1 MB, drawing each dart twice cost more than it saved).
  bool darts_ahead_ = index_.cover_bytes() > (std::size_t{4} << 20);
};

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
  // The active samples with their radii (not indices: one memory access less
  // a pick).
  struct Active {
    Point<D> p;
    double r;
  };
  std::vector<Active> active(set.size());
  for (std::size_t i = 0; i < active.size(); ++i) active[i] = {set.point(i), set.radius(i)};
  // The uniform loop's offsets at radius 1, scaled by the picked sample's
  // radius: uniform by volume in its shell [r, 2r] (up to the rounding of
  // the product, which the exact test of the candidate makes harmless).
  detail::AnnulusOffsets<D, 53> offsets(1.0, false, seed);
  // Progress: samples placed against the usual count of the room left
  // (estimated only when someone listens), every kReportEvery samples.
  constexpr std::size_t kReportEvery = 256;
  ProgressReporter progress(params.progress, params.progress ? set.typical_generated() : 1.0);
  for (;;) {
    while (!active.empty()) {
      const std::size_t slot = rng.below(active.size());
      const Point<D> centre = active[slot].p;
      const double r = active[slot].r;
      set.prefetch_around(centre, 2.0 * r);
      bool placed = false;
      for (int t = 0; t < params.k && !placed; ++t) {
        const Point<D>& v = offsets.next();
        Point<D> c;
        for (int i = 0; i < D; ++i) c[i] = centre[i] + r * v[i];
        c = domain.wrap(c);
        if (!domain.contains(c)) continue;
        placed = set.try_add(c);
      }
      if (placed) {
        active.push_back({set.point(set.size() - 1), set.radius(set.size() - 1)});
        if (set.generated() % kReportEvery == 0) progress.update(static_cast<double>(set.generated()));
      } else {
        active[slot] = active.back();
        active.pop_back();
      }
    }
    // The front is spent: look for space it never reached.
    if (!set.restart(rng, kConstrainedRestartDarts)) break;
    active.push_back({set.point(set.size() - 1), set.radius(set.size() - 1)});
    progress.update(static_cast<double>(set.generated()));
  }
  progress.finish();
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
  set.start_darts(rng);
  while (set.generated() < wanted) {
    const auto placed = static_cast<double>(set.generated());
    progress.update(params.count ? placed
                                 : expected * std::max(placed / expected,
                                                       static_cast<double>(failures) / static_cast<double>(bound)));
    if (set.try_add_dart(rng)) {
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
