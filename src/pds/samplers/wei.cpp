// L.-Y. Wei, "Parallel Poisson disk sampling", ACM SIGGRAPH 2008 (ACM TOG
// 27(3), article 20).
//
// Method, as in the paper:
// - A grid whose cells have edge s <= r/sqrt(D), so a cell holds at most one
//   sample and a sample covers its whole cell.
// - Phase groups: cells whose indices agree modulo m = floor(r/s) + 2 along
//   every axis. Two cells of a group are at least (m - 1) s > r apart, so their
//   darts never conflict and the cells of a group are processed in parallel;
//   the groups are visited one after another, in a random order.
// - k trials per cell, spread over k passes, each visiting every group.
// - Multi-resolution: after a level, each cell that is still empty is split
//   into 2^D children; children covered by a single disk are dropped (no dart
//   could land there) and the others get k passes at the next level. A dart in
//   a child is stored in its level-0 cell, so the fine cells of one level-0
//   cell are handled by one task, and the phase groups stay those of level 0
//   at every level.
//
// Departure from the paper: time windows. In the paper each pass visits the
// groups once, so the first group visited finds all its cells empty and fills
// nearly every one: a jittered lattice of period m cells holding about a third
// of the samples, seen as spikes in the spectrum at n0/m cycles per extent
// (measured, docs/wei.md), whatever the group order. Dart throwing has no such
// first group: each place receives darts at random times. So here every pass
// stands for one unit of dart-throwing time and is cut into W windows (the
// `windows` parameter, default 64). For each pass every empty level-0 cell
// draws its darts as dart throwing would: a Poisson(a) number, a = its number
// of active (sub)cells (1 at level 0), each at a uniform time, i.e. in a
// uniform window, in a uniform active sub-cell. Windows run in time order; in
// a window the groups run in a random order, the cells of a group in parallel.
// Only darts of neighbouring cells that fall in the same window are ordered by
// group instead of time, so the group's advantage, and with it the lattice,
// shrinks fast with W (the residual spike power about 6 times less from W = 16
// to 32, measured; a coherent lattice's power grows in proportion to N, so
// far larger sets want more windows); at W = 64 the
// radial power equals maximal dart throwing's at r = 0.02 in every annulus
// (tested), and at N = 7 10^5 the power at the lattice frequencies themselves
// is at the noise level (4 sets; W = 16 leaves them 3-30 times too high).
// The darts of a pass are drawn first and sorted by (window, group) (a
// counting sort over fixed chunks), so the cost is per dart, not per window.
// With faithful dart-throwing order the finer levels converge more slowly
// to saturation than with the lattice, hence 10 levels by default.
//
// Determinism: the number and windows of a cell's darts come from a hash of
// (seed, level, pass, cell), the darts from Rng(seed, level, cell, pass,
// window), the group order from Rng(seed, level, pass, window); no decision
// depends on the thread count or schedule (cells of one group never read what
// another writes: a dart looks at cells within floor(r/s) + 1 of its own, and
// same-group cells are farther). The output lists samples in level-0 cell
// order.
//
// Guarantees: minimum distance r; not maximal (a region covered only by the
// union of several disks keeps its cells active but cannot be filled; gaps
// remain where the darts of a level all missed); coverage, rho and the
// spectrum are measured in docs/wei.md.
//
// Complexity: O(N k) darts at level 0, and each finer level visits only the
// cells that are still uncovered: O(N) work for a fixed number of levels,
// k W 3^D barriers per level (empty ones skipped). Memory: one float offset
// per level-0 cell (about 3 per sample in 2D), the active fine cells (5
// bytes each at level 1 in 2D, about 2 per sample), and during a level's
// passes one 4-byte entry per dart (about one per empty cell), freed before
// the next level: at N = 10^6 in 2D a peak of 2.8 times the output (docs/wei.md).
#include "pds/samplers/wei.h"


#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/grid.h"
#include "pds/grid_neighbourhood.h"
#include "pds/parallel.h"
#include "pds/portable_math.h"
#include "pds/rng.h"
#include "union_cover.h"

namespace pds {
namespace {

constexpr int kMaxLevels = kWeiMaxLevels;
constexpr int kMaxWindows = kWeiMaxWindows;
constexpr double kProgressTotal = 1000.0;  // progress in thousandths of the run
constexpr int kFirstUnitDim = 4;            // from here WeiUnitSampler (below)
constexpr double kMaxPartBytes = 0x1.0p32;  // WeiUnitSampler's open cells: 4 GiB at most

/// The darts of one unit (a level-0 cell, with its active fine cells above
/// level 0) in one pass: a Poisson(active) number, each at a uniform time,
/// i.e. in a uniform one of the pass's windows, so every active cell gets
/// darts at rate one at Poisson times, as in dart throwing. All of it comes
/// from a hash of (key, cell), key being drawn from (seed, level, pass): no
/// state, no generator, and nothing but the seed and the cell decides it.
class Darts {
 public:
  Darts(std::uint64_t key, std::size_t cell, std::size_t active, int windows)
      : h_(mix64(key ^ mix64(cell + 0x9e3779b97f4a7c15ULL))), windows_(static_cast<std::uint64_t>(windows)) {
    // Poisson(active) as a sum of `active` Poisson(1) counts, one per active
    // cell, each from its own hash of h_ (the first from h_ itself).
    count_ = poisson_one(uniform_from_bits(h_));
    for (std::size_t i = 1; i < active; ++i)
      count_ += poisson_one(uniform_from_bits(mix64(h_ ^ (static_cast<std::uint64_t>(i) * 0xd1b54a32d192ed03ULL))));
  }
  int count() const { return count_; }
  int window(int dart) const {
    const std::uint64_t h = mix64(h_ + static_cast<std::uint64_t>(dart + 1) * 0x9e3779b97f4a7c15ULL);
    return static_cast<int>((static_cast<u128>(h) * windows_) >> 64);
  }

 private:
  std::uint64_t h_, windows_;
  int count_;
};

/// The phase groups of a window in a random order drawn from (seed, level,
/// pass, window).
std::vector<std::size_t> shuffled_groups(std::uint64_t seed, std::size_t groups, int level, int pass, int window) {
  std::vector<std::size_t> order(groups);
  std::iota(order.begin(), order.end(), std::size_t{0});
  Rng rng(seed, {static_cast<std::uint64_t>(level), static_cast<std::uint64_t>(pass),
                 static_cast<std::uint64_t>(window), ~std::uint64_t{0}});
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
  return order;
}

/// The fraction of the run done after `windows` windows of `level`: level 0
/// (most of the darts) is the first 90%, each finer level an equal part of
/// the rest.
double level_progress(const WeiParams& params, int level, int windows) {
  const double in_level = static_cast<double>(windows) / (params.trials * params.windows);
  return level == 0 ? 0.9 * in_level : 0.9 + 0.1 * (level - 1 + in_level) / std::max(1, params.levels - 1);
}

/// The key of the darts of one pass of one level.
std::uint64_t pass_key(std::uint64_t seed, int level, int pass) {
  return Rng(seed, {static_cast<std::uint64_t>(level), static_cast<std::uint64_t>(pass), ~std::uint64_t{1}}).next();
}

/// Draws the darts of every unit of a pass (a unit: the work one task does
/// in one group, a cell or a run of fine cells) and sorts them by window,
/// then phase group: a counting sort over fixed chunks of units, so that
/// neither the result nor its order depends on the threads. unit_range(g)
/// numbers the units of group g; for_each_unit(g, begin, end, f) calls
/// f(entry, cell, active) for those in [begin, end), entry being what the
/// events store, cell what the darts are drawn from, active the number of
/// cells they spread over. bucket[w * groups + g] is where window w's darts of
/// group g start in events.
template <class UnitRange, class ForEachUnit>
void schedule_pass(std::size_t groups, const WeiParams& params, std::uint64_t key, UnitRange&& unit_range,
                   ForEachUnit&& for_each_unit, std::vector<std::size_t>& bucket, std::vector<std::uint32_t>& events) {
  constexpr std::size_t kChunk = 4096;
  const std::size_t windows = static_cast<std::size_t>(params.windows);
  // counts[chunk_first[g] + c][w]: darts of window w in chunk c of group g;
  // turned into write positions below.
  std::vector<std::size_t> chunk_first(groups + 1, 0);
  for (std::size_t g = 0; g < groups; ++g) {
    const auto [begin, end] = unit_range(g);
    chunk_first[g + 1] = chunk_first[g] + (end - begin + kChunk - 1) / kChunk;
  }
  std::vector<std::size_t> counts(chunk_first[groups] * windows, 0);
  auto over_chunks = [&](auto&& per_dart) {
    for (std::size_t g = 0; g < groups; ++g) {
      // Plain variables: clang 14 cannot capture structured bindings.
      const auto range = unit_range(g);
      const std::size_t begin = range.first, end = range.second;
      parallel_for(0, chunk_first[g + 1] - chunk_first[g], 1, params.threads, [&](std::size_t c, std::size_t) {
        std::size_t* row = &counts[(chunk_first[g] + c) * windows];
        const std::size_t first = begin + c * kChunk;
        for_each_unit(g, first, std::min(first + kChunk, end), [&](std::size_t entry, std::size_t cell, std::size_t active) {
          const Darts darts(key, cell, active, params.windows);
          for (int d = 0; d < darts.count(); ++d) per_dart(row, entry, darts.window(d));
        });
      });
    }
  };
  over_chunks([](std::size_t* row, std::size_t, int w) { ++row[w]; });
  // Buckets in (window, group) order; within one, chunks in order.
  bucket.assign(windows * groups + 1, 0);
  std::size_t at = 0;
  for (std::size_t w = 0; w < windows; ++w)
    for (std::size_t g = 0; g < groups; ++g) {
      bucket[w * groups + g] = at;
      for (std::size_t c = chunk_first[g]; c < chunk_first[g + 1]; ++c) {
        const std::size_t n = counts[c * windows + w];
        counts[c * windows + w] = at;
        at += n;
      }
    }
  bucket[windows * groups] = at;
  events.resize(at);
  over_chunks([&](std::size_t* row, std::size_t entry, int w) { events[row[w]++] = static_cast<std::uint32_t>(entry); });
}

/// The phase groups of a grid: cells whose indices agree modulo `period`
/// along every axis. On a torus the last n mod period cells of an axis each
/// get a group of their own, so that no two cells of a group meet across the
/// seam. Groups are numbered axis 0 fastest.
template <int D>
class PhaseGroups {
 public:
  PhaseGroups() = default;
  PhaseGroups(const std::array<int, D>& cells, const std::array<int, D>& period, bool periodic)
      : n_(cells), period_(period) {
    for (int a = 0; a < D; ++a) {
      full_[a] = periodic ? n_[a] / period_[a] * period_[a] : n_[a];
      const int groups = periodic ? period_[a] + (n_[a] - full_[a]) : std::min(period_[a], n_[a]);
      members_[a].assign(static_cast<std::size_t>(groups), {});
      for (int c = 0; c < n_[a]; ++c) members_[a][static_cast<std::size_t>(coord(c, a))].push_back(c);
      count_ *= static_cast<std::size_t>(groups);
    }
  }

  std::size_t count() const { return count_; }

  /// The group of the cell with coordinates c.
  std::size_t of(const std::array<int, D>& c) const {
    std::size_t g = 0, stride = 1;
    for (int a = 0; a < D; ++a) {
      g += static_cast<std::size_t>(coord(c[a], a)) * stride;
      stride *= members_[a].size();
    }
    return g;
  }

  /// The number of cells of group g.
  std::size_t size(std::size_t g) const {
    std::size_t total = 1;
    for (int a = 0; a < D; ++a) {
      total *= members_[a][g % members_[a].size()].size();
      g /= members_[a].size();
    }
    return total;
  }

  /// Calls f(coords) for the cells [begin, end) of group g, numbered in the
  /// product of its per-axis coordinate lists, axis 0 fastest.
  template <class F>
  void for_each_cell(std::size_t g, std::size_t begin, std::size_t end, F&& f) const {
    std::array<const std::vector<int>*, D> lists;
    for (int a = 0; a < D; ++a) {
      lists[a] = &members_[a][g % members_[a].size()];
      g /= members_[a].size();
    }
    // Position in the product of the lists, decoded once and then stepped
    // like an odometer.
    std::array<std::size_t, D> at;
    std::size_t rest = begin;
    for (int a = 0; a < D; ++a) {
      at[a] = rest % lists[a]->size();
      rest /= lists[a]->size();
    }
    for (std::size_t u = begin; u != end; ++u) {
      std::array<int, D> c;
      for (int a = 0; a < D; ++a) c[a] = (*lists[a])[at[a]];
      for (int a = 0; a < D && ++at[a] == lists[a]->size(); ++a) at[a] = 0;
      f(c);
    }
  }

 private:
  int coord(int c, int axis) const { return c < full_[axis] ? c % period_[axis] : period_[axis] + (c - full_[axis]); }

  std::array<int, D> n_{}, period_{}, full_{};
  std::array<std::vector<std::vector<int>>, D> members_;  // per axis: the coordinates of each group coordinate
  std::size_t count_ = 1;
};

/// A cell of a finer level: its level-0 cell and its position inside it.
struct FineCell {
  std::uint32_t parent;
  std::uint32_t sub;  // sub-cell index at this level, axis 0 fastest
};

/// The active cells of a finer level as two arrays, parents and subs. A sub
/// at level l is below 2^(D l), so it is stored in the fewest of 1, 2 or 4
/// bytes that hold every index of the level: at level 1 in 2D, where these
/// cells are most numerous (about 2 per sample), 5 bytes a cell instead of 8.
class FineCells {
 public:
  FineCells() = default;
  FineCells(std::size_t size, int sub_bits)
      : parents_(size), width_(sub_bits <= 8 ? 1 : (sub_bits <= 16 ? 2 : 4)), subs_(size * width_) {}
  std::size_t size() const { return parents_.size(); }
  bool empty() const { return parents_.empty(); }
  std::uint32_t parent(std::size_t i) const { return parents_[i]; }
  FineCell operator[](std::size_t i) const {
    // Bytes, read through memcpy: a 2- or 4-byte sub need not be aligned.
    const std::uint8_t* at = &subs_[i * width_];
    std::uint32_t sub;
    if (width_ == 1) {
      sub = *at;
    } else if (width_ == 2) {
      std::uint16_t s;
      std::memcpy(&s, at, 2);
      sub = s;
    } else {
      std::memcpy(&sub, at, 4);
    }
    return {parents_[i], sub};
  }
  void set(std::size_t i, FineCell cell) {
    parents_[i] = cell.parent;
    std::uint8_t* at = &subs_[i * width_];
    if (width_ == 1) {
      *at = static_cast<std::uint8_t>(cell.sub);
    } else if (width_ == 2) {
      const auto s = static_cast<std::uint16_t>(cell.sub);
      std::memcpy(at, &s, 2);
    } else {
      std::memcpy(at, &cell.sub, 4);
    }
  }

 private:
  std::vector<std::uint32_t> parents_;
  std::size_t width_ = 4;
  std::vector<std::uint8_t> subs_;
};

/// What both samplers share: k passes a level, each cut into W time windows.
/// The darts of a pass are drawn and sorted first (schedule_pass); in a
/// window the phase groups run one after another in a random order, the
/// units of a group in parallel (Sampler::run_group). Sampler provides
/// group_count(), unit_range(level, g), for_each_unit(level, g, begin, end, f)
/// and run_group(level, pass, window, bucket).
template <class Sampler>
class WeiPasses {
 protected:
  WeiPasses(const WeiParams& params, std::uint64_t seed)
      : params_(params), seed_(seed), progress_(params.progress, kProgressTotal) {}

  void run_level(int level) {
    Sampler& self = static_cast<Sampler&>(*this);
    const std::size_t groups = self.group_count();
    for (int pass = 0; pass < params_.trials; ++pass) {
      schedule_pass(
          groups, params_, pass_key(seed_, level, pass), [&](std::size_t g) { return self.unit_range(level, g); },
          [&](std::size_t g, std::size_t begin, std::size_t end, auto&& f) {
            self.for_each_unit(level, g, begin, end, f);
          },
          bucket_, events_);
      for (int w = 0; w < params_.windows; ++w) {
        for (const std::size_t g : shuffled_groups(seed_, groups, level, pass, w))
          self.run_group(level, pass, w, static_cast<std::size_t>(w) * groups + g);
        progress_.update(level_progress(params_, level, pass * params_.windows + w + 1) * kProgressTotal);
      }
    }
    // Freed before the next refine; `events_ = {}` would only clear it (it
    // picks the initializer-list assignment).
    std::vector<std::uint32_t>().swap(events_);
  }

  const WeiParams& params_;
  std::uint64_t seed_;
  ProgressReporter progress_;
  // The darts of the current pass, one entry per dart naming its unit (see
  // for_each_unit), sorted by window, then group; bucket_[w * groups + g] is
  // where window w's darts of group g start.
  std::vector<std::uint32_t> events_;
  std::vector<std::size_t> bucket_;
};

template <int D>
class WeiSampler : public WeiPasses<WeiSampler<D>> {
  using Offset = std::array<float, D>;

 public:
  WeiSampler(const WeiParams& params, const Domain<D>& domain, std::uint64_t seed)
      : WeiPasses<WeiSampler>(params, seed), domain_(domain), r2_(params.radius * params.radius) {
    const double r = params.radius;
    double total = 1.0;
    for (int i = 0; i < D; ++i) {
      n_[i] = static_cast<int>(std::max(1.0, std::ceil(domain.extent(i) * std::sqrt(double(D)) / r)));
      edge_[i] = domain.extent(i) / n_[i];
      total *= n_[i];
      // Cells within `reach` of a dart's cell hold every sample closer than r.
      reach_[i] = static_cast<int>(std::floor(r / edge_[i])) + 1;
      period_[i] = reach_[i] + 1;
    }
    if (total > static_cast<double>(std::numeric_limits<std::uint32_t>::max() / 2))
      throw InvalidArgument("wei: radius " + detail::format_number(r) +
                            " is too small for the domain (grid above 2^31 cells)");
    hood_ = GridNeighbourhood<D>(domain, n_);
    std::size_t stride = 1;
    for (int i = 0; i < D; ++i) {
      stride_[i] = stride;
      stride *= static_cast<std::size_t>(n_[i]);
    }
    groups_ = PhaseGroups<D>(n_, period_, domain.periodic);
    Offset empty;
    empty.fill(std::numeric_limits<float>::quiet_NaN());
    grid_.assign(stride, empty);
  }

  PointSet<D> run() {
    for (int level = 0; level < params_.levels; ++level) {
      if (level > 0) {
        refine(level);
        if (active_.empty()) break;
      }
      run_level(level);
    }
    progress_.finish();
    active_ = {};  // freed before the output is built
    PointSet<D> points;
    std::size_t count = 0;
    for (const auto& p : grid_) count += !std::isnan(p[0]);
    points.reserve(count);
    for (std::size_t cell = 0; cell < grid_.size(); ++cell)
      if (!std::isnan(grid_[cell][0])) points.push_back(sample(coords(cell), grid_[cell]));
    return points;
  }

 private:
  using Passes = WeiPasses<WeiSampler>;
  friend Passes;
  using Passes::bucket_, Passes::events_, Passes::params_, Passes::progress_, Passes::run_level, Passes::seed_;

  std::array<int, D> coords(std::size_t cell) const {
    std::array<int, D> c;
    for (int i = 0; i < D; ++i) {
      c[i] = static_cast<int>(cell % static_cast<std::size_t>(n_[i]));
      cell /= static_cast<std::size_t>(n_[i]);
    }
    return c;
  }

  std::size_t group_of(std::size_t cell) const { return groups_.of(coords(cell)); }
  std::size_t group_count() const { return groups_.count(); }

  /// The samples of the cells within reach of `cell`: every sample closer
  /// than r to a point of the cell. Gathered once per cell and reused by all
  /// its darts and children.
  void gather(const std::array<int, D>& cell, std::vector<Point<D>>& near) const {
    near.clear();
    for_each_near(cell, [&](const Point<D>& s) {
      near.push_back(s);
      return true;
    });
  }

  bool free(const Point<D>& x, const std::vector<Point<D>>& near) const {
    for (const Point<D>& s : near)
      if (domain_.distance2(x, s) < r2_) return false;
    return true;
  }

  /// Calls f(sample) for the samples of the cells within reach of `cell`;
  /// f returns false to stop. Returns false if f stopped it.
  template <class F>
  bool for_each_near(const std::array<int, D>& cell, F&& f) const {
    return hood_.for_each_cell(hood_.window_around(cell, reach_), [&](std::size_t index, const std::array<int, D>& c) {
      const Offset& o = grid_[index];
      return std::isnan(o[0]) || f(sample(c, o));
    });
  }

  /// A stored sample: its level-0 cell's corner plus its float offset. These
  /// doubles are the sample (every distance test and the output use them).
  Point<D> sample(const std::array<int, D>& cell, const Offset& o) const {
    Point<D> p;
    for (int i = 0; i < D; ++i) p[i] = domain_.lo[i] + cell[i] * edge_[i] + static_cast<double>(o[i]);
    return p;
  }

  /// Bounds of sub-cell `sub` of level-0 cell `cell` at `level`.
  void sub_bounds(const std::array<int, D>& cell, std::uint32_t sub, int level, Point<D>& lo, Point<D>& hi) const {
    const int side = 1 << level;
    for (int i = 0; i < D; ++i) {
      const int s = static_cast<int>(sub % static_cast<std::uint32_t>(side));
      sub /= static_cast<std::uint32_t>(side);
      const double base = domain_.lo[i] + cell[i] * edge_[i];
      const double e = edge_[i] / side;
      lo[i] = base + s * e;
      // The last cell ends exactly at hi whatever the rounding.
      hi[i] = (cell[i] == n_[i] - 1 && s == side - 1) ? domain_.hi[i] : base + (s + 1) * e;
    }
  }

  /// A dart drawn from `rng` in sub-cell `sub` of `cell` at `level`; stores it
  /// and returns true if it fits. `fits(q)` says whether the dart q is at
  /// distance >= r from every sample.
  template <class Fits>
  bool throw_dart(std::size_t cell, const std::array<int, D>& c, std::uint32_t sub, int level, Rng& rng, Fits&& fits) {
    Point<D> lo, hi, x;
    sub_bounds(c, sub, level, lo, hi);
    for (int i = 0; i < D; ++i) x[i] = rng.uniform(lo[i], hi[i]);
    // Stored as a float offset in its level-0 cell (half the memory of a
    // point); the dart becomes the point that offset represents, which must
    // still lie in its cell and in the domain (a rounding can push it out).
    Offset o;
    bool inside = true;
    for (int i = 0; i < D; ++i) {
      o[i] = static_cast<float>(x[i] - (domain_.lo[i] + c[i] * edge_[i]));
      inside = inside && o[i] >= 0.0f && static_cast<double>(o[i]) < edge_[i];
    }
    if (!inside) return false;
    const Point<D> q = sample(c, o);
    if (!domain_.contains(q) || !fits(q)) return false;
    grid_[cell] = o;
    return true;
  }

  /// The generator of the darts of `cell` in one window.
  Rng dart_rng(int level, std::size_t cell, int pass, int window) const {
    return Rng(seed_, {static_cast<std::uint64_t>(level), cell, static_cast<std::uint64_t>(pass),
                       static_cast<std::uint64_t>(window)});
  }

  /// The units of group g: at level 0 the cells whose coordinates fall in
  /// the group's coordinate lists (numbered 0 .. count - 1 in the product of
  /// the lists); above, the runs of active_ (numbered by their index there).
  std::pair<std::size_t, std::size_t> unit_range(int level, std::size_t g) const {
    if (level > 0) return {group_begin_[g], group_begin_[g + 1]};
    return {0, groups_.size(g)};
  }

  /// Calls f(unit, cell, active) for the empty units of group g that start in
  /// [begin, end): unit is what events_ stores (the cell at level 0, the index
  /// of its first active fine cell above), active the number of (sub)cells.
  template <class F>
  void for_each_unit(int level, std::size_t g, std::size_t begin, std::size_t end, F&& f) const {
    if (level > 0) {
      const std::size_t group_begin = group_begin_[g], group_end = group_begin_[g + 1];
      std::size_t i = begin;
      while (i < end && i > group_begin && active_.parent(i) == active_.parent(i - 1)) ++i;
      while (i < end) {
        const std::uint32_t cell = active_.parent(i);
        std::size_t j = i;
        while (j < group_end && active_.parent(j) == cell) ++j;
        if (std::isnan(grid_[cell][0])) f(i, cell, j - i);
        i = j;
      }
      return;
    }
    groups_.for_each_cell(g, begin, end, [&](const std::array<int, D>& c) {
      std::size_t cell = 0;
      for (int i = 0; i < D; ++i) cell += static_cast<std::size_t>(c[i]) * stride_[i];
      if (std::isnan(grid_[cell][0])) f(cell, cell, 1);
    });
  }

  /// The darts of one window of a pass in one phase group, the cells in
  /// parallel. A run of equal entries is one unit's darts in this window; a
  /// chunk processes the runs that start inside it, so chunking never
  /// changes what is computed.
  void run_group(int level, int pass, int window, std::size_t bucket) {
    const std::size_t begin = bucket_[bucket], end = bucket_[bucket + 1];
    if (begin == end) return;
    // Small chunks: at the finer levels a bucket holds a few hundred darts.
    parallel_for(begin, end, 64, params_.threads, [&](std::size_t range_begin, std::size_t range_end) {
      std::vector<Point<D>> near;
      std::size_t i = range_begin;
      while (i < range_end && i > begin && events_[i] == events_[i - 1]) ++i;
      while (i < range_end) {
        const std::uint32_t unit = events_[i];
        std::size_t j = i;
        while (j < end && events_[j] == unit) ++j;
        const std::size_t darts = j - i;
        i = j;
        const std::uint32_t cell = level == 0 ? unit : active_.parent(unit);
        if (!std::isnan(grid_[cell][0])) continue;  // filled earlier in this pass
        const auto c = coords(cell);
        Rng rng = dart_rng(level, cell, pass, window);
        // A single dart is tested against the neighbours as they are read,
        // stopping at the first conflict; several share one gathered list.
        auto fits = [&](const Point<D>& q) {
          return darts == 1 ? for_each_near(c, [&](const Point<D>& s) { return domain_.distance2(q, s) >= r2_; })
                            : free(q, near);
        };
        if (darts > 1) gather(c, near);
        if (level == 0) {
          for (std::size_t d = 0; d < darts; ++d)
            if (throw_dart(cell, c, 0, 0, rng, fits)) break;
          continue;
        }
        std::size_t last = unit;
        while (last < active_.size() && active_.parent(last) == cell) ++last;
        // Each dart in one of the cell's active fine cells, chosen uniformly.
        for (std::size_t d = 0; d < darts; ++d)
          if (throw_dart(cell, c, active_[unit + rng.below(last - unit)].sub, level, rng, fits)) break;
      }
    });
  }


  /// True if one sample's disk contains the whole box [lo, hi].
  bool covered(const Point<D>& lo, const Point<D>& hi, const std::vector<Point<D>>& near) const {
    Point<D> centre;
    std::array<double, D> half;
    for (int i = 0; i < D; ++i) {
      centre[i] = 0.5 * (lo[i] + hi[i]);
      half[i] = 0.5 * (hi[i] - lo[i]);
    }
    for (const Point<D>& s : near) {
      double far2 = 0.0;
      for (int i = 0; i < D; ++i) {
        const double d = std::abs(domain_.delta(s[i], centre[i], i)) + half[i];
        far2 += d * d;
      }
      if (far2 <= r2_) return true;
    }
    return false;
  }

  /// Builds the active cells of `level` from those of level - 1: children of
  /// still-empty cells that no single disk covers.
  void refine(int level) {
    // Level 1 refines every level-0 cell, later levels the active fine cells.
    const bool from_grid = level == 1;
    const std::size_t count = from_grid ? grid_.size() : active_.size();
    auto parent_at = [&](std::size_t p) { return from_grid ? FineCell{static_cast<std::uint32_t>(p), 0} : active_[p]; };
    // One bit per child, computed in parallel; compacted in order afterwards.
    constexpr int kChildren = 1 << D;
    std::vector<std::uint8_t> masks(count);
    const int parent_side = 1 << (level - 1);
    const auto refine_range = [&](std::size_t range_begin, std::size_t range_end) {
      std::vector<Point<D>> near;
      std::uint32_t gathered = std::numeric_limits<std::uint32_t>::max();
      for (std::size_t p = range_begin; p != range_end; ++p) {
        const FineCell f = parent_at(p);
        masks[p] = 0;
        if (!std::isnan(grid_[f.parent][0])) continue;  // a sample covers its whole level-0 cell
        const auto c = coords(f.parent);
        // Fine cells of one level-0 cell are contiguous: gather once for them.
        if (f.parent != gathered) {
          gather(c, near);
          gathered = f.parent;
        }
        std::uint8_t mask = 0;
        for (int child = 0; child < kChildren; ++child) {
          Point<D> lo, hi;
          sub_bounds(c, child_sub(f.sub, child, parent_side), level, lo, hi);
          if (!covered(lo, hi, near)) mask |= static_cast<std::uint8_t>(1u << child);
        }
        masks[p] = mask;
      }
    };
    // Level 1 reads every level-0 cell and places no sample: between batches
    // this thread polls for a stop.
    constexpr std::size_t kParentsPerBatch = std::size_t{1} << 18;
    for (std::size_t batch = 0; batch < count; batch += kParentsPerBatch) {
      parallel_for(batch, std::min(count, batch + kParentsPerBatch), 256, params_.threads, refine_range);
      progress_.poll();
    }
    // The new active cells, sorted by phase group (a counting sort, written in
    // place), in parent order within a group.
    group_begin_.assign(group_count() + 1, 0);
    for (std::size_t p = 0; p < count; ++p)
      if (masks[p])
        group_begin_[group_of(parent_at(p).parent) + 1] += static_cast<std::size_t>(std::popcount(masks[p]));
    for (std::size_t g = 0; g + 1 < group_begin_.size(); ++g) group_begin_[g + 1] += group_begin_[g];
    std::vector<std::size_t> fill(group_begin_.begin(), group_begin_.end() - 1);
    if (group_begin_.back() > std::numeric_limits<std::uint32_t>::max())
      throw InvalidArgument("wei: more than 2^32 active fine cells; use fewer levels or a larger radius");
    FineCells next(group_begin_.back(), D * level);
    for (std::size_t p = 0; p < count; ++p) {
      if (!masks[p]) continue;
      const FineCell f = parent_at(p);
      std::size_t& at = fill[group_of(f.parent)];
      for (int child = 0; child < kChildren; ++child)
        if (masks[p] >> child & 1) next.set(at++, {f.parent, child_sub(f.sub, child, parent_side)});
    }
    active_ = std::move(next);
  }

  /// The index at the next level of child `child` of sub-cell `sub`.
  static std::uint32_t child_sub(std::uint32_t sub, int child, int parent_side) {
    std::uint32_t result = 0, stride = 1;
    for (int i = 0; i < D; ++i) {
      const std::uint32_t s = sub % static_cast<std::uint32_t>(parent_side);
      sub /= static_cast<std::uint32_t>(parent_side);
      result += (2 * s + static_cast<std::uint32_t>(child >> i & 1)) * stride;
      stride *= static_cast<std::uint32_t>(2 * parent_side);
    }
    return result;
  }

  const Domain<D>& domain_;
  double r2_;
  std::array<int, D> n_, reach_, period_;
  PhaseGroups<D> groups_;
  std::array<double, D> edge_;
  std::array<std::size_t, D> stride_;
  GridNeighbourhood<D> hood_;  // the level-0 grid's windows
  // The sample of each level-0 cell as a float offset from the cell's corner
  // (NaN if none): 8 bytes a cell in 2D instead of 16.
  std::vector<Offset> grid_;
  FineCells active_;                      // this level's cells, sorted by phase group
  std::vector<std::size_t> group_begin_;  // where each group's cells start in active_
};

// From 4 dimensions the paper's grid stops paying. Its cells have edge
// r/sqrt(D), so a dart reads the (2 floor(sqrt D) + 3)^D cells around its own
// (6,561 in 4D, 5.8 million in 8D), the phase groups number 4^D, and the
// grid holds (sqrt(D)/r)^D cells, about 1,600 a sample in 8D. Here the unit
// of parallel work is a cell of edge just over r (a `unit`, several samples
// at once): units whose indices agree in parity along every axis form a
// phase group (2^D of them; a torus axis with an odd count gives its last
// unit a group of its own), and two units of a group have a whole unit
// between them, so they are farther apart than r and their darts never
// conflict. A unit throws its darts one after another, tested against the
// samples of earlier groups (a grid of edge r whose pruned walk reads at most
// 3^D cells) and against those it took itself in this window; the group's new
// samples enter the grid after the group, in unit order.
//
// Darts come at the paper's rate: each pass gives every cell of edge about
// r/sqrt(D) (the `tiny` cells, a whole number of them along each axis of a
// unit) a Poisson(1) number of darts at uniform times, in the same time
// windows as below 4D. Finer levels split the tiny cells in halves along
// every axis and keep the parts that neither one disk nor the union of
// several covers (detail::UnionCover, as ebeida); a unit's darts then go to
// its open parts, each uniform. The open parts of a level are found by one
// descent a unit: a box that is covered is dropped whole, so the many parts
// deep inside disks are never visited one by one.
//
// Measured (unit torus, two threads, 2026-12-03): in 4D, r = 0.07, 35,147
// points in 4.9 s and 53 MB, against 32,744 in 25 s and 30 MB with the
// paper's grid (rho 0.806 against 0.792); in 5D 10^5 points in 108 s and
// 680 MB. The open parts, most of the memory, grow about eightfold a
// dimension (peak memory 1.5 KB a sample in 4D, 50 KB in 6D, 260 KB in 7D,
// where 489 points take 42 s on two threads), so
// the registry stops at 5 dimensions; the template takes 6 to 8 for callers
// who can wait.
template <int D>
class WeiUnitSampler : public WeiPasses<WeiUnitSampler<D>> {
  /// An open part of a finer level: its unit and its index inside the unit
  /// (axis 0 fastest, parts_per_axis(level) along each axis).
  struct Part {
    std::uint32_t unit;
    std::uint64_t index;
  };
  using Deltas = std::vector<std::array<double, D>>;
  /// A thread's buffers for descend().
  struct Scratch {
    std::vector<Deltas> near;                                 // per depth of the descent
    std::vector<std::vector<std::array<std::uint64_t, D>>> parents;  // the same
    Deltas from_box;           // the disks that reach the current box's centre, from it
    detail::UnionCover<D> union_cover;
  };

 public:
  WeiUnitSampler(const WeiParams& params, const Domain<D>& domain, std::uint64_t seed)
      : WeiPasses<WeiUnitSampler>(params, seed),
        domain_(domain),
        r_(params.radius),
        r2_(params.radius * params.radius),
        cover2_(params.radius * params.radius * (1.0 - 1e-9)),
        samples_(unit_grid(domain, params.radius)) {
    // The open parts dominate the memory. Measured (2026-12-03): the run's
    // peak is about 1.5 KB a sample in 4D, 6.5 KB in 5D, 50 KB in 6D and
    // 260 KB in 7D (unit torus); in 8D the level-1 open cells alone came to
    // 110 KB a sample (a box of edge 0.5, r = 0.3). So: 2 KB in 4D, eight
    // times more a dimension up to 7D.
    const double bytes =
        typical_count(sizing_volume(domain, r_), r_, D) * 2048.0 * std::pow(8.0, std::min(D, 7) - 4);
    if (bytes > kMaxPartBytes)
      throw InvalidArgument("wei: radius " + detail::format_number(r_) + " in " + std::to_string(D) +
                            " dimensions would need about " + detail::format_number(bytes / 0x1.0p30) +
                            " GiB for its open cells (more than " + detail::format_number(kMaxPartBytes / 0x1.0p30) +
                            "); use a larger radius, or bridson or dart-throwing");
    tiny_cells_ = 1;
    for (int a = 0; a < D; ++a) {
      n_[a] = samples_.cells(a);
      edge_[a] = domain.extent(a) / n_[a];
      tiny_[a] = static_cast<int>(std::ceil(edge_[a] * std::sqrt(double(D)) / r_));
      tiny_cells_ *= static_cast<std::size_t>(tiny_[a]);
    }
    std::array<int, D> period;
    period.fill(2);
    groups_ = PhaseGroups<D>(n_, period, domain.periodic);
  }

  PointSet<D> run() {
    for (int level = 0; level < params_.levels; ++level) {
      if (level > 0 && !refine(level)) break;
      run_level(level);
    }
    progress_.finish();
    return std::move(samples_).take_points();
  }

 private:
  using Passes = WeiPasses<WeiUnitSampler>;
  friend Passes;
  using Passes::bucket_, Passes::events_, Passes::params_, Passes::progress_, Passes::run_level, Passes::seed_;

  /// Units of edge at least r (1 + 1e-6) along every axis that has more than
  /// one, so that units with one between them never hold samples closer
  /// than r, whatever the rounding.
  static Grid<D> unit_grid(const Domain<D>& domain, double r) {
    double edge = 0.0;
    for (int a = 0; a < D; ++a) {
      const double n = std::max(1.0, std::floor(domain.extent(a) / (r * (1.0 + 1e-6))));
      edge = std::max(edge, domain.extent(a) / n);
    }
    // Each axis gets at most the cells above (the widest axis exactly those).
    return Grid<D>(domain, edge * (1.0 + 1e-12));
  }

  std::size_t group_of(std::size_t unit) const { return groups_.of(samples_.neighbourhood().coords(unit)); }
  std::size_t group_count() const { return groups_.count(); }

  /// Parts along each axis at `level`: the tiny cells at level 0, halved at
  /// each level after.
  std::uint64_t parts_per_axis(int axis, int level) const { return static_cast<std::uint64_t>(tiny_[axis]) << level; }

  /// Whether the parts of `level` can be numbered in 64 bits.
  bool indexable(int level) const {
    double bits = 0.0;
    for (int a = 0; a < D; ++a) bits += std::log2(static_cast<double>(parts_per_axis(a, level)));
    return bits < 63.0;
  }

  /// The box of unit `unit`.
  void unit_box(std::size_t unit, Point<D>& lo, Point<D>& hi) const {
    const auto c = samples_.neighbourhood().coords(unit);
    for (int a = 0; a < D; ++a) {
      lo[a] = domain_.lo[a] + domain_.extent(a) * c[a] / n_[a];
      hi[a] = c[a] == n_[a] - 1 ? domain_.hi[a] : domain_.lo[a] + domain_.extent(a) * (c[a] + 1) / n_[a];
    }
  }

  /// The box of parts [first, last) (per axis) of `unit` at `level`.
  void parts_box(std::size_t unit, int level, const std::array<std::uint64_t, D>& first,
                 const std::array<std::uint64_t, D>& last, Point<D>& lo, Point<D>& hi) const {
    Point<D> unit_lo, unit_hi;
    unit_box(unit, unit_lo, unit_hi);
    for (int a = 0; a < D; ++a) {
      const std::uint64_t side = parts_per_axis(a, level);
      const double e = (unit_hi[a] - unit_lo[a]) / static_cast<double>(side);
      lo[a] = unit_lo[a] + static_cast<double>(first[a]) * e;
      hi[a] = last[a] == side ? unit_hi[a] : unit_lo[a] + static_cast<double>(last[a]) * e;
    }
  }

  std::array<std::uint64_t, D> part_coords(std::uint64_t index, int level) const {
    std::array<std::uint64_t, D> c;
    for (int a = 0; a < D; ++a) {
      c[a] = index % parts_per_axis(a, level);
      index /= parts_per_axis(a, level);
    }
    return c;
  }

  std::uint64_t part_index(const std::array<std::uint64_t, D>& c, int level) const {
    std::uint64_t index = 0, stride = 1;
    for (int a = 0; a < D; ++a) {
      index += c[a] * stride;
      stride *= parts_per_axis(a, level);
    }
    return index;
  }

  /// The units of group g: at level 0 every unit whose coordinates fall in
  /// the group's lists (numbered in the product of the lists); above, the
  /// open parts of the group in parts_ (numbered by their index there).
  std::pair<std::size_t, std::size_t> unit_range(int level, std::size_t g) const {
    if (level > 0) return {group_begin_[g], group_begin_[g + 1]};
    return {0, groups_.size(g)};
  }

  /// Calls f(token, unit, parts) for the units of group g that start in
  /// [begin, end): token is what events_ stores (the unit at level 0, the
  /// index of its first open part above), parts the number of cells its
  /// darts are spread over.
  template <class F>
  void for_each_unit(int level, std::size_t g, std::size_t begin, std::size_t end, F&& f) const {
    if (level > 0) {
      const std::size_t group_begin = group_begin_[g], group_end = group_begin_[g + 1];
      std::size_t i = begin;
      while (i < end && i > group_begin && parts_[i].unit == parts_[i - 1].unit) ++i;
      while (i < end) {
        std::size_t j = i;
        while (j < group_end && parts_[j].unit == parts_[i].unit) ++j;
        f(i, parts_[i].unit, j - i);
        i = j;
      }
      return;
    }
    groups_.for_each_cell(g, begin, end, [&](const std::array<int, D>& c) {
      const std::size_t unit = samples_.neighbourhood().index(c);
      f(unit, unit, tiny_cells_);
    });
  }

  /// The darts of one window of a pass in one phase group, the units in
  /// parallel; their samples enter the grid afterwards, in order.
  void run_group(int level, int pass, int window, std::size_t bucket) {
    const std::size_t begin = bucket_[bucket], end = bucket_[bucket + 1];
    if (begin == end) return;
    staged_.resize(end - begin);
    taken_.assign(end - begin, 0);
    parallel_for(begin, end, 64, params_.threads, [&](std::size_t range_begin, std::size_t range_end) {
      std::vector<Point<D>> mine;
      std::vector<std::int32_t> blockers;
      std::size_t i = range_begin;
      while (i < range_end && i > begin && events_[i] == events_[i - 1]) ++i;
      while (i < range_end) {
        const std::uint32_t token = events_[i];
        std::size_t j = i;
        while (j < end && events_[j] == token) ++j;
        const std::size_t unit = level == 0 ? token : parts_[token].unit;
        std::size_t last = token;
        if (level > 0)
          while (last < parts_.size() && parts_[last].unit == unit) ++last;
        Rng rng(seed_, {static_cast<std::uint64_t>(level), unit, static_cast<std::uint64_t>(pass),
                        static_cast<std::uint64_t>(window), 0x756e6974ULL});
        mine.clear();
        blockers.clear();
        for (std::size_t d = i; d < j; ++d) {
          Point<D> lo, hi, x;
          if (level == 0) {
            unit_box(unit, lo, hi);
          } else {
            const std::array<std::uint64_t, D> first = part_coords(parts_[token + rng.below(last - token)].index, level);
            std::array<std::uint64_t, D> next;
            for (int a = 0; a < D; ++a) next[a] = first[a] + 1;
            parts_box(unit, level, first, next, lo, hi);
          }
          for (int a = 0; a < D; ++a) {
            x[a] = rng.uniform(lo[a], hi[a]);
            if (!(x[a] < hi[a])) x[a] = std::nextafter(hi[a], lo[a]);
          }
          if (!fits(x, mine, blockers)) continue;
          mine.push_back(x);
          staged_[d - begin] = x;
          taken_[d - begin] = 1;
        }
        i = j;
      }
    });
    for (std::size_t d = 0; d < end - begin; ++d)
      if (taken_[d]) samples_.insert(staged_[d]);
  }

  /// Whether dart x is at least r from every sample: those of the grid and
  /// `mine`, the unit's own of this window. The samples that stopped the
  /// unit's earlier darts are tried first: the darts of a unit's open parts
  /// mostly fall in the same few disks, and a full walk of the grid reads
  /// hundreds of cells in 8D.
  bool fits(const Point<D>& x, const std::vector<Point<D>>& mine, std::vector<std::int32_t>& blockers) const {
    constexpr std::size_t kMaxBlockers = 16;
    for (std::size_t b = 0; b < blockers.size(); ++b)
      if (domain_.distance2(x, samples_.points()[static_cast<std::size_t>(blockers[b])]) < r2_) {
        std::rotate(blockers.begin(), blockers.begin() + static_cast<std::ptrdiff_t>(b),
                    blockers.begin() + static_cast<std::ptrdiff_t>(b) + 1);  // to the front
        return false;
      }
    for (const Point<D>& s : mine)
      if (domain_.distance2(x, s) < r2_) return false;
    std::int32_t blocker = -1;
    samples_.for_each_within(x, r_, [&](std::int32_t j, double d2) {
      if (!(d2 < r2_)) return true;
      blocker = j;
      return false;
    });
    if (blocker < 0) return true;
    if (blockers.size() == kMaxBlockers) blockers.pop_back();
    blockers.insert(blockers.begin(), blocker);
    return false;
  }


  /// The open parts of `level`: the parts of the units (level 1) or of the
  /// open parts of the last level that no single disk, nor the union of
  /// several, covers. False if none remain or the parts can no longer be
  /// numbered. Each unit is one descent: the samples near it are gathered
  /// once and thinned as the boxes shrink (a walk of the grid for each open
  /// part of the last level took most of the run in 6D).
  bool refine(int level) {
    if (!indexable(level)) return false;
    const bool from_units = level == 1;
    // The units to visit, with where their open parts start in parts_.
    std::vector<std::size_t> starts;
    if (from_units) {
      starts.resize(samples_.cell_count() + 1);
      std::iota(starts.begin(), starts.end(), std::size_t{0});
    } else {
      for (std::size_t i = 0; i < parts_.size(); ++i)
        if (i == 0 || parts_[i].unit != parts_[i - 1].unit) starts.push_back(i);
      starts.push_back(parts_.size());
    }
    const std::size_t roots = starts.size() - 1;
    constexpr std::size_t kRootsPerChunk = 4;
    const std::size_t chunks = (roots + kRootsPerChunk - 1) / kRootsPerChunk;
    std::vector<std::vector<Part>> found(chunks);
    std::atomic<std::size_t> total{0};
    const auto descend_chunks = [&](std::size_t chunk_begin, std::size_t chunk_end) {
      Scratch scratch;
      for (std::size_t chunk = chunk_begin; chunk != chunk_end; ++chunk)
        for (std::size_t root = chunk * kRootsPerChunk; root < std::min(roots, (chunk + 1) * kRootsPerChunk); ++root) {
          const std::size_t unit = from_units ? root : parts_[starts[root]].unit;
          if (scratch.parents.empty()) scratch.parents.resize(1);
          scratch.parents[0].clear();
          if (!from_units)
            for (std::size_t i = starts[root]; i < starts[root + 1]; ++i)
              scratch.parents[0].push_back(part_coords(parts_[i].index, level - 1));
          std::array<std::uint64_t, D> first, last;
          for (int a = 0; a < D; ++a) {
            first[a] = 0;
            last[a] = parts_per_axis(a, level);
          }
          Point<D> centre;
          const std::size_t before = found[chunk].size();
          descend(unit, level, !from_units, first, last, centre, scratch, 0, found[chunk]);
          if ((total += found[chunk].size() - before) * sizeof(Part) > kMaxPartBytes)
            throw Failure("wei: more than " + detail::format_number(kMaxPartBytes / 0x1.0p30) +
                          " GiB of open cells at level " + std::to_string(level) +
                          "; use fewer levels, a larger radius, or bridson");
        }
    };
    // A level's descent can take seconds in 5D and places no sample: between
    // batches of units this thread polls for a stop.
    constexpr std::size_t kChunksPerBatch = 256;
    for (std::size_t batch = 0; batch < chunks; batch += kChunksPerBatch) {
      parallel_for(batch, std::min(chunks, batch + kChunksPerBatch), 1, params_.threads, descend_chunks);
      progress_.poll();
    }
    std::vector<Part> next;
    for (auto& f : found) next.insert(next.end(), f.begin(), f.end());
    found = {};
    if (next.size() > std::numeric_limits<std::uint32_t>::max())
      throw InvalidArgument("wei: more than 2^32 open cells at level " + std::to_string(level) +
                            "; use fewer levels or a larger radius");
    // Sorted by group (a stable counting sort), unit order within a group.
    const std::size_t groups = group_count();
    group_begin_.assign(groups + 1, 0);
    for (const Part& p : next) ++group_begin_[group_of(p.unit) + 1];
    for (std::size_t g = 0; g < groups; ++g) group_begin_[g + 1] += group_begin_[g];
    std::vector<std::size_t> fill(group_begin_.begin(), group_begin_.end() - 1);
    parts_.resize(next.size());
    for (const Part& p : next) parts_[fill[group_of(p.unit)]++] = p;
    return !parts_.empty();
  }

  /// Adds to `out` the parts of `level` in the box of parts [first, last) of
  /// `unit` that lie in an open part of the last level (if `in_parents`) and
  /// that no disk nor union covers. scratch.parents[depth] holds the open
  /// parts of the last level that meet the parent box, near[depth] the
  /// samples that may cover part of it (as offsets from the centre of the
  /// unit, depth 0: from the grid); this box filters both into depth + 1.
  void descend(std::size_t unit, int level, bool in_parents, std::array<std::uint64_t, D>& first,
               std::array<std::uint64_t, D>& last, Point<D>& root, Scratch& scratch, std::size_t depth,
               std::vector<Part>& out) const {
    if (scratch.near.size() <= depth + 1) scratch.near.resize(depth + 2);
    if (scratch.parents.size() <= depth + 1) scratch.parents.resize(depth + 2);
    if (in_parents) {
      auto& parents = scratch.parents[depth + 1];
      parents.clear();
      for (const auto& p : scratch.parents[depth]) {
        bool meets = true;
        for (int a = 0; a < D; ++a) meets = meets && 2 * p[a] < last[a] && 2 * p[a] + 2 > first[a];
        if (meets) parents.push_back(p);
      }
      if (parents.empty()) return;
    }
    std::vector<Deltas>& near = scratch.near;
    Point<D> lo, hi, centre;
    std::array<double, D> half;
    parts_box(unit, level, first, last, lo, hi);
    double half_diagonal2 = 0.0;
    for (int a = 0; a < D; ++a) {
      centre[a] = 0.5 * (lo[a] + hi[a]);
      half[a] = 0.5 * (hi[a] - lo[a]);
      half_diagonal2 += half[a] * half[a];
    }
    if (depth == 0) root = centre;
    // A disk that covers some box inside this one has its centre within r of
    // that box's centre, so within r plus this box's half diagonal of ours.
    const double reach2 = square((r_ + std::sqrt(half_diagonal2)) * (1.0 + 1e-12));
    Deltas& mine = near[depth + 1];
    mine.clear();
    scratch.from_box.clear();
    bool covered = false;
    // Takes a sample's offset from the root's centre; keeps it if it may
    // cover part of this box, and notes whether it covers all of it.
    auto consider = [&](const std::array<double, D>& from_root) {
      std::array<double, D> d;  // from this box's centre
      double d2 = 0.0, far2 = 0.0;
      for (int a = 0; a < D; ++a) {
        d[a] = from_root[a] - (centre[a] - root[a]);
        if (domain_.periodic) {  // back to the nearest image
          const double period = domain_.extent(a);
          if (d[a] > 0.5 * period) d[a] -= period;
          else if (d[a] < -0.5 * period) d[a] += period;
        }
        d2 += d[a] * d[a];
        const double far = std::abs(d[a]) + half[a];
        far2 += far * far;
      }
      if (far2 < cover2_) covered = true;
      if (d2 <= reach2) {
        mine.push_back(from_root);
        if (d2 < r2_) scratch.from_box.push_back(d);  // reaches the centre: a candidate for the union test
      }
      return !covered;
    };
    if (depth == 0) {
      samples_.for_each_within(centre, std::sqrt(reach2), [&](std::int32_t j, double) {
        const Point<D>& s = samples_.points()[static_cast<std::size_t>(j)];
        std::array<double, D> from_root;
        for (int a = 0; a < D; ++a) from_root[a] = domain_.delta(root[a], s[a], a);
        return consider(from_root);
      });
    } else {
      for (const auto& from_root : near[depth])
        if (!consider(from_root)) break;
    }
    if (covered) return;
    // The union test needs every disk that reaches the box's centre; the walk
    // stopped early only if one disk covers the box.
    std::array<double, D> edge, origin{};
    for (int a = 0; a < D; ++a) edge[a] = 2.0 * half[a];
    if (scratch.union_cover.covers(scratch.from_box, origin, edge, cover2_)) return;
    // Split the axis whose parts span the most length; a single part is open.
    int axis = -1;
    double widest = 0.0;
    for (int a = 0; a < D; ++a)
      if (last[a] - first[a] > 1 && half[a] > widest) {
        widest = half[a];
        axis = a;
      }
    if (axis < 0) {
      out.push_back({static_cast<std::uint32_t>(unit), part_index(first, level)});
      return;
    }
    const std::uint64_t from = first[axis], to = last[axis], middle = from + (to - from) / 2;
    last[axis] = middle;
    descend(unit, level, in_parents, first, last, root, scratch, depth + 1, out);
    last[axis] = to;
    first[axis] = middle;
    descend(unit, level, in_parents, first, last, root, scratch, depth + 1, out);
    first[axis] = from;
  }

  static double square(double x) { return x * x; }

  const Domain<D>& domain_;
  double r_, r2_, cover2_;
  Grid<D> samples_;  // the units: cells of edge just over r
  std::array<int, D> n_{}, tiny_{};
  PhaseGroups<D> groups_;
  std::array<double, D> edge_{};
  std::size_t tiny_cells_ = 1;  // tiny cells a unit
  std::vector<Part> parts_;                               // this level's open parts, sorted by group
  std::vector<std::size_t> group_begin_;                  // where each group's parts start in parts_
  std::vector<Point<D>> staged_;  // run_group(): each dart's sample, if taken
  std::vector<std::uint8_t> taken_;
};

}  // namespace

template <int D>
PointSet<D> wei(const WeiParams& params, const Domain<D>& domain, std::uint64_t seed) {
  domain.validate();
  require_radius_budget(domain, params.radius, params.max_points);
  if (params.trials < 1) throw InvalidArgument("wei: trials must be at least 1, got " + std::to_string(params.trials));
  if (params.levels < 1 || params.levels > kMaxLevels)
    throw InvalidArgument("wei: levels must be in [1, " + std::to_string(kMaxLevels) + "], got " +
                          std::to_string(params.levels));
  if (params.windows < 1 || params.windows > kMaxWindows)
    throw InvalidArgument("wei: windows must be in [1, " + std::to_string(kMaxWindows) + "], got " +
                          std::to_string(params.windows));
  if (params.threads < 0)
    throw InvalidArgument("wei: threads must be 0 (all) or positive, got " + std::to_string(params.threads));
  if constexpr (D >= kFirstUnitDim)
    return WeiUnitSampler<D>(params, domain, seed).run();
  else
    return WeiSampler<D>(params, domain, seed).run();
}

#define PDS_INSTANTIATE(D) template PointSet<D> wei<D>(const WeiParams&, const Domain<D>&, std::uint64_t);
PDS_INSTANTIATE(1)
PDS_INSTANTIATE(2)
PDS_INSTANTIATE(3)
PDS_INSTANTIATE(4)
PDS_INSTANTIATE(5)
PDS_INSTANTIATE(6)
PDS_INSTANTIATE(7)
PDS_INSTANTIATE(8)
#undef PDS_INSTANTIATE

}  // namespace pds
