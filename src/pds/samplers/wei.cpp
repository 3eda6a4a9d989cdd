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
#include "pds/grid_neighbourhood.h"
#include "pds/parallel.h"
#include "pds/portable_math.h"
#include "pds/rng.h"

namespace pds {
namespace {

constexpr int kMaxLevels = kWeiMaxLevels;
constexpr int kMaxWindows = kWeiMaxWindows;
constexpr double kProgressTotal = 1000.0;  // progress in thousandths of the run

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

template <int D>
class WeiSampler {
  using Offset = std::array<float, D>;

 public:
  WeiSampler(const WeiParams& params, const Domain<D>& domain, std::uint64_t seed)
      : params_(params),
        domain_(domain),
        seed_(seed),
        r2_(params.radius * params.radius),
        progress_(params.progress, kProgressTotal) {
    const double r = params.radius;
    double total = 1.0;
    for (int i = 0; i < D; ++i) {
      n_[i] = static_cast<int>(std::max(1.0, std::ceil(domain.extent(i) * std::sqrt(double(D)) / r)));
      edge_[i] = domain.extent(i) / n_[i];
      total *= n_[i];
      // Cells within `reach` of a dart's cell hold every sample closer than r.
      reach_[i] = static_cast<int>(std::floor(r / edge_[i])) + 1;
      period_[i] = reach_[i] + 1;
      // On a torus the last n mod period cells each get a group of their own
      // along this axis, so that no two cells of a group meet across the seam.
      const int full = domain.periodic ? n_[i] / period_[i] * period_[i] : n_[i];
      groups_[i] = domain.periodic ? period_[i] + (n_[i] - full) : std::min(period_[i], n_[i]);
      full_[i] = full;
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
    for (int i = 0; i < D; ++i) {
      members_[i].assign(static_cast<std::size_t>(groups_[i]), {});
      for (int c = 0; c < n_[i]; ++c) members_[i][static_cast<std::size_t>(group_coord(c, i))].push_back(c);
    }
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
  int group_coord(int c, int axis) const {
    return c < full_[axis] ? c % period_[axis] : period_[axis] + (c - full_[axis]);
  }

  std::array<int, D> coords(std::size_t cell) const {
    std::array<int, D> c;
    for (int i = 0; i < D; ++i) {
      c[i] = static_cast<int>(cell % static_cast<std::size_t>(n_[i]));
      cell /= static_cast<std::size_t>(n_[i]);
    }
    return c;
  }

  std::size_t group_of(std::size_t cell) const {
    const auto c = coords(cell);
    std::size_t g = 0, stride = 1;
    for (int i = 0; i < D; ++i) {
      g += static_cast<std::size_t>(group_coord(c[i], i)) * stride;
      stride *= static_cast<std::size_t>(groups_[i]);
    }
    return g;
  }

  std::size_t group_count() const {
    std::size_t g = 1;
    for (int i = 0; i < D; ++i) g *= static_cast<std::size_t>(groups_[i]);
    return g;
  }

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

  /// The phase groups of a window in a random order drawn from (seed, level,
  /// pass, window).
  std::vector<std::size_t> group_order(int level, int pass, int window) const {
    std::vector<std::size_t> order(group_count());
    std::iota(order.begin(), order.end(), std::size_t{0});
    Rng rng(seed_, {static_cast<std::uint64_t>(level), static_cast<std::uint64_t>(pass),
                    static_cast<std::uint64_t>(window), ~std::uint64_t{0}});
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
    return order;
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
    std::size_t total = 1;
    for (int i = 0; i < D; ++i) {
      total *= members_[i][g % static_cast<std::size_t>(groups_[i])].size();
      g /= static_cast<std::size_t>(groups_[i]);
    }
    return {0, total};
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
    std::array<const std::vector<int>*, D> lists;
    for (int i = 0; i < D; ++i) {
      lists[i] = &members_[i][g % static_cast<std::size_t>(groups_[i])];
      g /= static_cast<std::size_t>(groups_[i]);
    }
    // Position in the product of the lists, decoded once and then stepped
    // like an odometer (axis 0 fastest).
    std::array<std::size_t, D> at;
    std::size_t rest = begin;
    for (int i = 0; i < D; ++i) {
      at[i] = rest % lists[i]->size();
      rest /= lists[i]->size();
    }
    for (std::size_t u = begin; u != end; ++u) {
      std::size_t cell = 0;
      for (int i = 0; i < D; ++i) cell += static_cast<std::size_t>((*lists[i])[at[i]]) * stride_[i];
      for (int i = 0; i < D && ++at[i] == lists[i]->size(); ++i) at[i] = 0;
      if (std::isnan(grid_[cell][0])) f(cell, cell, 1);
    }
  }

  /// Draws the darts of every empty unit for one pass and sorts them by
  /// window, then phase group (a counting sort over fixed chunks of units, so
  /// that neither the result nor its order depends on the threads).
  void schedule(int level, int pass) {
    constexpr std::size_t kChunk = 4096;
    if (active_.size() > std::numeric_limits<std::uint32_t>::max())
      throw InvalidArgument("wei: more than 2^32 active fine cells; use fewer levels or a larger radius");
    const std::size_t groups = group_count(), windows = static_cast<std::size_t>(params_.windows);
    const std::uint64_t key =
        Rng(seed_, {static_cast<std::uint64_t>(level), static_cast<std::uint64_t>(pass), ~std::uint64_t{1}}).next();
    // counts[chunk_first[g] + c][w]: darts of window w in chunk c of group g;
    // turned into write positions below.
    std::vector<std::size_t> chunk_first(groups + 1, 0);
    for (std::size_t g = 0; g < groups; ++g) {
      const auto [begin, end] = unit_range(level, g);
      chunk_first[g + 1] = chunk_first[g] + (end - begin + kChunk - 1) / kChunk;
    }
    std::vector<std::size_t> counts(chunk_first[groups] * windows, 0);
    auto over_chunks = [&](auto&& per_dart) {
      for (std::size_t g = 0; g < groups; ++g) {
        // Plain variables: clang 14 cannot capture structured bindings.
        const auto range = unit_range(level, g);
        const std::size_t begin = range.first, end = range.second;
        parallel_for(0, chunk_first[g + 1] - chunk_first[g], 1, params_.threads, [&](std::size_t c, std::size_t) {
          std::size_t* row = &counts[(chunk_first[g] + c) * windows];
          const std::size_t first = begin + c * kChunk;
          for_each_unit(level, g, first, std::min(first + kChunk, end),
                        [&](std::size_t unit, std::size_t cell, std::size_t active) {
                          const Darts darts(key, cell, active, params_.windows);
                          for (int d = 0; d < darts.count(); ++d) per_dart(row, unit, darts.window(d));
                        });
        });
      }
    };
    over_chunks([](std::size_t* row, std::size_t, int w) { ++row[w]; });
    // Buckets in (window, group) order; within one, chunks in order.
    bucket_.assign(windows * groups + 1, 0);
    std::size_t at = 0;
    for (std::size_t w = 0; w < windows; ++w)
      for (std::size_t g = 0; g < groups; ++g) {
        bucket_[w * groups + g] = at;
        for (std::size_t c = chunk_first[g]; c < chunk_first[g + 1]; ++c) {
          const std::size_t n = counts[c * windows + w];
          counts[c * windows + w] = at;
          at += n;
        }
      }
    bucket_[windows * groups] = at;
    events_.resize(at);
    over_chunks(
        [&](std::size_t* row, std::size_t unit, int w) { events_[row[w]++] = static_cast<std::uint32_t>(unit); });
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

  /// k passes, each cut into W windows; in a window the phase groups run one
  /// after another in a random order, the cells of a group in parallel.
  void run_level(int level) {
    const std::size_t groups = group_count();
    for (int pass = 0; pass < params_.trials; ++pass) {
      schedule(level, pass);
      for (int w = 0; w < params_.windows; ++w) {
        for (const std::size_t g : group_order(level, pass, w))
          run_group(level, pass, w, static_cast<std::size_t>(w) * groups + g);
        report(level, pass * params_.windows + w + 1);
      }
    }
    // Freed before the next refine; `events_ = {}` would only clear it (it
    // picks the initializer-list assignment).
    std::vector<std::uint32_t>().swap(events_);
  }

  /// Progress after `windows` windows of `level`: level 0 (most of the
  /// darts) is the first 90%, each finer level an equal part of the rest.
  void report(int level, int windows) {
    const double in_level = static_cast<double>(windows) / (params_.trials * params_.windows);
    const double done =
        level == 0 ? 0.9 * in_level : 0.9 + 0.1 * (level - 1 + in_level) / std::max(1, params_.levels - 1);
    progress_.update(done * kProgressTotal);
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
    parallel_for(0, count, 256, params_.threads, [&](std::size_t range_begin, std::size_t range_end) {
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
    });
    // The new active cells, sorted by phase group (a counting sort, written in
    // place), in parent order within a group.
    group_begin_.assign(group_count() + 1, 0);
    for (std::size_t p = 0; p < count; ++p)
      if (masks[p])
        group_begin_[group_of(parent_at(p).parent) + 1] += static_cast<std::size_t>(std::popcount(masks[p]));
    for (std::size_t g = 0; g + 1 < group_begin_.size(); ++g) group_begin_[g + 1] += group_begin_[g];
    std::vector<std::size_t> fill(group_begin_.begin(), group_begin_.end() - 1);
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

  const WeiParams& params_;
  const Domain<D>& domain_;
  std::uint64_t seed_;
  double r2_;
  ProgressReporter progress_;
  std::array<int, D> n_, reach_, period_, groups_, full_;
  std::array<double, D> edge_;
  std::array<std::size_t, D> stride_;
  GridNeighbourhood<D> hood_;                             // the level-0 grid's windows
  std::array<std::vector<std::vector<int>>, D> members_;  // per axis: the coordinates of each group coordinate
  // The sample of each level-0 cell as a float offset from the cell's corner
  // (NaN if none): 8 bytes a cell in 2D instead of 16.
  std::vector<Offset> grid_;
  FineCells active_;                      // this level's cells, sorted by phase group
  std::vector<std::size_t> group_begin_;  // where each group's cells start in active_
  // The darts of the current pass, one entry per dart naming its unit (see
  // for_each_unit), sorted by window, then group; bucket_[w * groups + g] is
  // where window w's darts of group g start.
  std::vector<std::uint32_t> events_;
  std::vector<std::size_t> bucket_;
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
  return WeiSampler<D>(params, domain, seed).run();
}

#define PDS_INSTANTIATE(D) template PointSet<D> wei<D>(const WeiParams&, const Domain<D>&, std::uint64_t);
PDS_INSTANTIATE(1)
PDS_INSTANTIATE(2)
PDS_INSTANTIATE(3)
PDS_INSTANTIATE(4)
#undef PDS_INSTANTIATE

}  // namespace pds
