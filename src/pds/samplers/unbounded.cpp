// The unbounded, chunk-invariant Poisson disk field (docs/unbounded.md).
//
// Random sequential adsorption in continuous time: every cell of edge
// r/sqrt(D) owns a Poisson process of darts (rate one per cell, until time T =
// darts_per_cell), and a dart is kept iff no kept dart within r is earlier in
// the total order (time, cell, j). This is ebeida's level 0 (docs/ebeida.md,
// "darts in time order") without the domain: the union of the cells' streams
// is one Poisson process in space-time, so in time order it is sequential
// dart throwing with uniform darts, on the whole plane at once.
//
// Why a region can be computed alone, exactly: a dart's fate is a function of
// the earlier darts within r and their fates, recursively. Every step of that
// recursion goes to a strictly earlier dart, and there are finitely many darts
// before time T within any bounded distance, so the recursion ends; the set
// of darts it visits is determined by the seed and the dart, not by the region
// that asked. sample() therefore decides the darts of the region's cells in
// any order, and those outside that they depend on lazily (memoised for the
// call: an array of cells around the region, a hash map beyond), and returns
// exactly the kept darts in the region. No truncation, no margin guessed: the
// reach outside the region is whatever the recursion needs, and
// UnboundedStats::margin_cells reports it.
//
// Reach and depth: the earlier darts within r are tried earliest first, and
// the first kept one rejects the dart; an early dart has few darts before it,
// so the recursion seldom travels far. Cells inside the region are swept in
// time windows of 1/2 (as ebeida does), so the darts a decision recurses into
// are mostly decided already: within one window about 3 darts (2D; 11 in 3D)
// fall within r of a dart, a sparse graph whose decreasing-time paths are
// short. Cells outside the region are decided on demand from time 0. Measured
// depth at most 11 in 2D and 12 in 3D, reach 6 to 12 cells (docs/unbounded.md);
// kMaxUnboundedDepth bounds the depth with a clear error long before the
// stack (a frame is a few hundred bytes) could overflow.
//
// On a torus the cells' coordinates wrap modulo the cells per axis (at least
// 5, so the 5^D block of neighbours holds distinct cells) and distances wrap.
//
// Determinism: dart j of cell c has its bits from mix64 of (seed, c, j) and
// its waiting time from the portable logarithm (pds/portable_math.h).

#include "pds/samplers/unbounded.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <unordered_map>
#include <vector>

#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/portable_math.h"
#include "pds/rng.h"

namespace pds {
namespace {

// Positions are (c + u) * edge: beyond 2^40 cells from the origin the spacing
// of doubles near c would exceed 2^-12 of a cell.
constexpr double kMaxCellIndex = 0x1.0p40;
// Time windows of the sweep inside the region (only the recursion depth
// depends on it, never the samples).
constexpr double kWindow = 0.5;

template <int D>
using Cell = std::array<std::int64_t, D>;

template <int D>
struct CellHash {
  std::size_t operator()(const Cell<D>& c) const {
    std::uint64_t h = 0x243f6a8885a308d3ULL;
    for (int a = 0; a < D; ++a) h = mix64(h ^ static_cast<std::uint64_t>(c[a]));
    return static_cast<std::size_t>(h);
  }
};

template <int D>
struct Dart {
  Point<D> p;
  double t;
};

template <int D>
struct CellState {
  std::vector<Dart<D>> darts;        // in time order, all before time T
  std::vector<std::uint8_t> status;  // per dart: kUndecided, kKept or kRejected
  std::uint32_t swept = 0;           // darts[0, swept) decided by the sweep
  bool generated = false;
};

// Cells within this many cells of the region live in an array (the reach
// measured outside the region is under 10 cells); farther ones in a hash map.
constexpr std::int64_t kDenseMargin = 12;

constexpr std::uint8_t kUndecided = 0, kKept = 1, kRejected = 2;

/// A place in the total order of darts: (time, cell, index).
template <int D>
struct Key {
  double t;
  Cell<D> cell;
  std::uint32_t j;
};

template <int D>
bool earlier(double t, const Cell<D>& cell, std::uint32_t j, const Key<D>& k) {
  if (t != k.t) return t < k.t;
  if (cell != k.cell) return cell < k.cell;
  return j < k.j;
}

/// The offsets of the cells that can hold a point within r of a point of cell
/// 0: all of [-2, 2]^D (cell edge r/sqrt(D) puts the next ring at 2 edges =
/// 2r/sqrt(D) > r away for D <= 3; the corners of the block, exactly r away,
/// are kept so that rounding of positions can never hide a conflict). Sorted
/// by distance, the cell itself first: a rejection is usually found at once.
template <int D>
std::vector<Cell<D>> neighbour_offsets() {
  std::vector<Cell<D>> offsets;
  Cell<D> o{};
  o.fill(-2);
  while (true) {
    offsets.push_back(o);
    int a = 0;
    while (a < D && o[a] == 2) o[a++] = -2;
    if (a == D) break;
    ++o[a];
  }
  const auto gap = [](const Cell<D>& c) {
    std::int64_t s = 0, m = 0;
    for (int a = 0; a < D; ++a) {
      s += std::max<std::int64_t>(std::abs(c[a]) - 1, 0) * std::max<std::int64_t>(std::abs(c[a]) - 1, 0);
      m += c[a] * c[a];
    }
    return s * 64 + m;
  };
  std::stable_sort(offsets.begin(), offsets.end(), [&](const Cell<D>& a, const Cell<D>& b) { return gap(a) < gap(b); });
  return offsets;
}

template <int D>
Cell<D> filled_cell(std::int64_t v) {
  Cell<D> c;
  c.fill(v);
  return c;
}

template <int D>
class Settler {
 public:
  /// `torus` null: the plane, cells of edge edges[a] from the origin; else
  /// cells of edge edges[a] from torus->lo, `period[a]` of them along each axis.
  Settler(const UnboundedParams& params, std::uint64_t seed, const std::array<double, D>& edges,
          const Domain<D>* torus, const Cell<D>& period, const Cell<D>& lo, const Cell<D>& hi)
      : r2_(params.radius * params.radius),
        end_time_(params.darts_per_cell),
        edges_(edges),
        torus_(torus),
        period_(period),
        key_(mix64(mix64(seed ^ 0x756e626f756e6465ULL) + 0x9e3779b97f4a7c15ULL)),
        offsets_(neighbour_offsets<D>()) {
    std::size_t size = 1;
    for (int a = 0; a < D; ++a) {
      dense_lo_[a] = lo[a] - kDenseMargin;
      dense_n_[a] = hi[a] - lo[a] + 1 + 2 * kDenseMargin;
      size *= static_cast<std::size_t>(dense_n_[a]);
    }
    dense_.resize(size);
  }

  /// The cell's own coordinates: on a torus, wrapped into [0, period).
  Cell<D> canonical(Cell<D> c) const {
    if (torus_)
      for (int a = 0; a < D; ++a) c[a] = ((c[a] % period_[a]) + period_[a]) % period_[a];
    return c;
  }

  /// The state of a cell given by its own (canonical) coordinates.
  CellState<D>& state(const Cell<D>& c) {
    std::size_t index = 0;
    bool inside = true;
    for (int a = D - 1; a >= 0; --a) {
      const std::int64_t i = c[a] - dense_lo_[a];
      inside = inside && i >= 0 && i < dense_n_[a];
      index = index * static_cast<std::size_t>(dense_n_[a]) + static_cast<std::size_t>(i);
    }
    CellState<D>& s = inside ? dense_[index] : sparse_[c];
    if (!s.generated) {
      generate(c, s);
      s.generated = true;
      ++cells_touched_;
      for (int a = 0; a < D; ++a) reach_lo_[a] = std::min(reach_lo_[a], c[a]), reach_hi_[a] = std::max(reach_hi_[a], c[a]);
    }
    return s;
  }

  /// Decides every dart of cell c before time t.
  void settle_until(Cell<D> c, double t) {
    c = canonical(c);
    CellState<D>& s = state(c);
    while (s.swept < s.darts.size() && s.darts[s.swept].t < t) decide(c, s, s.swept++);
  }

  std::size_t cells_touched() const { return cells_touched_; }
  /// The bounding box of the cells touched.
  const Cell<D>& reach_lo() const { return reach_lo_; }
  const Cell<D>& reach_hi() const { return reach_hi_; }
  std::size_t darts_settled() const { return darts_settled_; }
  int max_depth() const { return max_depth_; }

 private:
  void generate(const Cell<D>& c, CellState<D>& s) const {
    std::uint64_t h = key_;
    for (int a = 0; a < D; ++a) h = mix64(h ^ mix64(static_cast<std::uint64_t>(c[a]) + 0x632be59bd9b4e019ULL));
    double t = 0.0;
    for (std::uint32_t j = 0;; ++j) {
      const std::uint64_t base = mix64(h + 0x9e3779b97f4a7c15ULL * (std::uint64_t{j} + 1));
      const auto part = [base](int k) { return mix64(base ^ (0xd1b54a32d192ed03ULL * static_cast<std::uint64_t>(k + 1))); };
      t += neg_log(uniform_open_from_bits(part(0)));
      if (!(t < end_time_)) break;
      Dart<D> d;
      d.t = t;
      for (int a = 0; a < D; ++a)
        d.p[a] = origin(a) + (static_cast<double>(c[a]) + uniform_from_bits(part(a + 1))) * edges_[a];
      if (torus_)  // rounding must not put a dart on the torus's upper bound
        for (int a = 0; a < D; ++a)
          if (!(d.p[a] < torus_->hi[a])) d.p[a] = std::nextafter(torus_->hi[a], torus_->lo[a]);
      s.darts.push_back(d);
    }
    s.status.assign(s.darts.size(), kUndecided);
  }

  /// Whether dart j of cell c is kept: iff no kept dart within r is earlier.
  /// The earlier darts within r are tried earliest first: the first kept one
  /// settles it, and an early dart has few darts before it to depend on, so
  /// the recursion stays near the dart (the causal cone of dart throwing,
  /// explored lazily; docs/unbounded.md measures its reach).
  bool decide(const Cell<D>& c, CellState<D>& s, std::uint32_t j) {
    if (s.status[j] != kUndecided) return s.status[j] == kKept;
    if (++depth_ > kMaxUnboundedDepth)
      throw Failure("unbounded: a chain of dependent darts is deeper than " + std::to_string(kMaxUnboundedDepth) +
                    " (report this with the seed and radius)");
    max_depth_ = std::max(max_depth_, depth_);
    ++darts_settled_;
    const Dart<D> d = s.darts[j];
    const Key<D> key{d.t, c, j};
    struct Candidate {
      Key<D> key;
      CellState<D>* state;
    };
    std::vector<Candidate> candidates;
    for (const Cell<D>& o : offsets_) {
      Cell<D> m;
      double gap2 = 0.0;  // squared distance from the dart to cell m
      for (int a = 0; a < D; ++a) {
        m[a] = c[a] + o[a];
        // Widened by 2^-10 of a cell: a dart's position (c + u) * edge may
        // round past its cell's bounds by up to 2^-12 of a cell at 2^40 cells
        // from the origin.
        const double lo = origin(a) + (static_cast<double>(m[a]) - 0x1.0p-10) * edges_[a],
                     hi = lo + edges_[a] * (1.0 + 0x1.0p-9);
        const double g = d.p[a] < lo ? lo - d.p[a] : (d.p[a] > hi ? d.p[a] - hi : 0.0);
        gap2 += g * g;
      }
      if (gap2 > r2_ * (1.0 + 1e-9)) continue;  // no dart of cell m is within r
      m = canonical(m);
      CellState<D>& ms = state(m);
      for (std::uint32_t k = 0; k < ms.darts.size() && ms.darts[k].t <= d.t; ++k) {
        if (ms.status[k] == kRejected || !earlier<D>(ms.darts[k].t, m, k, key)) continue;
        double dist2 = 0.0;
        for (int a = 0; a < D; ++a) {
          const double delta = torus_ ? torus_->delta(d.p[a], ms.darts[k].p[a], a) : ms.darts[k].p[a] - d.p[a];
          dist2 += delta * delta;
        }
        if (!(dist2 < r2_)) continue;
        if (ms.status[k] == kKept) {  // already known: rejected at once
          s.status[j] = kRejected;
          --depth_;
          return false;
        }
        candidates.push_back({Key<D>{ms.darts[k].t, m, k}, &ms});
      }
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
      return earlier<D>(a.key.t, a.key.cell, a.key.j, b.key);
    });
    bool kept = true;
    for (const Candidate& q : candidates)
      if (decide(q.key.cell, *q.state, q.key.j)) {
        kept = false;
        break;
      }
    s.status[j] = kept ? kKept : kRejected;
    --depth_;
    return kept;
  }

  double origin(int a) const { return torus_ ? torus_->lo[a] : 0.0; }

  double r2_, end_time_;
  std::array<double, D> edges_;
  const Domain<D>* torus_;
  Cell<D> period_;
  std::uint64_t key_;
  std::vector<Cell<D>> offsets_;
  Cell<D> dense_lo_{}, dense_n_{};
  std::vector<CellState<D>> dense_;
  std::unordered_map<Cell<D>, CellState<D>, CellHash<D>> sparse_;
  std::size_t cells_touched_ = 0;
  Cell<D> reach_lo_ = filled_cell<D>(INT64_MAX), reach_hi_ = filled_cell<D>(INT64_MIN);
  std::size_t darts_settled_ = 0;
  int depth_ = 0, max_depth_ = 0;
};

}  // namespace

template <int D>
UnboundedField<D>::UnboundedField(const UnboundedParams& params, std::uint64_t seed)
    : params_(params), seed_(seed) {
  static_assert(D >= 2 && D <= 3, "the unbounded field is built for the plane and space");
  require_radius(params.radius);
  if (!(params.darts_per_cell > 0.0 && params.darts_per_cell <= 64.0))
    throw InvalidArgument("darts_per_cell: " + detail::format_number(params.darts_per_cell) + " is outside (0, 64]");
  edges_.fill(params.radius / std::sqrt(static_cast<double>(D)));
}

template <int D>
UnboundedField<D>::UnboundedField(const UnboundedParams& params, std::uint64_t seed, const Domain<D>& torus)
    : UnboundedField(params, seed) {
  if (!torus.periodic) throw InvalidArgument("torus: the domain is not periodic (use the plane's constructor)");
  periodic_ = true;
  torus_ = torus;
  for (int a = 0; a < D; ++a) {
    validate_axis(a, torus.lo[a], torus.hi[a]);
    const double n = std::floor(torus.extent(a) / edges_[a]);
    if (!(n >= 5.0 && n <= kMaxCellIndex))
      throw InvalidArgument("torus: axis " + std::to_string(a) + " of extent " + detail::format_number(torus.extent(a)) +
                            " holds " + detail::format_number(n) + " cells of edge radius/sqrt(D) = " +
                            detail::format_number(edges_[a]) + "; it needs 5 to 2^40 (use ebeida for small tori)");
    cells_[a] = static_cast<std::int64_t>(n);
    edges_[a] = torus.extent(a) / n;  // >= radius/sqrt(D), below 1.25 of it (n >= 5): the reach still covers r
  }
}

template <int D>
PointSet<D> UnboundedField<D>::sample(const Domain<D>& region, UnboundedStats* stats) const {
  if (region.periodic) throw InvalidArgument("region: the unbounded field samples boxes, not a torus");
  Cell<D> lo, hi;
  for (int a = 0; a < D; ++a) {
    validate_axis(a, region.lo[a], region.hi[a]);
    if (periodic_ && !(region.lo[a] >= torus_.lo[a] && region.hi[a] <= torus_.hi[a]))
      throw InvalidArgument("region: axis " + std::to_string(a) + " [" + detail::format_number(region.lo[a]) + ", " +
                            detail::format_number(region.hi[a]) + ") is not inside the torus [" +
                            detail::format_number(torus_.lo[a]) + ", " + detail::format_number(torus_.hi[a]) + ")");
    const double origin = periodic_ ? torus_.lo[a] : 0.0;
    const double l = std::floor((region.lo[a] - origin) / edges_[a]), h = std::floor((region.hi[a] - origin) / edges_[a]);
    if (!(std::abs(l) <= kMaxCellIndex && std::abs(h) <= kMaxCellIndex))
      throw InvalidArgument("region: axis " + std::to_string(a) + " reaches " +
                            detail::format_number(std::abs(l) > std::abs(h) ? region.lo[a] : region.hi[a]) +
                            ", more than 2^40 cells (of edge " + detail::format_number(edges_[a]) +
                            ") from the origin");
    // One cell more on each side: rounding of (c + u) * edge may put a dart
    // of a neighbouring cell on the region's edge. On a torus, only its cells.
    lo[a] = static_cast<std::int64_t>(l) - 1;
    hi[a] = static_cast<std::int64_t>(h) + 1;
    if (periodic_) {
      lo[a] = std::max<std::int64_t>(lo[a], 0);
      hi[a] = std::min<std::int64_t>(hi[a], cells_[a] - 1);
    }
  }
  // The memo spans the region's cells and a margin of kDenseMargin cells a
  // side: a long, thin region has far more cells than its volume says, so
  // the budget counts the memo's box as well (computed in double: the cell
  // product of an absurd region would wrap a size_t).
  double memo_volume = 1.0;
  for (int a = 0; a < D; ++a)
    memo_volume *= (static_cast<double>(hi[a] - lo[a]) + 1.0 + 2.0 * kDenseMargin) * edges_[a];
  require_point_budget(std::max(packing_count(region.volume(), params_.radius, D),
                                packing_count(memo_volume, params_.radius, D)),
                       D, params_.max_points,
                       "radius " + detail::format_number(params_.radius) + " over a region of volume " +
                           detail::format_number(region.volume()) + " (" + detail::format_number(memo_volume) +
                           " with the cells it touches)",
                       // The memo's measured bytes a sample over D doubles (1.3 KB in 2D, 6.6 KB
                       // in 3D at 8 darts a cell; docs/unbounded.md), with margin.
                       D == 2 ? 96.0 : 320.0);

  Settler<D> settler(params_, seed_, edges_, periodic_ ? &torus_ : nullptr, cells_, lo, hi);
  const auto for_each_cell = [&](auto&& f) {
    Cell<D> c = lo;
    while (true) {
      f(c);
      int a = 0;
      while (a < D && c[a] == hi[a]) {
        c[a] = lo[a];
        ++a;
      }
      if (a == D) break;
      ++c[a];
    }
  };
  // Sweep in windows of time so that chains inside the region stay short;
  // the last window settles every dart (nothing is at or after the end time).
  for (double w = kWindow;; w += kWindow) {
    const bool last = !(w < params_.darts_per_cell);
    const double until = last ? INFINITY : w;
    for_each_cell([&](const Cell<D>& c) { settler.settle_until(c, until); });
    if (last) break;
  }

  PointSet<D> points;
  for_each_cell([&](const Cell<D>& c) {
    const CellState<D>& s = settler.state(c);
    for (std::size_t k = 0; k < s.darts.size(); ++k)
      if (s.status[k] == kKept && region.contains(s.darts[k].p)) points.push_back(s.darts[k].p);
  });
  std::sort(points.begin(), points.end(), [](const Point<D>& a, const Point<D>& b) {
    return static_cast<const std::array<double, D>&>(a) < static_cast<const std::array<double, D>&>(b);
  });

  if (stats) {
    stats->cells_touched = settler.cells_touched();
    stats->darts_settled = settler.darts_settled();
    stats->max_depth = settler.max_depth();
    std::int64_t margin = 0;
    for (int a = 0; a < D; ++a)
      margin = std::max({margin, lo[a] - settler.reach_lo()[a], settler.reach_hi()[a] - hi[a]});
    stats->margin_cells = static_cast<int>(margin);
  }
  return points;
}

template class UnboundedField<2>;
template class UnboundedField<3>;

}  // namespace pds
