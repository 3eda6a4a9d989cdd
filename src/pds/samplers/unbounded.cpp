// The unbounded, chunk-invariant Poisson disk field (docs/unbounded.md).
//
// Maximal random sequential adsorption in continuous time. Level 0 is
// ebeida's first level without a domain (docs/ebeida.md, "darts in time
// order"): every cell of edge r/sqrt(D) owns a Poisson process of darts
// (rate one per cell, until time T = darts_per_cell), and a dart is kept iff
// no kept dart within r is earlier in the total order (time, cell, position).
// Then, as ebeida refines: at level k >= 1 (time [T_k-1, T_k), T_k = T_k-1 +
// kSubDarts 2^kD) each sub-cell of edge 2^-k that is the child of an open
// sub-cell of level k - 1 and that no disk of a sample kept before T_k-1
// covers wholly is open, and owns a Poisson stream of darts of rate 2^-kD
// (one per cell's area, kSubDarts per sub-cell and level). A covered
// sub-cell's darts would all be rejected, so leaving them out changes no
// decision: the union of the streams is the space-time Poisson process with
// the never-kept darts removed, and in time order this is sequential dart
// throwing with uniform darts run to saturation. When no sub-cell of a cell
// is open, every point of it is within r of a sample: maximal.
//
// Why a region can be computed alone, exactly: a dart's fate is a function of
// the earlier darts within r and their fates, and a sub-cell's openness a
// function of the darts kept before its level starts within r of its parent;
// each step of that recursion goes to strictly earlier darts or to a lower
// level, and finitely many darts and sub-cells lie below a time within any
// bounded distance, so it ends. What it visits is determined by the seed and
// the dart, not by the region that asked. sample() therefore decides the
// darts of the region's cells in any order, and those outside that they
// depend on lazily (memoised for the call: an array of cells around the
// region, a hash map beyond), each cell's tree of open sub-cells grown only
// where a question reaches. No truncation, no margin guessed:
// UnboundedStats::margin_cells reports the reach.
//
// Why it ends: a gap (a connected part of the plane not within r of a
// sample) has positive area; each level throws darts at it with the same
// rate per area, and the first one in it is kept. Once no gap is left, every
// point is inside some disk (points on three circles at once have
// probability zero), so by compactness sub-cells small enough are each inside
// one disk: a finite number of levels, measured 10 to 20 at 10^5 samples.
// kMaxUnboundedLevel (60, sub-cells far below the rounding of coordinates)
// bounds it with a Failure, as kMaxUnboundedDepth bounds the recursion.
//
// Reach and depth: the earlier darts within r are tried earliest first, and
// the first kept one rejects the dart; cells inside the region are swept in
// time windows of 1/2 at level 0 and then level by level, and a cell whose
// darts are all decided up to a time answers from its list of kept darts.
//
// On a torus the cells' coordinates wrap modulo the cells per axis (at least
// 5, so the 5^D block of neighbours holds distinct cells) and distances wrap.
//
// Determinism: dart j of sub-cell s of cell c at level k has its bits from
// mix64 of (seed, c, k, s, j) and its waiting time from the portable
// logarithm (pds/portable_math.h).

#include "pds/samplers/unbounded.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "block_vector.h"
#include "mapped_pages.h"
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

constexpr std::uint8_t kUndecided = 0, kKept = 1, kRejected = 2;

template <int D>
struct Dart {
  Point<D> p;
  double t;
  std::uint8_t status = kUndecided;  // kUndecided, kKept or kRejected
};

/// A sub-cell of a cell at refinement level k: its index along each axis, in
/// [0, 2^k).
template <int D>
using Sub = std::array<std::uint64_t, D>;

constexpr std::uint8_t kNotExpanded = 0, kExpanding = 1, kExpanded = 2;

/// An open sub-cell (level >= 1), or the cell itself (level 0, the root): a
/// node of the cell's quadtree (octree), grown lazily where it is needed.
template <int D>
struct Node {
  Sub<D> sub{};
  std::uint32_t first_dart = 0, darts = 0;      // its darts, in time order: Settler::darts_[first_dart, + darts)
  std::uint32_t first_child = 0, children = 0;  // its open children: Settler::nodes_[first_child, + children)
  std::uint8_t level = 0;
  std::uint8_t expanded = kNotExpanded;  // kNotExpanded, kExpanding or kExpanded
};

constexpr std::uint32_t kRoot = UINT32_MAX;
constexpr std::int8_t kClosed = INT8_MAX;  // CellState::done: no sub-cell open, no dart will ever come

template <int D>
struct CellState {
  Node<D> root;                     // the cell at level 0, its darts the level-0 darts
  std::vector<std::uint32_t> kept;  // the darts decided kept after the first (CellSummary::kept)
  std::uint32_t nodes = 0;          // open sub-cells found so far
  std::uint32_t swept = 0;          // level-0 darts [0, swept) decided by the sweep
  std::int8_t done = -1;            // the darts of levels 0..done are all decided (their nodes all exist)
};

/// The darts and sub-cells of one call, which the recursion holds references
/// into while it adds more (one block of them instead of a list a cell),
/// indexed by 32-bit numbers.
template <class T>
class Arena {
 public:
  std::uint32_t size() const { return static_cast<std::uint32_t>(store_.size()); }
  T& operator[](std::uint32_t i) { return store_[i]; }
  const T& operator[](std::uint32_t i) const { return store_[i]; }
  void push_back(const T& v) {
    if (store_.size() == UINT32_MAX) throw Failure("unbounded: more than 2^32 darts or sub-cells in one region");
    store_.push_back(v);
  }

 private:
  detail::BlockVector<T, 11> store_;
};

/// What the common questions read of a cell, in a small record of its own
/// (an array of them per region, next to the CellStates): whether a cell's
/// darts before a time are all decided, and then its kept darts. On the
/// plane a cell (edge r/sqrt(D), diagonal r) holds at most one kept dart, so
/// the first is stored here; any more (a torus's cells are up to 1.25 times
/// wider) are read from CellState::kept.
template <int D>
struct CellSummary {
  double decided_until = 0.0;  // every dart of the cell before this time is decided
  Dart<D> kept;                // the first kept dart, when kept_count > 0
  std::uint32_t kept_count = 0;
  bool generated = false;
};

/// A cell's summary and state, where the memo keeps them.
template <int D>
struct CellRef {
  CellSummary<D>* summary;
  CellState<D>* state;
};

// Cells within this many cells of the region live in an array (the reach
// measured outside the region is 9 to 15 cells in 2D, 18 in 3D); farther
// ones in a hash map.
constexpr std::int64_t kDenseMargin = 12;


// Expected darts of an open sub-cell at each refinement level (as ebeida's
// kLevelTime; only the work depends on it, never the law of the samples).
constexpr double kSubDarts = 0.5;
// Open children of one sub-cell: at most 2^D. Open sub-cells of one cell in
// all: a few in practice (a gap is smaller than a disk); far more means the
// coverage test cannot close a gap.
constexpr std::size_t kMaxNodesPerCell = std::size_t{1} << 16;

/// The total order of darts: time, then cell, then position (a tie in time
/// has probability zero; position breaks it the same way in every region).
template <int D>
bool earlier(const Dart<D>& a, const Cell<D>& ca, const Dart<D>& b, const Cell<D>& cb) {
  if (a.t != b.t) return a.t < b.t;
  if (ca != cb) return ca < cb;
  return static_cast<const std::array<double, D>&>(a.p) < static_cast<const std::array<double, D>&>(b.p);
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
    // Level k > 0 runs for kSubDarts * 2^(kD) of time: the rate per area
    // stays one dart per cell per unit time (a sub-cell of level k is 2^-kD of
    // a cell), and each open sub-cell expects kSubDarts darts.
    level_end_[0] = end_time_;
    for (int k = 0; k <= kMaxUnboundedLevel; ++k) scale_[static_cast<std::size_t>(k)] = std::ldexp(1.0, -k);
    for (int k = 1; k <= kMaxUnboundedLevel; ++k) level_end_[k] = level_end_[k - 1] + std::ldexp(kSubDarts, k * D);
    std::size_t size = 1;
    for (int a = 0; a < D; ++a) {
      dense_lo_[a] = lo[a] - kDenseMargin;
      dense_n_[a] = hi[a] - lo[a] + 1 + 2 * kDenseMargin;
      size *= static_cast<std::size_t>(dense_n_[a]);
    }
    // Huge pages where offered (mapped_pages.h): both arrays are written
    // through at once, and their 4 KiB page faults were a tenth of a 2D run.
    dense_ = detail::vector_in_huge_pages<CellState<D>>(size);
    dense_summary_ = detail::vector_in_huge_pages<CellSummary<D>>(size);
    std::int64_t stride = 1;
    for (int a = 0; a < D; ++a) {
      dense_stride_[a] = stride;
      stride *= dense_n_[a];
    }
    for (const Cell<D>& o : offsets_) {
      std::int64_t step = 0;
      for (int a = 0; a < D; ++a) step += o[a] * dense_stride_[a];
      offset_steps_.push_back(step);
    }
  }

  /// The cell's own coordinates: on a torus, wrapped into [0, period).
  Cell<D> canonical(Cell<D> c) const {
    if (torus_)
      for (int a = 0; a < D; ++a) c[a] = ((c[a] % period_[a]) + period_[a]) % period_[a];
    return c;
  }

  /// The summary and state of a cell given by its own (canonical)
  /// coordinates; its darts are drawn on first use.
  CellRef<D> cell(const Cell<D>& c) {
    std::size_t index = 0;
    bool inside = true;
    for (int a = D - 1; a >= 0; --a) {
      const std::int64_t i = c[a] - dense_lo_[a];
      inside = inside && i >= 0 && i < dense_n_[a];
      index = index * static_cast<std::size_t>(dense_n_[a]) + static_cast<std::size_t>(i);
    }
    if (inside) return dense_cell(index, c);
    SparseCell& sparse = sparse_[c];
    return generated({&sparse.summary, &sparse.state}, c);
  }

 private:
  CellRef<D> dense_cell(std::size_t index, const Cell<D>& c) {
    return generated({&dense_summary_[index], &dense_[index]}, c);
  }

  /// The cell, its darts drawn if this is its first use.
  CellRef<D> generated(CellRef<D> ref, const Cell<D>& c) {
    if (!ref.summary->generated) {
      generate(c, *ref.state);
      ref.summary->generated = true;
      ref.summary->decided_until = decided_until(*ref.state);
      ++cells_touched_;
      for (int a = 0; a < D; ++a) reach_lo_[a] = std::min(reach_lo_[a], c[a]), reach_hi_[a] = std::max(reach_hi_[a], c[a]);
    }
    return ref;
  }

 public:
  /// Decides every level-0 dart of cell c before time t.
  void settle_until(Cell<D> c, double t) {
    c = canonical(c);
    const CellRef<D> ref = cell(c);
    CellState<D>& s = *ref.state;
    while (s.swept < s.root.darts && darts_[s.root.first_dart + s.swept].t < t) {
      decide(c, ref, s.root.first_dart + s.swept);
      ++s.swept;
      ref.summary->decided_until = decided_until(s);
    }
    if (s.swept == s.root.darts && s.done < 0) s.done = 0;
    ref.summary->decided_until = decided_until(s);
  }

  /// Refinement level k of cell c (canonical): expands its nodes of level
  /// k - 1 and decides the darts of those of level k. Returns whether c has
  /// an open sub-cell at level k (darts may still come).
  bool settle_level(const Cell<D>& c, int k) {
    const CellRef<D> ref = cell(c);
    CellState<D>& s = *ref.state;
    bool open = false;
    // Expands the nodes of level k - 1 on the way down to those of level k.
    visit(c, s, kRoot, k + 1, [&](std::uint32_t n) {
      const Node<D>& node = node_of(s, n);
      if (node.level != k) return;
      open = true;
      for (std::uint32_t i = 0; i < node.darts; ++i) decide(c, ref, node.first_dart + i);
    });
    s.done = open ? static_cast<std::int8_t>(k) : kClosed;
    ref.summary->decided_until = decided_until(s);
    return open;
  }

  std::size_t cells_touched() const { return cells_touched_; }
  /// The bounding box of the cells touched.
  const Cell<D>& reach_lo() const { return reach_lo_; }
  const Cell<D>& reach_hi() const { return reach_hi_; }
  std::size_t darts_settled() const { return darts_settled_; }
  int max_depth() const { return max_depth_; }
  int max_level() const { return max_level_; }

 private:
  std::uint64_t cell_key(const Cell<D>& c) const {
    std::uint64_t h = key_;
    for (int a = 0; a < D; ++a) h = mix64(h ^ mix64(static_cast<std::uint64_t>(c[a]) + 0x632be59bd9b4e019ULL));
    return h;
  }

  void generate(const Cell<D>& c, CellState<D>& s) {
    s.root.first_dart = darts_.size();
    stream(cell_key(c), c, 0, Sub<D>{}, 0.0, end_time_);
    s.root.darts = darts_.size() - s.root.first_dart;
  }

  Node<D>& node_of(CellState<D>& s, std::uint32_t i) { return i == kRoot ? s.root : nodes_[i]; }

  /// The darts of one Poisson stream in [start, end): those of sub-cell `sub`
  /// of cell c at level k (level 0: the cell), rate 2^-kD per unit time (one
  /// per cell's area), positions uniform in the sub-cell; bits from h.
  /// Appended to darts_.
  void stream(std::uint64_t h, const Cell<D>& c, int k, const Sub<D>& sub, double start, double end) {
    const double scale = std::ldexp(1.0, -k), wait = std::ldexp(1.0, k * D);
    double t = start;
    for (std::uint32_t j = 0;; ++j) {
      const std::uint64_t base = mix64(h + 0x9e3779b97f4a7c15ULL * (std::uint64_t{j} + 1));
      const auto part = [base](int i) { return mix64(base ^ (0xd1b54a32d192ed03ULL * static_cast<std::uint64_t>(i + 1))); };
      t += neg_log(uniform_open_from_bits(part(0))) * wait;
      if (!(t < end)) break;
      Dart<D> d;
      d.t = t;
      for (int a = 0; a < D; ++a)
        d.p[a] = origin(a) + (static_cast<double>(c[a]) +
                              (static_cast<double>(sub[a]) + uniform_from_bits(part(a + 1))) * scale) *
                                 edges_[a];
      if (torus_)  // rounding must not put a dart on the torus's upper bound
        for (int a = 0; a < D; ++a)
          if (!(d.p[a] < torus_->hi[a])) d.p[a] = std::nextafter(torus_->hi[a], torus_->lo[a]);
      darts_.push_back(d);
    }
  }

  /// The level a dart of time t belongs to.
  int level_of(double t) const {
    int k = 0;
    while (!(t < level_end_[static_cast<std::size_t>(k)])) ++k;
    return k;
  }

  /// One coordinate of the lower corner of sub-cell index i at level k of
  /// cell index c along axis a (i = 2^k: the upper corner).
  double corner(int a, std::int64_t c, std::uint64_t i, int k) const {
    return origin(a) + (static_cast<double>(c) + static_cast<double>(i) * scale_[static_cast<std::size_t>(k)]) * edges_[a];
  }

  /// A node's box as centre and half-edges, widened by 2^-10 of a cell edge:
  /// a dart's position may round past its sub-cell by up to 2^-12 of a cell
  /// at 2^40 cells from the origin. Only used to choose what to look at.
  struct Box {
    std::array<double, D> mid, half;
  };
  Box box(const Cell<D>& c, const Sub<D>& sub, int k) const {
    Box b;
    for (int a = 0; a < D; ++a) {
      const double lo = corner(a, c[a], sub[a], k), hi = corner(a, c[a], sub[a] + 1, k);
      b.half[a] = 0.5 * (hi - lo) + 0x1.0p-10 * edges_[a];
      b.mid[a] = lo + 0.5 * (hi - lo);
    }
    return b;
  }
  double delta(double a, double b, int axis) const { return torus_ ? torus_->delta(a, b, axis) : b - a; }
  /// Whether a point (half = 0) or box lies within r of box b (conservatively).
  bool near(const Box& b, const std::array<double, D>& mid, const std::array<double, D>* half) const {
    double g2 = 0.0;
    for (int a = 0; a < D; ++a) {
      const double g = std::abs(delta(b.mid[a], mid[a], a)) - b.half[a] - (half ? (*half)[a] : 0.0);
      if (g > 0.0) g2 += g * g;
    }
    return g2 <= r2_ * (1.0 + 1e-9);
  }

  /// Calls f(n) for node n of cell c and, recursively, for its open
  /// descendants up to level `below` - 1 that lie within r of `near_box`
  /// (all when null), expanding those of levels below `below` - 1 on the way
  /// (nodes of level below - 1 are given to f unexpanded).
  template <typename F>
  void visit(const Cell<D>& c, CellState<D>& s, std::uint32_t n, int below, F&& f, const Box* near_box = nullptr) {
    f(n);
    const int level = node_of(s, n).level;
    if (level + 1 >= below) return;
    expand(c, s, n);
    const std::uint32_t first = node_of(s, n).first_child, count = node_of(s, n).children;
    for (std::uint32_t i = first; i < first + count; ++i) {
      if (near_box) {
        const Box b = box(c, nodes_[i].sub, level + 1);
        if (!near(*near_box, b.mid, &b.half)) continue;
      }
      visit(c, s, i, below, f, near_box);
    }
  }

  /// The cells (canonical) whose points can be within r of box b of cell c:
  /// calls f(m, its CellRef), nearest first.
  template <typename F>
  void for_each_neighbour(const Cell<D>& c, const Box& b, F&& f) {
    // The squared gap from b to the cells of each offset along each axis,
    // unwrapped (the same frame as b, widened as box() widens): offsets
    // -2..2 of the 5^D block.
    std::array<std::array<double, 5>, D> gap2;
    // The block lies in the dense memo (and, on the plane, needs no wrap):
    // its cells are at fixed steps from c's.
    bool dense = torus_ == nullptr;
    std::size_t index = 0;
    for (int a = D - 1; a >= 0; --a) {
      for (int o = -2; o <= 2; ++o) {
        const double mid = origin(a) + (static_cast<double>(c[a] + o) + 0.5) * edges_[a];
        const double g = std::abs(mid - b.mid[a]) - (0.5 + 0x1.0p-10) * edges_[a] - b.half[a];
        gap2[a][o + 2] = g > 0.0 ? g * g : 0.0;
      }
      const std::int64_t i = c[a] - dense_lo_[a];
      dense = dense && i >= 2 && i + 2 < dense_n_[a];
      index = index * static_cast<std::size_t>(dense_n_[a]) + static_cast<std::size_t>(i);
    }
    for (std::size_t n = 0; n < offsets_.size(); ++n) {
      const Cell<D>& o = offsets_[n];
      double g2 = 0.0;  // summed in axis order, as the per-cell formula (adding 0 is exact)
      for (int a = 0; a < D; ++a) g2 += gap2[a][o[a] + 2];
      if (g2 > r2_ * (1.0 + 1e-9)) continue;
      Cell<D> m;
      for (int a = 0; a < D; ++a) m[a] = c[a] + o[a];
      if (dense) {
        f(m, dense_cell(index + static_cast<std::size_t>(offset_steps_[n]), m));
      } else {
        m = canonical(m);
        f(m, cell(m));
      }
    }
  }

  /// Every dart of the cell before this time is decided (kept up to date in
  /// CellSummary::decided_until, which the questions read).
  double decided_until(const CellState<D>& s) const {
    if (s.done == kClosed) return INFINITY;
    if (s.done >= 0) return level_end_[static_cast<std::size_t>(s.done)];
    return s.swept < s.root.darts ? darts_[s.root.first_dart + s.swept].t : 0.0;
  }

  /// Finds the open children of node n of cell c (level k - 1 -> k): a child
  /// stays open unless one disk of a sample kept before the level's start
  /// holds all its corners (the disk is convex, so then it holds the child);
  /// each open child gets its own Poisson stream of darts over the level's
  /// time. A covered sub-cell would only get darts that are rejected, so
  /// leaving it out changes no decision: the darts are still the space-time
  /// Poisson process, restricted to where a dart can be kept.
  void expand(const Cell<D>& c, CellState<D>& s, std::uint32_t n) {
    if (node_of(s, n).expanded == kExpanded) return;
    if (node_of(s, n).expanded == kExpanding) throw Failure("unbounded: internal error, a sub-cell depends on itself");
    const int k = node_of(s, n).level + 1;
    if (k > kMaxUnboundedLevel)
      throw Failure("unbounded: a gap is still open after " + std::to_string(kMaxUnboundedLevel) +
                    " levels of refinement (numerical breakdown; report this with the seed and radius)");
    if (++depth_ > kMaxUnboundedDepth)
      throw Failure("unbounded: a chain of dependent darts is deeper than " + std::to_string(kMaxUnboundedDepth) +
                    " (report this with the seed and radius)");
    max_depth_ = std::max(max_depth_, depth_);
    max_level_ = std::max(max_level_, k);
    node_of(s, n).expanded = kExpanding;
    const Sub<D> parent = node_of(s, n).sub;
    const double start = level_end_[static_cast<std::size_t>(k - 1)];
    const Box pb = box(c, parent, k - 1);
    // The samples kept before `start` within r of the parent: the darts of
    // the nodes of levels below k near it, decided.
    // Buffers reused by every call at this recursion depth (depth_ counts this call).
    Scratch& scratch = scratch_at(depth_);
    std::vector<Point<D>>& kept = scratch.kept;
    kept.clear();
    for_each_neighbour(c, pb, [&](const Cell<D>& m, const CellRef<D>& mref) {
      const CellSummary<D>& sum = *mref.summary;
      if (sum.decided_until >= start) {  // the usual case inside a region: its kept dart
        for_each_kept(mref, [&](const Dart<D>& q) {
          if (q.t < start && near(pb, q.p, nullptr)) kept.push_back(q.p);
          return true;
        });
        return;
      }
      CellState<D>& ms = *mref.state;
      visit(m, ms, kRoot, k, [&](std::uint32_t i) {
        const std::uint32_t first = node_of(ms, i).first_dart, count = node_of(ms, i).darts;
        for (std::uint32_t j = first; j < first + count; ++j) {
          if (!(darts_[j].t < start) || !near(pb, darts_[j].p, nullptr)) continue;
          if (decide(m, mref, j)) kept.push_back(darts_[j].p);
        }
      }, &pb);
    });
    std::array<Sub<D>, (1 << D)> open;
    std::array<std::uint32_t, (1 << D)> counts;
    std::size_t opened = 0;
    // The open children's darts go to darts_ one child after the other
    // (nothing else is added meanwhile: stream() does not recurse).
    const std::uint32_t first_dart = darts_.size();
    const std::uint64_t level_key = mix64(cell_key(c) ^ mix64(0x6c6576656cULL + static_cast<std::uint64_t>(k)));
    for (int child = 0; child < (1 << D); ++child) {
      Sub<D> sub;
      std::array<double, D> lo, hi;
      for (int a = 0; a < D; ++a) {
        sub[a] = 2 * parent[a] + static_cast<std::uint64_t>((child >> a) & 1);
        lo[a] = corner(a, c[a], sub[a], k);
        hi[a] = corner(a, c[a], sub[a] + 1, k);
      }
      bool covered = false;
      for (const Point<D>& q : kept) {
        double far2 = 0.0;
        for (int a = 0; a < D; ++a) {
          const double dl = delta(q[a], lo[a], a), dh = delta(q[a], hi[a], a);
          far2 += std::max(dl * dl, dh * dh);
        }
        if (far2 < r2_) {
          covered = true;
          break;
        }
      }
      if (covered) continue;
      open[opened] = sub;
      std::uint64_t h = level_key;
      for (int a = 0; a < D; ++a) h = mix64(h ^ mix64(sub[a] + 0x8f1bbcdcbfa53e0bULL * static_cast<std::uint64_t>(a + 1)));
      const std::uint32_t before = darts_.size();
      stream(h, c, k, sub, start, level_end_[static_cast<std::size_t>(k)]);
      counts[opened++] = darts_.size() - before;
    }
    if (s.nodes + opened > kMaxNodesPerCell)
      throw Failure("unbounded: more than " + std::to_string(kMaxNodesPerCell) +
                    " sub-cells of one cell open (numerical breakdown; report this with the seed and radius)");
    Node<D>& node = node_of(s, n);
    node.first_child = nodes_.size();
    node.children = static_cast<std::uint32_t>(opened);
    node.expanded = kExpanded;
    s.nodes += static_cast<std::uint32_t>(opened);
    std::uint32_t first = first_dart;
    for (std::size_t i = 0; i < opened; ++i) {
      Node<D> child;
      child.sub = open[i];
      child.level = static_cast<std::uint8_t>(k);
      child.first_dart = first;
      child.darts = counts[i];
      first += counts[i];
      nodes_.push_back(child);
    }
    --depth_;
  }

  /// Whether dart j of cell c is kept: iff no kept dart within r is earlier.
  /// The earlier darts within r are tried earliest first: the first kept one
  /// settles it, and an early dart has few darts before it to depend on, so
  /// the recursion stays near the dart (the causal cone of dart throwing,
  /// explored lazily; docs/unbounded.md measures its reach).
  bool decide(const Cell<D>& c, const CellRef<D>& ref, std::uint32_t j) {
    CellState<D>& s = *ref.state;
    if (darts_[j].status != kUndecided) return darts_[j].status == kKept;
    if (++depth_ > kMaxUnboundedDepth)
      throw Failure("unbounded: a chain of dependent darts is deeper than " + std::to_string(kMaxUnboundedDepth) +
                    " (report this with the seed and radius)");
    max_depth_ = std::max(max_depth_, depth_);
    ++darts_settled_;
    const Dart<D> d = darts_[j];
    const int level = d.t < end_time_ ? 0 : level_of(d.t);
    std::vector<Candidate>& candidates = scratch_at(depth_).candidates;
    candidates.clear();
    bool rejected = false;
    Box point;
    point.mid = d.p;
    point.half.fill(0.0);
    for_each_neighbour(c, point, [&](const Cell<D>& m, const CellRef<D>& mref) {
      if (rejected) return;
      if (mref.summary->decided_until > d.t) {  // all of m's darts before d are decided: only its kept ones matter
        for_each_kept(mref, [&](const Dart<D>& q) {
          if (!earlier<D>(q, m, d, c)) return true;
          double dist2 = 0.0;
          for (int a = 0; a < D; ++a) {
            const double e = delta(d.p[a], q.p[a], a);
            dist2 += e * e;
          }
          rejected = dist2 < r2_;
          return !rejected;
        });
        return;
      }
      CellState<D>& ms = *mref.state;
      // The nodes of m up to d's level near d; expanding them may decide
      // earlier darts (of lower levels), never d.
      visit(m, ms, kRoot, level + 1, [&](std::uint32_t i) {
        if (rejected) return;
        const std::uint32_t first = node_of(ms, i).first_dart, count = node_of(ms, i).darts;
        for (std::uint32_t k = first; k < first + count && darts_[k].t <= d.t; ++k) {
          if (darts_[k].status == kRejected || !earlier<D>(darts_[k], m, d, c)) continue;
          double dist2 = 0.0;
          for (int a = 0; a < D; ++a) {
            const double e = delta(d.p[a], darts_[k].p[a], a);
            dist2 += e * e;
          }
          if (!(dist2 < r2_)) continue;
          if (darts_[k].status == kKept) {  // already known: rejected at once
            rejected = true;
            return;
          }
          candidates.push_back({darts_[k], m, mref, k});
        }
      }, &point);
    });
    bool kept = !rejected;
    if (kept) {
      std::sort(candidates.begin(), candidates.end(),
                [](const Candidate& a, const Candidate& b) { return earlier<D>(a.dart, a.cell, b.dart, b.cell); });
      for (const Candidate& q : candidates)
        if (decide(q.cell, q.ref, q.j)) {
          kept = false;
          break;
        }
    }
    darts_[j].status = kept ? kKept : kRejected;
    if (kept) {
      if (ref.summary->kept_count++ == 0)
        ref.summary->kept = darts_[j];
      else
        s.kept.push_back(j);
    }
    --depth_;
    return kept;
  }

  double origin(int a) const { return torus_ ? torus_->lo[a] : 0.0; }

 public:
  /// Calls f(dart) for each kept dart of a cell, in the order they were
  /// decided, while f returns true.
  template <typename F>
  void for_each_kept(const CellRef<D>& ref, F&& f) {
    const CellSummary<D>& sum = *ref.summary;
    if (sum.kept_count == 0) return;
    if (!f(sum.kept)) return;
    for (const std::uint32_t k : ref.state->kept)
      if (!f(darts_[k])) return;
  }

 private:
  struct Candidate {
    Dart<D> dart;
    Cell<D> cell;
    CellRef<D> ref;
    std::uint32_t j;
  };
  /// Buffers of one recursion depth, kept for the call's whole run: a call
  /// only uses its own depth's, and finishes with them before returning.
  struct Scratch {
    std::vector<Point<D>> kept;
    std::vector<Candidate> candidates;
  };
  Scratch& scratch_at(int depth) {
    if (scratch_.size() <= static_cast<std::size_t>(depth)) scratch_.resize(static_cast<std::size_t>(depth) + 1);
    return scratch_[static_cast<std::size_t>(depth)];
  }

  double r2_, end_time_;
  std::array<double, D> edges_;
  const Domain<D>* torus_;
  Cell<D> period_;
  std::uint64_t key_;
  std::vector<Cell<D>> offsets_;
  Cell<D> dense_lo_{}, dense_n_{}, dense_stride_{};
  std::vector<std::int64_t> offset_steps_;  // offsets_ as steps in the dense memo
  std::vector<CellState<D>> dense_;
  std::vector<CellSummary<D>> dense_summary_;
  struct SparseCell {
    CellSummary<D> summary;
    CellState<D> state;
  };
  std::unordered_map<Cell<D>, SparseCell, CellHash<D>> sparse_;
  std::size_t cells_touched_ = 0;
  Cell<D> reach_lo_ = filled_cell<D>(INT64_MAX), reach_hi_ = filled_cell<D>(INT64_MIN);
  std::size_t darts_settled_ = 0;
  int depth_ = 0, max_depth_ = 0, max_level_ = 0;
  std::array<double, kMaxUnboundedLevel + 1> level_end_{}, scale_{};
  std::deque<Scratch> scratch_;  // a deque: growing it moves no buffer in use
  Arena<Dart<D>> darts_;         // every cell's darts: a node's contiguous, in time order
  Arena<Node<D>> nodes_;         // the open sub-cells: the children of one node contiguous
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
                            detail::format_number(edges_[a]) + "; it needs 5 to 2^40 (sample a small torus with ebeida, not the unbounded field)");
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
                       // The memo's bytes a sample over D doubles, with margin (measured: 1.4 KB
                       // in 2D over one 400 r region; 6.6 KB in 3D before the refinement levels).
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
  // Sweep level 0 in windows of time so that chains inside the region stay
  // short; then the refinement levels, one at a time, until no cell of the
  // region has an open sub-cell (then none of them gets a dart ever again).
  for (double w = kWindow;; w += kWindow) {
    const bool last = !(w < params_.darts_per_cell);
    const double until = last ? INFINITY : w;
    for_each_cell([&](const Cell<D>& c) { settler.settle_until(c, until); });
    if (last) break;
  }
  std::vector<Cell<D>> open;
  for_each_cell([&](const Cell<D>& c) { open.push_back(settler.canonical(c)); });
  for (int k = 1; !open.empty(); ++k) {
    std::size_t kept = 0;
    for (const Cell<D>& c : open)
      if (settler.settle_level(c, k)) open[kept++] = c;
    open.resize(kept);
  }

  PointSet<D> points;
  for_each_cell([&](const Cell<D>& c) {
    settler.for_each_kept(settler.cell(c), [&](const Dart<D>& d) {
      if (region.contains(d.p)) points.push_back(d.p);
      return true;
    });
  });
  std::sort(points.begin(), points.end(), [](const Point<D>& a, const Point<D>& b) {
    return static_cast<const std::array<double, D>&>(a) < static_cast<const std::array<double, D>&>(b);
  });

  if (stats) {
    stats->cells_touched = settler.cells_touched();
    stats->darts_settled = settler.darts_settled();
    stats->max_depth = settler.max_depth();
    stats->max_level = settler.max_level();
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
