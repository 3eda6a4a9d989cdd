// D. P. Mitchell, Generating antialiased images at low sampling densities,
// SIGGRAPH 1987, and Spectrally optimal sampling for distribution ray
// tracing, SIGGRAPH 1991 (the m*i candidates rule).
//
// Method: the first sample is uniform; sample i+1 is the candidate, among m*i
// uniform random ones, farthest from the i samples so far (on a torus the
// nearest periodic image counts). Every prefix of the output is well spread.
//
// Taken literally that is m*i nearest-sample queries a sample, O(m N^2): 5e10
// queries for N = 10^5, m = 10. While m*i < 256 we do exactly that. From
// there on the m*i candidates are replaced by a Poisson process of mean m*i
// (intensity lambda = m*i / volume), and the winner is exactly the farthest
// point of that process, found without drawing most of it:
//  * A background grid of the samples gives exact nearest-sample distances
//    (rebuilt with about one sample a cell whenever the count doubles).
//  * The domain is cut into leaf cells (rebuilt for twice the samples so far
//    whenever the count doubles). Each leaf is split into live boxes, dyadic
//    sub-boxes that may hold points farther than a threshold theta (with an
//    upper bound on that distance), and an idle rest with an upper bound F,
//    kept in a max tree. Branch and bound over sub-boxes against the samples
//    near the leaf makes this split ("tightening"); it runs for a leaf when
//    a new sample may cut its live boxes, or when theta falls below its F.
//  * A round draws, for each box size, ONE Poisson count of mean lambda x box
//    volume x (entries in that size's list), each candidate in a uniformly
//    chosen entry. Entries of boxes that died since (their leaf was tightened
//    again) are skipped: thinning a Poisson count by a fixed probability per
//    point leaves each live box exactly Poisson(lambda x its volume), all of
//    them independent. A round thus costs about the candidates that fall in
//    the live boxes, not the number of gaps.
//  * If the best candidate of the live boxes exceeds every idle bound F, it
//    is the winner: no idle point is that far from the samples. Otherwise
//    (rare) every leaf with F above the best so far draws its own Poisson
//    count over the whole leaf (from a hash of seed, round and leaf) and
//    drops the candidates inside its live boxes, which were already drawn.
// Exactness: the live boxes and the idle parts are disjoint and cover the
// domain, and they are fixed before the round's random numbers are drawn,
// so the candidates are a Poisson process of intensity lambda on the whole
// domain (independent counts on disjoint regions, uniform positions), and
// every candidate that is not evaluated provably cannot beat the best (it
// lies where the upper bound is below the best, or no farther from a
// sample than the best). Thresholds, margins and leaf sizes only change
// the speed. The one departure from Mitchell is the Poisson candidate
// count (relative spread 1/sqrt(m*i) <= 6%); a test compares the output
// with the literal method statistically.
//
// Guarantees: samples in [lo, hi); same seed, same points; the reported
// distances are exact. No minimum distance is promised unless a radius is
// given. Measured relative radius ~0.75 (m = 10), docs/best-candidate.md.
//
// Complexity and limits: per round, about a hundred live-box candidates (most
// rejected by a stored nearby sample without a query) and some twenty leaf
// tightenings in 2D (more in 3D), both growing slowly with i; in all about
// N^1.2 (docs/benchmarks.md: 10^5 in 2D in 5.0 s, 10^6 in 130 s). Memory: the
// leaves (4 a sample in 1D and 2D, 16 in 3D, for up to twice the samples) of
// about 12 bytes plus their 4-byte bound tree, the live boxes (about one a
// sample, 48 bytes) and the nearest-sample grid: 17 times the output at 10^6
// in 2D (docs/reliability.md).

#include "pds/samplers/best_candidate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "pds/detail/format.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"
#include "pds/grid.h"
#include "pds/grid_neighbourhood.h"
#include "pds/limits.h"
#include "pds/portable_math.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"
#include "pds/samplers/sizing.h"
#include "block_vector.h"

namespace pds {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Leaf cells per sample, for twice the samples placed when the leaves are
// rebuilt. Measured (CPU time, m = 10, torus): 2D hardly cares between 4 and
// 16; 3D runs 1.4x faster with 16 than with 4 (smaller leaves, fewer samples
// and sub-boxes in each branch and bound).
template <int D>
constexpr double kLeavesPerSample = D <= 2 ? 4.0 : 16.0;  // 1D: 2 took a third more time, 16 twice the memory

// From 4 dimensions the method is taken literally, m*i uniform candidates for
// every sample: the leaves would number 2^D and more a sample, and their
// dyadic sub-boxes 2^(D level). Each candidate costs one pruned grid walk
// (distance2_if_above), so a set costs about m N^2 / 2 walks.
template <int D>
constexpr bool kLiteral = D >= 4;

// The literal method's candidate budget: m N^2 / 2 walks at 0.1 (4D) to 1.2
// (8D) microseconds each here, so about 1-10 minutes at the budget (10^4
// points at m = 10); beyond it a request is refused rather than left running
// for hours.
constexpr double kLiteralMaxCandidates = 5e8;

// A round's threshold theta follows the best distance from below: it is
// kThresholdShare below a running mean of best x sqrt(i) (weight
// kTypicalWeight), scaled to round i, and never rises between two
// rebuilds of the leaves. Leaves are tightened against theta x (1 - margin), with margin
// kTightenMargin x (1000 / i)^(1/3) (at least kMarginMin), so that they stay
// valid while theta drifts down; the live boxes are split until their
// expected candidates a round fall to kSplitBelow x (1000 / i)^(2/3) (at
// least kSplitMin). The shrinking factors follow the gaps near the top,
// which get fewer relative to i (about i^(2/3) above the best) and smaller.
// Measured on the 2D torus with m = 10; none of these affects the output
// distribution, only the speed.
constexpr double kThresholdShare = 0.01, kTypicalWeight = 0.05;
constexpr double kTightenMargin = 0.03, kMarginMin = 0.002;
constexpr double kSplitBelow = 1.0 / 32, kSplitMin = 1.0 / 4096;

// The domain cut into leaf cells (about kLeavesPerSample per sample, rebuilt
// as the count grows), each split into two disjoint parts:
//  * live boxes: dyadic sub-boxes of the leaf that may hold points farther
//    than the threshold they were made against, each with an upper bound on
//    the distance from its points to the nearest sample. They sit in one list
//    per size, so that one Poisson count per list covers all of them.
//  * the idle rest of the leaf, with an upper bound F in a max tree.
// A leaf is re-made ("tightened") by branch and bound over its sub-boxes
// against the samples near it; its old boxes are then marked dead and stay in
// the lists until compaction.
template <int D>
class GapBoxes {
 public:
  struct Box {
    Point<D> lo;
    Point<D> witness;    // a sample near the box: a candidate no farther from it than the best cannot win
    double bound;        // no point of the box is farther than this from every sample
    std::uint32_t leaf;  // kDead once the leaf is tightened again
    int level;           // edges are the leaf's times 2^-level
  };
  static constexpr int kMaxLevel = D == 2 ? 7 : 5;
  static constexpr std::uint32_t kDead = UINT32_MAX;

  GapBoxes(const Domain<D>& domain, double target_leaves) : domain_(domain) {
    const double edge = std::pow(domain.volume() / target_leaves, 1.0 / D);
    leaves_ = 1;
    std::size_t tiles = 1;
    for (int i = 0; i < D; ++i) {
      cells_[i] = static_cast<int>(std::clamp(std::round(domain.extent(i) / edge), 1.0, 1e9));
      edge_[i] = domain.extent(i) / cells_[i];
      leaves_ *= static_cast<std::size_t>(cells_[i]);
      tiles_[i] = (cells_[i] + kTile - 1) / kTile;
      tile_stride_[i] = tiles;
      tiles *= static_cast<std::size_t>(tiles_[i]);
      if (leaves_ > kMaxGridCells || tiles * kTileSlots > 2 * kMaxGridCells)
        throw InvalidArgument("best-candidate: the request needs more than " + std::to_string(kMaxGridCells) +
                              " leaf cells");
    }
    hood_ = GridNeighbourhood<D>(domain, cells_);
    volume_ = 1.0;
    half_diagonal_ = 0.0;
    for (int i = 0; i < D; ++i) {
      volume_ *= edge_[i];
      half_diagonal_ += 0.25 * edge_[i] * edge_[i];
    }
    half_diagonal_ = std::sqrt(half_diagonal_) * (1.0 + 1e-9);
    // Bounds are stored as floats in units of a power of two near the leaf's
    // half diagonal: exact to scale, and far from float's limits at any scale
    // of domain.
    unit_ = std::ldexp(1.0, std::ilogb(half_diagonal_));
    inv_unit_ = 1.0 / unit_;
    const std::size_t slots = tiles * kTileSlots;
    size_ = 1;
    while (size_ < slots) size_ *= 2;
    tree_.assign(2 * size_, -kInf);
    first_.assign(slots, 0);
    count_.assign(slots, 0);
    live_max_.assign(slots, -kInf);
    dirty_.assign(slots, 0);
  }

  /// Sets every leaf's idle bound (no live boxes yet): the smallest
  /// farthest-corner distance to the samples near it. `nearest2(p)` is the
  /// squared distance from p to the nearest sample; `gather(p, r, out)` puts
  /// the samples within r of p in out.
  template <class Nearest2, class Gather>
  void start(const Nearest2& nearest2, const Gather& gather) {
    PointSet<D> near;
    for (std::size_t j = 0; j < count_.size(); ++j) {
      const auto c = coords(j);
      bool real = true;
      for (int i = 0; i < D; ++i) real &= c[i] < cells_[i];
      if (!real) continue;
      // Via the sample nearest the centre no point of the leaf is farther
      // than `loose`; the samples near the leaf give a tighter bound.
      const Point<D> middle = centre(j), lo = leaf_lo(j);
      const double loose = std::sqrt(nearest2(middle)) * (1.0 + 1e-12) + half_diagonal_;
      gather(middle, loose + half_diagonal_, near);
      double bound2 = loose * loose;
      for (const auto& q : near) {
        double far2 = 0.0;
        for (int i = 0; i < D; ++i) {
          const double far = farthest(q[i], lo[i], c[i] + 1 == cells_[i] ? domain_.hi[i] : lo[i] + edge_[i], i);
          far2 += far * far;
        }
        bound2 = std::min(bound2, far2);
      }
      tree_[size_ + j] = stored(std::sqrt(bound2) * (1.0 + 1e-12));
    }
    for (std::size_t n = size_ - 1; n >= 1; --n) tree_[n] = std::max(tree_[2 * n], tree_[2 * n + 1]);
  }

  std::size_t leaves() const { return leaves_; }
  double leaf_volume() const { return volume_; }
  double idle_bound(std::size_t leaf) const { return bound(tree_[size_ + leaf]); }
  double max_idle_bound() const { return bound(tree_[1]); }
  /// No point of the domain is farther than this from every sample.
  double reach() const { return std::max(max_idle_bound(), live_max_all_); }

  Point<D> leaf_lo(std::size_t leaf) const {
    const auto c = coords(leaf);
    Point<D> p;
    for (int i = 0; i < D; ++i) p[i] = domain_.lo[i] + static_cast<double>(c[i]) * edge_[i];
    return p;
  }
  Point<D> centre(std::size_t leaf) const {
    Point<D> p = leaf_lo(leaf);
    for (int i = 0; i < D; ++i) p[i] += 0.5 * edge_[i];
    return p;
  }

  /// A uniform point of the box at `lo` with edges edge * scale.
  Point<D> uniform_in(const Point<D>& lo, double scale, Rng& rng) const {
    Point<D> c;
    for (int k = 0; k < D; ++k)
      c[k] = std::min(lo[k] + rng.uniform() * edge_[k] * scale, std::nextafter(domain_.hi[k], domain_.lo[k]));
    return c;
  }

  /// A new sample: lowers the idle bounds of the leaves near it to their
  /// farthest-corner distance and marks the leaves whose live boxes it may
  /// cut (dirty, to be tightened again before the next draw).
  void add_sample(const Point<D>& p) {
    const double reach = this->reach();
    std::array<int, D> first, last;
    for (int i = 0; i < D; ++i) {
      const double x = (p[i] - domain_.lo[i]) / edge_[i] - 0.5;  // in units of leaves, from the first centre
      const double r = reach / edge_[i] + 0.5;                   // leaf centres within reach + half an edge
      double a = std::ceil(x - r), b = std::floor(x + r);
      if (!std::isfinite(reach)) {
        a = 0;
        b = cells_[i] - 1;
      }
      // Clamped only to stay in int range: the window is then the whole axis
      // (torus) or clipped to it (box) as before.
      first[i] = static_cast<int>(std::max(a, -2.0 * cells_[i]));
      last[i] = static_cast<int>(std::min(b, 3.0 * cells_[i]));
    }
    hood_.for_each_cell(hood_.window(first, last), [&](std::size_t, const std::array<int, D>& cell) {
      double far2 = 0.0, near2 = 0.0;  // squared distance from p to the leaf's farthest and nearest points
      for (int i = 0; i < D; ++i) {
        const int c = cell[i];
        const double a = domain_.lo[i] + c * edge_[i];
        const double b = c + 1 == cells_[i] ? domain_.hi[i] : a + edge_[i];
        const double far = farthest(p[i], a, b, i), near = nearest(p[i], a, b, i);
        far2 += far * far;
        near2 += near * near;
      }
      const std::size_t leaf = id(cell);
      const double bound = std::sqrt(far2) * (1.0 + 1e-12);
      if (bound < idle_bound(leaf)) set(leaf, bound);
      if (count_[leaf] > 0 && !dirty_[leaf] && std::sqrt(near2) < this->bound(live_max_[leaf])) {
        dirty_[leaf] = 1;
        dirty_list_.push_back(leaf);
      }
      return true;
    });
  }

  /// Leaves marked by add_sample() since the last call (read once).
  std::vector<std::size_t> take_dirty() {
    std::vector<std::size_t> out;
    out.swap(dirty_list_);
    return out;
  }

  /// Re-makes the leaf against threshold theta: branch and bound over its
  /// dyadic sub-boxes against `near` (the samples within near_radius(leaf) of
  /// its centre; any subset keeps the bounds valid, this one makes them
  /// tight). A box whose upper bound is <= theta joins the idle part; a box
  /// that may hold points above theta is split while it may also hold points
  /// below it, its volume exceeds split_above and the level is below
  /// kMaxLevel; else it becomes a live box. Old live boxes die.
  void tighten(std::size_t leaf, const PointSet<D>& near, double theta, double split_above) {
    dirty_[leaf] = 0;
    const double total = near_radius(leaf) - half_diagonal_;
    live_boxes_ -= count_[leaf];
    for (std::uint32_t k = first_[leaf]; k < first_[leaf] + count_[leaf]; ++k) arena_[k].leaf = kDead;
    count_[leaf] = 0;
    live_max_[leaf] = -kInf;
    if (!(total > theta) || near.empty()) {
      set(leaf, total);
      return;
    }
    // The samples as seen from the leaf: on a torus each moved to its image
    // nearest the leaf's centre. Distances to one image are upper bounds of
    // the torus distance, so the upper bounds below stay valid; the lower
    // bounds (only used to decide whether to split) may be loose.
    const Point<D> middle = centre(leaf);
    local_.resize(near.size());
    for (std::size_t k = 0; k < near.size(); ++k)
      for (int i = 0; i < D; ++i) local_[k][i] = middle[i] + domain_.delta(middle[i], near[k][i], i);
    first_[leaf] = static_cast<std::uint32_t>(arena_.size());
    // Bounds are compared with theta in squares: sqrt(d2) (1 +- 1e-12) <=
    // theta holds when d2 < theta^2 (1 - 1e-9) and fails when d2 > theta^2
    // (1 + 1e-9); only in between (rarely) is the root taken to decide. So
    // every decision is the root's, and only live boxes need their root.
    // (Where theta's square is not a normal number, always the root.)
    const double theta2 = theta * theta;
    const bool squares = std::isnormal(theta2);
    const double surely_below = theta2 * (1.0 - 1e-9), surely_above = theta2 * (1.0 + 1e-9);
    const auto at_most_theta = [&](double d2, double factor) {
      if (squares && d2 < surely_below) return true;
      if (squares && d2 > surely_above) return false;
      return std::sqrt(d2) * factor <= theta;
    };
    double idle2 = -1.0;  // the largest squared upper bound of an idle box
    stack_.clear();
    stack_.push_back({leaf_lo(leaf), 0});
    while (!stack_.empty()) {
      const auto [lo, level] = stack_.back();
      stack_.pop_back();
      const double scale = 1.0 / static_cast<double>(1 << level);
      Point<D> centre;
      for (int i = 0; i < D; ++i) centre[i] = lo[i] + 0.5 * edge_[i] * scale;
      Point<D> hi;
      for (int i = 0; i < D; ++i) hi[i] = std::min(lo[i] + edge_[i] * scale, domain_.hi[i]);
      // The upper bound first: most boxes end idle on it alone.
      double upper2 = kInf;
      for (const auto& q : local_) {
        double far2 = 0.0;
        for (int i = 0; i < D; ++i) {
          const double far = std::max(std::abs(q[i] - lo[i]), std::abs(q[i] - hi[i]));
          far2 += far * far;
        }
        upper2 = std::min(upper2, far2);
      }
      if (at_most_theta(upper2, 1.0 + 1e-12)) {
        idle2 = std::max(idle2, upper2);
        continue;
      }
      double lower2 = kInf;
      for (const auto& q : local_) {
        double near2 = 0.0;
        for (int i = 0; i < D; ++i) {
          const double close = q[i] < lo[i] ? lo[i] - q[i] : q[i] > hi[i] ? q[i] - hi[i] : 0.0;
          near2 += close * close;
        }
        lower2 = std::min(lower2, near2);
      }
      if (at_most_theta(lower2, 1.0 - 1e-12) && level < kMaxLevel && volume_ * scale_volume(level) > split_above) {
        for (int child = 0; child < (1 << D); ++child) {
          Point<D> c = lo;
          for (int i = 0; i < D; ++i)
            if (child >> i & 1) c[i] += 0.5 * edge_[i] * scale;
          stack_.push_back({c, level + 1});
        }
        continue;
      }
      const double upper = std::sqrt(upper2) * (1.0 + 1e-12);
      double centre2 = kInf;
      std::size_t witness = 0;
      for (std::size_t k = 0; k < local_.size(); ++k) {
        double d2 = 0.0;
        for (int i = 0; i < D; ++i) d2 += (local_[k][i] - centre[i]) * (local_[k][i] - centre[i]);
        if (d2 < centre2) {
          centre2 = d2;
          witness = k;
        }
      }
      arena_.push_back({lo, near[witness], upper, static_cast<std::uint32_t>(leaf), level});
      lists_[level].push_back(static_cast<std::uint32_t>(arena_.size() - 1));
      ++count_[leaf];
      live_max_[leaf] = std::max(live_max_[leaf], stored(upper));
      live_max_all_ = std::max(live_max_all_, upper);
    }
    live_boxes_ += count_[leaf];
    // The largest idle bound: the root of the largest square, as the root
    // and the factor are monotone.
    set(leaf, idle2 < 0.0 ? -kInf : std::sqrt(idle2) * (1.0 + 1e-12));
  }

  /// Every sample within this distance of the leaf's centre must be passed
  /// to tighten(): the nearest sample of any point of the leaf is among them.
  double near_radius(std::size_t leaf) const {
    return bound(std::max(tree_[size_ + leaf], live_max_[leaf])) + half_diagonal_;
  }

  bool is_dirty(std::size_t leaf) const { return dirty_[leaf]; }

  /// The live boxes of one size: arena indices (dead ones included; see live()).
  const std::vector<std::uint32_t>& list(int level) const { return lists_[level]; }
  const Box& box(std::uint32_t index) const { return arena_[index]; }
  static bool live(const Box& b) { return b.leaf != kDead; }
  static double scale_volume(int level) { return std::ldexp(1.0, -D * level); }

  /// True if p (a point of the leaf) lies in one of the leaf's live boxes.
  bool in_live_box(std::size_t leaf, const Point<D>& p) const {
    for (std::uint32_t k = first_[leaf]; k < first_[leaf] + count_[leaf]; ++k) {
      const Box& b = arena_[k];
      const double scale = std::ldexp(1.0, -b.level);
      bool inside = true;
      for (int i = 0; i < D; ++i) inside &= p[i] >= b.lo[i] && p[i] < b.lo[i] + edge_[i] * scale;
      if (inside) return true;
    }
    return false;
  }

  /// Drops the dead boxes once they outnumber the live ones; a leaf's live
  /// boxes stay contiguous and every list keeps its order. (When this runs
  /// depends only on the state, so the output stays a function of the seed.)
  /// In place: a second arena beside the first was the run's peak.
  void compact() {
    if (arena_.size() < 4096 || arena_.size() < 2 * live_boxes_) return;
    std::vector<std::uint32_t> where(arena_.size(), UINT32_MAX);
    live_max_all_ = -kInf;
    std::uint32_t kept = 0;
    for (std::uint32_t k = 0; k < arena_.size(); ++k) {
      const Box& b = arena_[k];
      if (!live(b)) continue;
      if (k == first_[b.leaf]) first_[b.leaf] = kept;
      where[k] = kept;
      live_max_all_ = std::max(live_max_all_, b.bound);
      arena_[kept++] = b;  // kept <= k: no live box is overwritten before it is read
    }
    arena_.truncate(kept);
    for (auto& list : lists_) {
      std::size_t out = 0;
      for (const std::uint32_t k : list)
        if (where[k] != UINT32_MAX) list[out++] = where[k];
      list.resize(out);
    }
  }

  /// Calls visit(leaf) for leaves whose idle bound exceeds `t` (which visit
  /// may raise), largest first (depth first, larger child first).
  template <class F>
  void visit_idle_above(const double& t, F&& visit) {
    walk_.clear();
    walk_.push_back(1);
    while (!walk_.empty()) {
      const std::size_t node = walk_.back();
      walk_.pop_back();
      if (!(bound(tree_[node]) > t)) continue;
      if (node >= size_) {
        visit(node - size_);
        continue;
      }
      const std::size_t a = 2 * node, b = a + 1;
      if (tree_[a] >= tree_[b]) {
        walk_.push_back(b);
        walk_.push_back(a);
      } else {
        walk_.push_back(a);
        walk_.push_back(b);
      }
    }
  }

 private:
  // Expected candidates a round below which a box that straddles the
  // threshold is not split further: few candidates are wasted on it.

  // A bound as stored: the smallest float at least value / unit_ (a power of
  // two, so the quotient is exact), read back exactly by bound(). Half the
  // bytes of a double, and still an upper bound.
  float stored(double value) const {
    const double x = value * inv_unit_;
    // (Bounds stay within some 10^9 units; a larger one would not convert.)
    if (x > std::numeric_limits<float>::max()) return std::numeric_limits<float>::infinity();
    const float f = static_cast<float>(x);
    return f < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
  }
  double bound(float value) const { return static_cast<double>(value) * unit_; }

  void set(std::size_t leaf, double value) {
    std::size_t node = size_ + leaf;
    tree_[node] = stored(value);
    for (node /= 2; node >= 1; node /= 2) {
      const float v = std::max(tree_[2 * node], tree_[2 * node + 1]);
      if (v == tree_[node]) break;
      tree_[node] = v;
    }
  }

  // Leaf ids go tile by tile (kTile^D leaves a tile, row-major inside), so
  // that a subtree of the max tree is a compact block of space. Slots of
  // partial tiles beyond the domain hold -inf and are never visited.
  std::size_t id(const std::array<int, D>& c) const {
    std::size_t tile = 0, inner = 0, scale = 1;
    for (int i = 0; i < D; ++i) {
      tile += static_cast<std::size_t>(c[i] / kTile) * tile_stride_[i];
      inner += static_cast<std::size_t>(c[i] % kTile) * scale;
      scale *= kTile;
    }
    return tile * kTileSlots + inner;
  }

  std::array<int, D> coords(std::size_t id) const {
    const std::size_t tile = id / kTileSlots;
    std::size_t inner = id % kTileSlots;
    std::array<int, D> c;
    for (int i = 0; i < D; ++i) {
      c[i] = static_cast<int>(tile / tile_stride_[i] % static_cast<std::size_t>(tiles_[i])) * kTile +
             static_cast<int>(inner % kTile);
      inner /= kTile;
    }
    return c;
  }

  // The largest distance along one axis from x to a point of [a, b] (on a
  // torus, to the nearest image: at most half the period).
  double farthest(double x, double a, double b, int axis) const {
    if (!domain_.periodic) return std::max(std::abs(x - a), std::abs(b - x));
    const double L = domain_.extent(axis);
    double antipode = x + 0.5 * L;
    if (antipode >= domain_.hi[axis]) antipode -= L;
    if (antipode >= a && antipode <= b) return 0.5 * L;
    return std::max(std::abs(domain_.delta(x, a, axis)), std::abs(domain_.delta(x, b, axis)));
  }

  // The smallest distance along one axis from x to a point of [a, b] (x and
  // the interval inside the domain; on a torus an outside point's nearest
  // point of the interval is an end).
  double nearest(double x, double a, double b, int axis) const {
    if (x >= a && x <= b) return 0.0;
    if (!domain_.periodic) return x < a ? a - x : x - b;
    return std::min(std::abs(domain_.delta(x, a, axis)), std::abs(domain_.delta(x, b, axis)));
  }

  struct Pending {
    Point<D> lo;
    int level;
  };

  Domain<D> domain_;
  std::array<int, D> cells_{};
  std::array<double, D> edge_{};
  GridNeighbourhood<D> hood_;  // the leaves' windows (leaf ids are tiled, see id())
  std::array<int, D> tiles_{};
  std::array<std::size_t, D> tile_stride_{};
  std::size_t leaves_ = 0, size_ = 0;
  double volume_ = 0.0, half_diagonal_ = 0.0;
  // kTile^D = kTileSlots leaves a tile in 1 to 3 dimensions (a 1D tile of
  // 4 left 60 of its 64 slots empty: 12 KB a sample).
  static constexpr int kTile = D == 1 ? 64 : D == 2 ? 8 : 4;
  static constexpr std::size_t kTileSlots = 64;
  static_assert(D >= 4 || kTileSlots == std::size_t(kTile) * (D >= 2 ? kTile : 1) * (D >= 3 ? kTile : 1));
  double unit_ = 1.0, inv_unit_ = 1.0;  // of the stored bounds
  std::vector<float> tree_;  // idle bounds (leaves at size_ + leaf), max tree
  std::vector<std::uint32_t> first_, count_;
  std::vector<float> live_max_;  // the largest bound of each leaf's live boxes
  std::vector<char> dirty_;
  std::vector<std::size_t> dirty_list_, walk_;
  // In blocks that never move: a doubling vector held the old and the new
  // buffer together, the run's peak (and compact() works in place).
  detail::BlockVector<Box, 12> arena_;
  std::array<std::vector<std::uint32_t>, kMaxLevel + 1> lists_;
  std::size_t live_boxes_ = 0;
  double live_max_all_ = -kInf;
  std::vector<Pending> stack_;
  PointSet<D> local_;
};

// Exact distances to the nearest sample, on a grid of about one sample a cell
// that is rebuilt whenever the sample count doubles.
template <int D>
class NearestSample {
 public:
  explicit NearestSample(const Domain<D>& domain) : domain_(domain), grid_(domain, max_extent(domain)) {
    for (int i = 0; i < D; ++i) diameter_ += domain.extent(i) * domain.extent(i);
    diameter_ = std::sqrt(diameter_) * 1.01;
  }

  void add(const Point<D>& p, const PointSet<D>& all) {
    if (all.size() >= 2 * built_) {
      built_ = all.size();
      spacing_ = std::pow(domain_.volume() / static_cast<double>(built_), 1.0 / D);
      grid_ = Grid<D>(domain_, spacing_);
      for (const auto& q : all) grid_.insert(q);
    } else {
      grid_.insert(p);
    }
  }

  /// The samples within r of p (at least all of them; on a torus as stored).
  void gather(const Point<D>& p, double r, PointSet<D>& out) const {
    out.clear();
    grid_.for_each_within(p, std::min(r, diameter_), [&](std::int32_t index, double) {
      out.push_back(grid_.points()[static_cast<std::size_t>(index)]);
      return true;
    });
  }

  /// The squared distance from p to the nearest sample (searching ever wider).
  double nearest2(const Point<D>& p) const {
    for (double r = spacing_;; r *= 2.0) {
      double d2 = kInf;
      grid_.for_each_within(p, std::min(r, diameter_), [&](std::int32_t, double e2) {
        d2 = std::min(d2, e2);
        return true;
      });
      if (d2 <= r * r || r >= diameter_) return d2;
    }
  }

  /// The squared distance from p to the nearest sample if it exceeds beat2,
  /// else a value <= beat2. `bound` is an upper bound on that distance.
  double distance2_if_above(const Point<D>& p, double beat2, double bound) const {
    if constexpr (D >= 4) {
      // Without a useful bound (every candidate of the literal method), ask
      // first whether a sample lies within the distance to beat: the pruned,
      // nearest-first walk of that ball usually stops in the first cells,
      // where a search from the whole diameter would scan the grid.
      if (bound == kInf) {
        if (beat2 >= 0.0) {
          auto farther = [&](std::int32_t, double d2) { return d2 > beat2; };
          // p's own cell first: it settles some candidates without the walk's set-up (10% faster in 8D).
          if (!grid_.for_each_in_own_cell(p, farther) || !grid_.for_each_within(p, std::sqrt(beat2), farther))
            return beat2;
        }
        return nearest2(p);
      }
    }
    for (double r = std::min(bound, diameter_);; r = diameter_) {
      double nearest2 = kInf;
      const bool whole = grid_.for_each_within(p, r, [&](std::int32_t, double d2) {
        nearest2 = std::min(nearest2, d2);
        return d2 > beat2;
      });
      if (!whole || nearest2 < kInf || r >= diameter_) return nearest2;
    }
  }

 private:
  static double max_extent(const Domain<D>& domain) {
    double e = 0.0;
    for (int i = 0; i < D; ++i) e = std::max(e, domain.extent(i));
    return e;
  }

  Domain<D> domain_;
  Grid<D> grid_;
  std::size_t built_ = 0;
  double diameter_ = 0.0, spacing_ = 0.0;
};

template <int D>
void validate(const BestCandidateParams& params, const Domain<D>& domain) {
  domain.validate();
  if (params.m < 1) throw InvalidArgument("best-candidate: m must be at least 1, got " + std::to_string(params.m));
  if (!params.count && !params.radius) throw InvalidArgument("best-candidate needs a count or a radius");
  if (params.count && *params.count == 0) throw InvalidArgument("best-candidate: count must be at least 1, got 0");
  if (params.radius) {
    require_radius(*params.radius);
    if (params.count) require_count_fits("best-candidate", *params.count, *params.radius, domain);
  }
}

}  // namespace

template <int D>
BestCandidateResult<D> best_candidate_run(const BestCandidateParams& params, const Domain<D>& domain,
                                          std::uint64_t seed) {
  validate(params, domain);
  // The leaves, up to kLeavesPerSample for each of the final samples (a
  // radius alone leaves about typical_count): refuse at once what
  // would exceed the cell budget later.
  const double expected = params.count ? static_cast<double>(*params.count)
                                       : typical_count(sizing_volume(domain, *params.radius), *params.radius, D);
  if (!kLiteral<D> && static_cast<double>(kMaxGridCells) < expected * kLeavesPerSample<D>)
    throw InvalidArgument("best-candidate: the request needs more than " + std::to_string(kMaxGridCells) +
                          " leaf cells (" + detail::format_number(expected) + " samples)");
  if (kLiteral<D> && 0.5 * params.m * expected * expected > kLiteralMaxCandidates)
    throw InvalidArgument(
        "best-candidate: in " + std::to_string(D) + " dimensions every sample is the best of m*i " +
        "uniform candidates, about m N^2 / 2 = " + detail::format_number(0.5 * params.m * expected * expected) +
        " candidates for " + detail::format_number(expected) + " samples, more than the " +
        detail::format_number(kLiteralMaxCandidates) + " allowed (hours of work); ask for fewer samples or a " +
        "smaller m, or use bridson");
  NearestSample<D> nearest(domain);
  std::optional<GapBoxes<D>> boxes;
  std::uint64_t rebuild_at = 0;
  const std::uint64_t wanted = params.count.value_or(UINT64_MAX);
  const double radius = params.radius.value_or(0.0);
  // typical: a running mean of best x sqrt(i), which varies slowly (the
  // best itself shrinks like 1/sqrt(i) and jitters by a few per cent).
  double typical = -1.0, theta = kInf;

  BestCandidateResult<D> result;
  if (params.count) {
    // Exactly the count: growing by doubling held the old and the new block
    // together.
    result.points.reserve(static_cast<std::size_t>(*params.count));
    result.distance.reserve(static_cast<std::size_t>(*params.count));
  }
  ProgressReporter progress(params.progress, expected);
  PointSet<D> near;
  auto place = [&](const Point<D>& p, double distance) {
    result.points.push_back(p);
    result.distance.push_back(distance);
    nearest.add(p, result.points);
    if constexpr (!kLiteral<D>) {
      if (boxes) {
        boxes->add_sample(p);
        boxes->compact();
      }
    }
  };
  {
    Rng rng(seed, {0});
    place(uniform_point(rng, domain), kInf);
  }
  while (result.points.size() < wanted) {
    const std::uint64_t i = result.points.size();
    // The literal method's rounds cost m*i each: its work grows as i^2.
    progress.update(kLiteral<D> ? static_cast<double>(i) * static_cast<double>(i) / expected : static_cast<double>(i));
    const std::uint64_t candidates = static_cast<std::uint64_t>(params.m) * i;
    double best2 = -1.0, best = -1.0;
    Point<D> winner{};
    auto consider = [&](const Point<D>& c, double bound) {
      const double d2 = nearest.distance2_if_above(c, best2, bound);
      if (d2 > best2) {
        best2 = d2;
        best = std::sqrt(d2);
        winner = c;
      }
    };
    if (kLiteral<D> || candidates < kBestCandidateExactBelow) {
      Rng rng(seed, {i});
      for (std::uint64_t t = 0; t < candidates; ++t) consider(uniform_point(rng, domain), kInf);
    } else if constexpr (!kLiteral<D>) {
      if (!boxes || i >= rebuild_at) {
        // Leaves for twice the samples so far (at most the count): their size
        // follows the density.
        double target = 2.0 * static_cast<double>(i);
        rebuild_at = 2 * i;
        if (params.count && target >= static_cast<double>(*params.count)) {
          target = static_cast<double>(*params.count);
          rebuild_at = UINT64_MAX;
        }
        boxes.emplace(domain, target * kLeavesPerSample<D>);
        theta = kInf;
        boxes->start([&](const Point<D>& p) { return nearest.nearest2(p); },
                     [&](const Point<D>& p, double r, PointSet<D>& out) { nearest.gather(p, r, out); });
      }
      const double lambda = static_cast<double>(candidates) / domain.volume();  // candidates per unit volume
      theta = std::min(theta, (1.0 - kThresholdShare) * typical / std::sqrt(static_cast<double>(i)));
      // Every leaf whose idle part may reach above theta is tightened (against
      // a slightly lower threshold), as are the leaves whose live boxes the
      // last sample cut; then no idle point is farther than theta.
      const double shrink = std::cbrt(1000.0 / static_cast<double>(i));
      const double margin = std::clamp(kTightenMargin * shrink, kMarginMin, kTightenMargin);
      const double split_above = std::max(kSplitBelow * shrink * shrink, kSplitMin) / lambda;
      auto tighten = [&](std::size_t leaf) {
        nearest.gather(boxes->centre(leaf), boxes->near_radius(leaf), near);
        boxes->tighten(leaf, near, theta * (1.0 - margin), split_above);
      };
      for (const std::size_t leaf : boxes->take_dirty())
        if (boxes->is_dirty(leaf)) tighten(leaf);
      boxes->visit_idle_above(theta, tighten);

      for (std::uint64_t attempt = 0; best2 < 0.0; ++attempt) {
        // No candidate at all has probability e^-(m*i) < e^-256; bounded anyway.
        if (attempt == 16) throw Failure("best-candidate: no candidate was drawn in 16 rounds");
        // The live boxes: one Poisson count per size, each candidate in a
        // uniformly chosen entry of that size's list. Entries of dead boxes
        // are skipped: that thins each live box's count to exactly
        // Poisson(lambda x its volume), independent of the other boxes.
        Rng rng(seed, {i, attempt + 1});
        for (int level = 0; level <= GapBoxes<D>::kMaxLevel; ++level) {
          const auto& list = boxes->list(level);
          if (list.empty()) continue;
          const double scale = std::ldexp(1.0, -level);
          const double mean =
              lambda * boxes->leaf_volume() * GapBoxes<D>::scale_volume(level) * static_cast<double>(list.size());
          const std::uint64_t n = poisson(mean, rng);
          for (std::uint64_t t = 0; t < n; ++t) {
            const auto& box = boxes->box(list[rng.below(list.size())]);
            if (!boxes->live(box)) continue;
            const Point<D> c = boxes->uniform_in(box.lo, scale, rng);
            if (domain.distance2(c, box.witness) <= best2) continue;
            consider(c, box.bound);
          }
        }
        if (best > boxes->max_idle_bound()) break;
        // Rarely the best of the live boxes is not above every idle bound:
        // then the idle parts may hold the winner. Each leaf whose idle bound exceeds the
        // best so far draws its own Poisson count (from a hash of round and
        // leaf) over the whole leaf and drops the candidates inside its live
        // boxes, which were drawn above.
        const std::uint64_t round_key = mix64(mix64(seed ^ 0x6265737463616e64ULL) + mix64(i) + attempt);
        const double leaf_mean = lambda * boxes->leaf_volume();
        const double p0 = exp_neg(leaf_mean);
        boxes->visit_idle_above(best, [&](std::size_t leaf) {
          // Most leaves draw no candidate: decide that from one hash.
          const std::uint64_t key = mix64(round_key ^ mix64(leaf + 0x632be59bd9b4e019ULL));
          const double u = uniform_from_bits(key);
          if (u < p0) return;
          const std::uint64_t n = poisson_above_zero(u, leaf_mean, p0);
          Rng leaf_rng(key);
          const Point<D> lo = boxes->leaf_lo(leaf);
          for (std::uint64_t t = 0; t < n; ++t) {
            const Point<D> c = boxes->uniform_in(lo, 1.0, leaf_rng);
            if (!boxes->in_live_box(leaf, c)) consider(c, boxes->idle_bound(leaf));
          }
        });
      }
    }
    const double scaled = best * std::sqrt(static_cast<double>(i));
    typical = typical < 0.0 ? scaled : typical + kTypicalWeight * (scaled - typical);
    if (best < radius) {
      if (!params.count) break;
      throw InvalidArgument("best-candidate: placed only " + std::to_string(i) + " of the " + std::to_string(wanted) +
                            " points requested at radius " + detail::format_number(radius) +
                            " before the best candidate fell closer than the radius; ask for fewer points or a "
                            "smaller radius");
    }
    place(winner, best);
  }
  progress.finish();
  return result;
}

#define PDS_INSTANTIATE(D) \
  template BestCandidateResult<D> best_candidate_run<D>(const BestCandidateParams&, const Domain<D>&, std::uint64_t);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
