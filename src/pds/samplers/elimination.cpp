// C. Yuksel, Sample elimination for generating Poisson disk sample sets,
// Computer Graphics Forum 34(2) (Eurographics 2015), 25-32.
//
// Method: every candidate i gets the weight w_i = sum over the other
// candidates j within d_max of (1 - max(d_ij, d_min) / d_max)^alpha
// (section 3, with the weight limit of section 3.2). The paper removes the
// heaviest candidate and subtracts its term from each remaining neighbour,
// one at a time from a max-heap, until N remain. d_max = 2 r_max, r_max the
// radius of the densest packing of N balls in the domain's volume (hexagonal
// in 2D, FCC in 3D: analysis/relative_radius.h), so d_max is the largest
// minimum distance N samples could have. Progressive order (section 5): the
// N survivors are eliminated again to N/2 with d_max grown by 2^(1/D), the
// N/2 to N/4, and so on; each round's eliminated samples follow its
// survivors, the last eliminated first (the reverse elimination order is
// itself a ranking). The weight limit d_min stays the one of the first round,
// as in the paper's reference code (cyCodeBase, cySampleElim.h).
//
// What we change: the heap's top is anywhere, so each of its removals reads a
// fresh neighbourhood from memory. Most removals here run in sweeps in memory
// order instead, and remove exactly what the heap would, in an order that
// sorts back to the heap's (RoundEliminator explains why). That needs
// weights that do not depend on the order of the subtractions: they are sums
// of terms in fixed point, 2^-32 a unit, so the kept set can differ from one
// summed in floating point where two weights are within rounding of each
// other (docs/elimination.md, "Faithfulness").
//
// Neighbour search: the candidates are sorted by the cell of a uniform grid
// of edge about d_max / 2 (GridNeighbourhood's cell arithmetic), so the
// candidates within d_max of a point are the contiguous runs of the rows of
// one window (5 cells an axis), each cell once, wrapped across a torus's
// seam. On a torus distances are to the nearest periodic image
// (Domain::distance2), so every candidate counts once even when d_max exceeds
// half a period. Removed candidates leave the index after each sweep. Ties
// between equal weights go to the smaller position in the sorted order, so
// the result is deterministic.
//
// Guarantees: exactly N samples, each a candidate (so inside the domain);
// same seed, same points. No minimum distance: nothing bounds the closest
// pair (docs/elimination.md gives the measured relative radius).
//
// Complexity: O(M k) for the weights (each pair once) and about 2 (M - N)
// neighbourhood scans of k candidates for the elimination, with M candidates
// and k ~ 18 (2D) or ~30 (3D) neighbours within d_max for M = 5N, plus a sweep
// over the live candidates per band (about 10 bands) and the heap's O(log M)
// for the last few percent; progressive order adds the same on N, N/2, ...
// samples. Memory: the candidates, sorted in place when elimination() drew
// them (eliminate() copies its caller's), an 8-byte weight and a 4-byte
// original index each, the grid's cell starts (at most 4 cells a candidate, 1
// in the first round from 2D), 8 bytes a candidate while the heap runs, and
// in the progressive rounds a 4-byte rank and a 16-byte record a removal.

#include "pds/samplers/elimination.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <sstream>
#include <string>
#include <utility>

#include "elimination_detail.h"
#include "mapped_pages.h"
#include "pds/analysis/relative_radius.h"
#include "pds/detail/format.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"
#include "pds/grid.h"
#include "pds/grid_neighbourhood.h"
#include "pds/limits.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

constexpr std::size_t kMaxCandidates = std::size_t{1} << 31;
// Elimination's typical relative radius from 5N candidates (2D 0.69, 3D
// 0.68; docs/elimination.md): a radius field sizes the count by it.
constexpr double kTypicalRho = 0.69;

// The paper's weight of a neighbour at squared distance d2 < d_max^2.
class WeightFunction {
 public:
  WeightFunction(double d_max, double d_min, double alpha)
      : inv_d_max_(1.0 / d_max), d_min_(d_min), alpha_(alpha), alpha8_(alpha == 8.0) {}

  [[gnu::always_inline]] double operator()(double d2) const {
    const double d = std::max(std::sqrt(d2), d_min_);
    return power(std::max(0.0, 1.0 - d * inv_d_max_));
  }

  /// The weight of a pair whose d_max and d_min are scaled by `scale` (the
  /// larger of the two samples' scales).
  [[gnu::always_inline]] double operator()(double d2, double scale) const {
    const double d = std::max(std::sqrt(d2), d_min_ * scale);
    return power(std::max(0.0, 1.0 - d * inv_d_max_ / scale));
  }

 private:
  [[gnu::always_inline]] double power(double x) const {
    if (alpha8_) {
      const double x2 = x * x, x4 = x2 * x2;
      return x4 * x4;
    }
    return std::pow(x, alpha_);
  }

  double inv_d_max_, d_min_, alpha_;
  bool alpha8_;
};

// A point near another, at squared distance d2.
struct Near {
  std::uint32_t index;
  double d2;
};

// Points sorted by grid cell: the points near a point are a few contiguous
// runs. Indices are positions in the sorted order.
template <int D>
class CellIndex {
 public:
  /// Takes the points over and sorts them in place: no second copy of them
  /// (the 5N candidates are most of elimination's memory).
  CellIndex(const Domain<D>& domain, PointSet<D>&& points, double reach, double cells_per_point)
      : domain_(domain), reach_(reach), points_(std::move(points)) {
    // Cells of edge about reach / 2 (a window of 5 cells an axis) up to 3D,
    // reach beyond (3 an axis: 5^D cells would outnumber the points), fewer
    // where the grid would outgrow cells_per_point a point (a thin axis, a
    // tiny set in a large domain, or few candidates for the count).
    const double max_cells =
        std::min<double>(kMaxGridCells, cells_per_point * static_cast<double>(points_.size()) + 64.0);
    std::array<int, D> cells;
    double edge = D <= 3 ? reach / 2.0 : reach;
    while (true) {
      double total = 1.0;
      for (int i = 0; i < D; ++i) {
        cells[i] = static_cast<int>(std::clamp(std::floor(domain.extent(i) / edge), 1.0, 1e9));
        total *= cells[i];
      }
      if (total <= max_cells) break;
      edge *= 1.25;
    }
    for (int i = 0; i < D; ++i) {
      inv_edge_[i] = cells[i] / domain.extent(i);
      scale_ = std::max({scale_, std::abs(domain.lo[i]), std::abs(domain.hi[i])});
    }
    hood_ = GridNeighbourhood<D>(domain, cells);
    // Counting sort by cell, stable: ties keep the input order. `to[k]` is
    // first point k's cell, then its place in the sorted order.
    const std::size_t n = points_.size();
    std::vector<std::uint32_t> to = detail::vector_in_huge_pages<std::uint32_t>(n);
    start_ = detail::vector_in_huge_pages<std::uint32_t>(hood_.size() + 1);
    for (std::size_t k = 0; k < n; ++k) {
      std::size_t c = 0;
      for (int i = 0; i < D; ++i) {
        const double u = std::floor((points_[k][i] - domain.lo[i]) * inv_edge_[i]);
        c += static_cast<std::size_t>(std::clamp(u, 0.0, static_cast<double>(cells[i] - 1))) * hood_.stride(i);
      }
      to[k] = static_cast<std::uint32_t>(c);
      ++start_[c + 1];
    }
    for (std::size_t c = 0; c < hood_.size(); ++c) start_[c + 1] += start_[c];
    // start_[c] serves as cell c's next free place (no copy of the cell
    // starts: as many as 4 a point), then goes back one cell.
    original_ = detail::vector_in_huge_pages<std::uint32_t>(n);
    for (std::size_t k = 0; k < n; ++k) {
      to[k] = start_[to[k]]++;
      original_[to[k]] = static_cast<std::uint32_t>(k);
    }
    for (std::size_t c = hood_.size(); c > 0; --c) start_[c] = start_[c - 1];
    start_[0] = 0;
    move_points_to(to);
  }

  std::size_t size() const { return points_.size(); }
  const Point<D>& point(std::uint32_t k) const { return points_[k]; }

  /// Drops the points `keep(k)` refuses, keeping the others' order; calls
  /// moved(from, to) for each kept point, in increasing order (to <= from).
  template <class Keep, class Moved>
  void compact(Keep&& keep, Moved&& moved) {
    std::uint32_t to = 0;
    for (std::size_t c = 0; c + 1 < start_.size(); ++c) {
      const std::uint32_t begin = start_[c], end = start_[c + 1];
      start_[c] = to;
      for (std::uint32_t k = begin; k < end; ++k)
        if (keep(k)) {
          points_[to] = points_[k];
          original_[to] = original_[k];
          moved(k, to++);
        }
    }
    start_.back() = to;
    points_.resize(to);
    original_.resize(to);
    detail::release_unused(points_);
    detail::release_unused(original_);
  }

  std::uint32_t original(std::uint32_t k) const { return original_[k]; }

  /// The points, in the order of their original indices; the index is spent.
  /// Permuted in place (by cycles), not copied: the output would otherwise
  /// sit beside the index's points at the end of the run.
  PointSet<D> take_points_in_input_order() {
    std::vector<std::uint32_t> by_input(points_.size());
    for (std::uint32_t k = 0; k < by_input.size(); ++k) by_input[k] = k;
    std::sort(by_input.begin(), by_input.end(),
              [&](std::uint32_t a, std::uint32_t b) { return original_[a] < original_[b]; });
    std::vector<std::uint32_t>& to = original_;  // now each point's place
    for (std::uint32_t i = 0; i < by_input.size(); ++i) to[by_input[i]] = i;
    std::vector<std::uint32_t>().swap(by_input);
    move_points_to(to);
    std::vector<std::uint32_t>().swap(original_);
    std::vector<std::uint32_t>().swap(start_);
    return std::move(points_);
  }

  /// Writes to out[0, n) every point k other than `self` closer than the
  /// reach to points_[self], with d2 = Domain::distance2(point k, p), in a
  /// fixed order, and returns n (`out` grows as needed, never shrinks).
  std::size_t gather(std::uint32_t self, std::vector<Near>& out) const {
    const Point<D>& p = points_[self];
    const double r = reach_ * (1.0 + 1e-12) + 1e-12 * scale_;
    const double r2 = reach_ * reach_;
    // Cell coordinates clamped beyond any grid (kMaxGridCells = 2^28 cells
    // in all) before the cast: the reach along a thin axis can span more
    // cells than an int holds (a 1e-150 x 1e150 box). The window then clips
    // the axis to the box, or takes a torus's whole period, as it would.
    constexpr double kFar = 0x1.0p29;
    std::array<int, D> first, last;
    for (int i = 0; i < D; ++i) {
      const double x = p[i] - domain_.lo[i];
      first[i] = static_cast<int>(std::clamp(std::floor((x - r) * inv_edge_[i]), -kFar, kFar));
      last[i] = static_cast<int>(std::clamp(std::floor((x + r) * inv_edge_[i]), -kFar, kFar));
    }
    std::size_t n = 0;
    const auto window = hood_.window(first, last);
    if (!window.seam && narrow(window)) {
      // No wrapping inside this window, and it spans less than half a period:
      // every Domain::distance2 here would be the plain difference, so the
      // cells of a row are one run of points, tested without branches.
      hood_.for_each_row(window, [&](std::size_t row_start) {
        const std::uint32_t begin = start_[row_start], end = start_[row_start + window.count[0]];
        if (out.size() < n + (end - begin)) out.resize(2 * (n + (end - begin)));
        Near* to = out.data();
        for (std::uint32_t k = begin; k < end; ++k) {
          double d2 = 0.0;
          for (int i = 0; i < D; ++i) {
            const double d = p[i] - points_[k][i];
            d2 += d * d;
          }
          to[n] = {k, d2};
          n += static_cast<std::size_t>((d2 < r2) & (k != self));
        }
      });
    } else {
      hood_.for_each_cell(window, [&](std::size_t cell, const std::array<int, D>&) {
        for (std::uint32_t k = start_[cell], end = start_[cell + 1]; k < end; ++k) {
          if (k == self) continue;
          const double d2 = domain_.distance2(points_[k], p);
          if (d2 < r2) {
            if (out.size() <= n) out.resize(2 * n + 16);
            out[n++] = {k, d2};
          }
        }
        return true;
      });
    }
    return n;
  }

 private:
  // Moves point k to to[k] (a permutation, spent on the way), by its cycles:
  // each swap puts one point in its place.
  void move_points_to(std::vector<std::uint32_t>& to) {
    for (std::size_t k = 0; k < points_.size(); ++k)
      while (to[k] != k) {
        const std::uint32_t there = to[k];
        std::swap(points_[k], points_[there]);
        std::swap(to[k], to[there]);
      }
  }

  // A window less than half the cells wide along every axis of a torus (any
  // window in a box).
  bool narrow(const typename GridNeighbourhood<D>::Window& window) const {
    if (!domain_.periodic) return true;
    for (int i = 0; i < D; ++i)
      if (2 * window.count[i] > hood_.cells(i)) return false;
    return true;
  }

  Domain<D> domain_;
  double reach_;
  double scale_ = 0.0;
  std::array<double, D> inv_edge_{};
  GridNeighbourhood<D> hood_;
  std::vector<std::uint32_t> start_;
  PointSet<D> points_;
  std::vector<std::uint32_t> original_;
};

// Weights in fixed point, 2^-32 a unit: a pair's term (at most 1) is
// rounded down once, and a weight is an exact sum of terms, whatever order
// they are added and subtracted in. So a weight depends only on which
// candidates are gone, not on the order they went, which is what lets the
// elimination below run in memory order and still remove exactly what the
// heap would. Sums of up to 2^31 terms stay below 2^63.
using Weight = std::uint64_t;
constexpr double kWeightUnit = 0x1.0p32;
constexpr Weight kGone = std::numeric_limits<Weight>::max();
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// A binary max-heap of indices into the caller's weights, with the position
// of each index, for decrease-key: 8 bytes a candidate (with a copy of each
// weight in its entry it took 20, beside the weights themselves). Larger
// weight first; equal weights, smaller index first.
class WeightHeap {
 public:
  explicit WeightHeap(const std::vector<Weight>& weights)
      : weights_(weights),
        heap_(detail::vector_in_huge_pages<Entry>(weights.size())),
        position_(detail::vector_in_huge_pages<std::uint32_t>(weights.size())) {
    for (std::size_t k = 0; k < weights.size(); ++k) {
      heap_[k] = static_cast<std::uint32_t>(k);
      position_[k] = static_cast<std::uint32_t>(k);
    }
    for (std::size_t at = heap_.size() / 2; at-- > 0;) sift_down(at);
  }

  /// The top entry, removed: its weight and index.
  std::pair<Weight, std::uint32_t> pop() {
    const std::uint32_t top = heap_[0];
    heap_[0] = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) {
      position_[heap_[0]] = 0;
      sift_down(0);
    }
    return {weights_[top], top};
  }

  /// Takes k's place again after the caller lowered its weight.
  void lowered(std::uint32_t k) { sift_down(position_[k]); }

 private:
  using Entry = std::uint32_t;
  bool above(Entry a, Entry b) const { return weights_[a] > weights_[b] || (weights_[a] == weights_[b] && a < b); }
  void sift_down(std::size_t at) {
    const Entry moving = heap_[at];
    const std::size_t n = heap_.size();
    while (true) {
      std::size_t child = 2 * at + 1;
      if (child >= n) break;
      if (child + 1 < n && above(heap_[child + 1], heap_[child])) ++child;
      if (!above(heap_[child], moving)) break;
      heap_[at] = heap_[child];
      position_[heap_[at]] = static_cast<std::uint32_t>(at);
      at = child;
    }
    heap_[at] = moving;
    position_[moving] = static_cast<std::uint32_t>(at);
  }

  const std::vector<Weight>& weights_;
  std::vector<Entry> heap_;
  std::vector<std::uint32_t> position_;
};

// One round of elimination: the paper removes the heaviest candidate, one at
// a time, from a heap. The heaviest is anywhere, so every removal reads a
// fresh neighbourhood from memory (cache misses were 40% of the time). Here
// the same removals run mostly in memory order, by two facts about the heap's
// sequence (priority: weight, then the smaller index):
// - A candidate heavier than every live neighbour it shares a non-zero term
//   with (a local maximum) is removed by the heap before any of those
//   neighbours, at its present weight: its weight cannot change before one of
//   them goes, and none of them can be the top while it is there.
// - The heap's removals come in strictly decreasing priority, and a weight
//   only falls. So with T the K-th highest priority now (K removals still to
//   make), the heap's removals of priority >= T are at most K (each is a
//   candidate of priority >= T now), all of them within this round.
// A band sweeps the candidates of priority >= T in memory order and settles
// each: remove it if it is a local maximum, else first settle its heaviest
// heavier neighbour, until it is gone or below T. That removes exactly the
// heap's removals of priority >= T (weights are exact, so the state depends
// only on what is gone). Bands repeat with a new T; the last few removals,
// when a band would be mostly sweeping, go through the heap itself. The
// removals are recorded with their weights, and sorting them by priority
// gives the heap's order.
template <int D, bool Scaled>
class RoundEliminator {
 public:
  RoundEliminator(std::span<const Point<D>> points, std::span<const double> scale, const Domain<D>& domain,
                  double d_max, const WeightFunction& weight)
      : RoundEliminator(PointSet<D>(points.begin(), points.end()), scale, domain, d_max, weight, 4.0) {}

  /// Takes the points over (the index sorts them in place). The index has at
  /// most cells_per_point cells a point (CellIndex). `fixed`: points that
  /// stay whatever is removed (the levels before this one); each adds its
  /// term to the weights of the candidates near it, a constant, since it
  /// never goes.
  RoundEliminator(PointSet<D>&& points, std::span<const double> scale, const Domain<D>& domain, double d_max,
                  const WeightFunction& weight, double cells_per_point, const Grid<D>* fixed = nullptr)
      : index_(domain, std::move(points), d_max * (Scaled ? *std::max_element(scale.begin(), scale.end()) : 1.0),
               cells_per_point),
        weight_(weight),
        weights_(detail::vector_in_huge_pages<Weight>(index_.size())) {
    const std::size_t n = index_.size();
    if constexpr (Scaled) {
      scale_.resize(n);
      for (std::uint32_t k = 0; k < n; ++k) scale_[k] = scale[index_.original(k)];
    }
    // Each pair once, its term added to both (sums are exact).
    for (std::uint32_t k = 0; k < n; ++k) {
      Weight sum = 0;
      const std::size_t count = index_.gather(k, near_);
      for (const Near& m : std::span(near_.data(), count))
        if (m.index > k) {
          const Weight q = term(m.index, k, m.d2);
          sum += q;
          weights_[m.index] += q;
        }
      weights_[k] += sum;
    }
    if constexpr (!Scaled)
      if (fixed != nullptr)
        for (std::uint32_t k = 0; k < n; ++k)
          fixed->for_each_within(index_.point(k), d_max, [&](std::int32_t, double d2) {
            weights_[k] += static_cast<Weight>(weight_(d2) * kWeightUnit);
            return true;
          });
  }

  /// After run(): the survivors' points in input order (run's first `keep`
  /// indices, in the same order). The weights go first: the round is over.
  PointSet<D> take_survivors() {
    std::vector<Weight>().swap(weights_);
    return index_.take_points_in_input_order();
  }

  /// Eliminates down to `keep`. Returns indices into the points: the
  /// survivors first (in input order), then, if `ordered`, the eliminated, the
  /// last eliminated first; nothing if not `indices` (take_survivors() alone
  /// is wanted: the list would sit beside the index at the run's peak).
  std::vector<std::uint32_t> run(std::size_t keep, bool ordered, bool by_heap, ProgressReporter& progress, double done,
                                 bool indices = true) {
    const std::size_t total = index_.size();
    // Only an ordered round keeps a record of each removal (16 bytes): the
    // first round of 5N candidates would hold 4N of them for nothing.
    ordered_ = ordered;
    if (ordered) {
      rank_.resize(total);
      for (std::uint32_t k = 0; k < total; ++k) rank_[k] = k;
      removed_.reserve(total - keep);
    }
    while (index_.size() > keep) {
      const std::size_t live = index_.size(), to_remove = live - keep;
      // A band costs a sweep over the live candidates; the heap costs a cache
      // miss a removal. Sweeps pay while they remove many (measured).
      if (by_heap || to_remove * kHeapShare < live) {
        finish_with_heap(to_remove, progress, done);
        break;
      }
      const auto [t_weight, t_index] = kth_highest(to_remove);
      const std::size_t before = removals_;
      for (std::uint32_t k = 0; k < live; ++k)
        if (weights_[k] != kGone && at_least(k, t_weight, t_index)) settle(k, t_weight, t_index);
      // The top candidate is a local maximum above the threshold, so a band
      // removes at least one; and never more than the heap would.
      if (removals_ == before || removals_ - before > to_remove)
        throw Failure("elimination: a band removed " + std::to_string(removals_ - before) + " of " +
                      std::to_string(to_remove) + " candidates (internal error)");
      progress.update(done + static_cast<double>(removals_));
      compact();
    }
    std::vector<std::uint32_t> order;
    if (!indices) return order;
    order.reserve(ordered ? total : keep);
    for (std::uint32_t k = 0; k < index_.size(); ++k) order.push_back(index_.original(k));
    std::sort(order.begin(), order.end());
    if (ordered) {
      // The heap's order: priority descending; the last eliminated first.
      std::sort(removed_.begin(), removed_.end(), [](const Removal& a, const Removal& b) {
        return a.weight > b.weight || (a.weight == b.weight && a.rank < b.rank);
      });
      for (auto it = removed_.rbegin(); it != removed_.rend(); ++it) order.push_back(it->original);
    }
    return order;
  }

 private:
  // Below this share of the live candidates left to remove, the heap finishes.
  static constexpr std::size_t kHeapShare = 32;

  struct Removal {
    Weight weight;
    std::uint32_t rank;      // position before any compaction: the heap's tie-break
    std::uint32_t original;  // index into the round's input
  };
  // The pair (self, k)'s term at squared distance d2, in fixed point; zero
  // beyond the pair's own d_max.
  [[gnu::always_inline]] Weight term(std::uint32_t self, std::uint32_t k, double d2) const {
    double w;
    if constexpr (Scaled)
      w = weight_(d2, std::max(scale_[self], scale_[k]));
    else
      w = weight_(d2);
    return static_cast<Weight>(w * kWeightUnit);
  }

  // Positions keep the order of ranks through compaction, so they break ties.
  bool above(std::uint32_t a, std::uint32_t b) const {
    return weights_[a] > weights_[b] || (weights_[a] == weights_[b] && a < b);
  }
  bool at_least(std::uint32_t k, Weight t_weight, std::uint32_t t_index) const {
    return weights_[k] > t_weight || (weights_[k] == t_weight && k <= t_index);
  }

  // Removes x, or lowers it below the threshold, removing first whatever of
  // priority >= threshold the heap would remove before it. A candidate is
  // compared with every live one within reach, not only those its term
  // reaches: a stricter test, the same removals, and the terms are only
  // evaluated for a removal.
  void settle(std::uint32_t x, Weight t_weight, std::uint32_t t_index) {
    stack_.push_back(x);
    while (!stack_.empty()) {
      const std::uint32_t y = stack_.back();
      if (weights_[y] == kGone || !at_least(y, t_weight, t_index)) {
        stack_.pop_back();
        continue;
      }
      std::uint32_t heavier = kNone;
      const std::size_t count = index_.gather(y, near_);
      for (const Near& m : std::span(near_.data(), count))
        if (weights_[m.index] != kGone && above(m.index, y) && (heavier == kNone || above(m.index, heavier)))
          heavier = m.index;
      if (heavier != kNone) {
        stack_.push_back(heavier);  // a chain of rising priorities: it ends
        continue;
      }
      for (const Near& m : std::span(near_.data(), count))
        if (weights_[m.index] != kGone) weights_[m.index] -= term(y, m.index, m.d2);
      record(y, weights_[y]);
      weights_[y] = kGone;
      stack_.pop_back();
    }
  }

  void finish_with_heap(std::size_t to_remove, ProgressReporter& progress, double done) {
    WeightHeap heap(weights_);  // the index holds only live candidates
    for (std::size_t i = 0; i < to_remove; ++i) {
      progress.update(done + static_cast<double>(removals_));
      const auto [w, gone] = heap.pop();
      record(gone, w);
      weights_[gone] = kGone;
      const std::size_t count = index_.gather(gone, near_);
      for (const Near& m : std::span(near_.data(), count))
        if (weights_[m.index] != kGone) {
          const Weight q = term(gone, m.index, m.d2);
          weights_[m.index] -= q;
          heap.lowered(m.index);
        }
    }
    compact();
  }

  // The live candidate of the k-th highest priority (k >= 1), by a radix
  // select on the weights, 16 bits a pass, then the ties in position order:
  // no copy of the weights or of their indices.
  std::pair<Weight, std::uint32_t> kth_highest(std::size_t k) {
    Weight prefix = 0;  // the high bits of the answer found so far
    std::vector<std::size_t> count(std::size_t{1} << 16);
    for (int shift = 48; shift >= 0; shift -= 16) {
      std::fill(count.begin(), count.end(), 0);
      const Weight high_mask = shift == 48 ? 0 : ~Weight{0} << (shift + 16);
      for (const Weight w : weights_)
        if ((w & high_mask) == prefix) ++count[(w >> shift) & 0xffff];
      std::size_t digit = 0xffff;
      while (count[digit] < k) k -= count[digit--];
      prefix |= static_cast<Weight>(digit) << shift;
    }
    // The k-th smallest position among the weights equal to prefix.
    for (std::uint32_t at = 0;; ++at)
      if (weights_[at] == prefix && --k == 0) return {prefix, at};
  }

  void record(std::uint32_t k, Weight weight) {
    ++removals_;
    if (ordered_) removed_.push_back({weight, rank_[k], index_.original(k)});
  }

  // Drops the removed candidates from the index and the arrays beside it, so
  // later sweeps and scans read only live ones.
  void compact() {
    index_.compact([&](std::uint32_t k) { return weights_[k] != kGone; },
                   [&](std::uint32_t from, std::uint32_t to) {
                     weights_[to] = weights_[from];
                     if (ordered_) rank_[to] = rank_[from];
                     if constexpr (Scaled) scale_[to] = scale_[from];
                   });
    weights_.resize(index_.size());
    detail::release_unused(weights_);
    if (ordered_) rank_.resize(index_.size());
    if constexpr (Scaled) scale_.resize(index_.size());
  }

  CellIndex<D> index_;
  WeightFunction weight_;
  std::vector<double> scale_;
  std::vector<Weight> weights_;  // kGone once removed
  bool ordered_ = false;
  std::size_t removals_ = 0;
  std::vector<std::uint32_t> rank_;  // ordered rounds only
  std::vector<Removal> removed_;     // ordered rounds only
  std::vector<Near> near_;
  std::vector<std::uint32_t> stack_;
};

// One round: eliminates `points` down to `keep`. Returns indices into
// `points`: the survivors first (in input order), then (if `ordered`) the
// eliminated, the last eliminated first. `scale` is empty (one d_max for all)
// or one factor a point: a pair's d_max and d_min grow by the larger of its
// two factors.
template <int D, bool Scaled>
std::vector<std::uint32_t> eliminate_round(std::span<const Point<D>> points, std::span<const double> scale,
                                           std::size_t keep, const Domain<D>& domain, double d_max,
                                           const WeightFunction& weight, ProgressReporter& progress, double done,
                                           bool ordered, bool by_heap) {
  RoundEliminator<D, Scaled> round(points, scale, domain, d_max, weight);
  return round.run(keep, ordered, by_heap, progress, done);
}

template <int D>
std::vector<std::uint32_t> eliminate_round(std::span<const Point<D>> points, std::span<const double> scale,
                                           std::size_t keep, const Domain<D>& domain, double d_max,
                                           const WeightFunction& weight, ProgressReporter& progress, double done,
                                           bool ordered, bool by_heap) {
  return scale.empty()
             ? eliminate_round<D, false>(points, scale, keep, domain, d_max, weight, progress, done, ordered, by_heap)
             : eliminate_round<D, true>(points, scale, keep, domain, d_max, weight, progress, done, ordered, by_heap);
}

void validate(const EliminationWeights& w) {
  if (!(w.alpha > 0.0) || !std::isfinite(w.alpha))
    throw InvalidArgument("elimination: alpha must be positive and finite, got " + detail::format_number(w.alpha));
  if (!(w.beta >= 0.0 && w.beta < 1.0))
    throw InvalidArgument("elimination: beta must be in [0, 1), got " + detail::format_number(w.beta));
  if (!(w.gamma > 0.0) || !std::isfinite(w.gamma))
    throw InvalidArgument("elimination: gamma must be positive and finite, got " + detail::format_number(w.gamma));
}

// The paper's progressive order (section 5): the kept set is eliminated
// again to half its size, with d_max grown to the half's spacing, and so on;
// each half's eliminated go after the half's survivors. `kept` (indices into
// `points`, `scale` beside them) is reordered so that every prefix of a
// power of two is such a half.
template <int D>
void order_progressively(std::span<const Point<D>> points, std::span<const double> scale,
                         std::vector<std::uint32_t>& kept, const Domain<D>& domain, double d_max, double d_min,
                         double alpha, int growth_dim, ProgressReporter& reporter, double done, bool by_heap) {
  const std::size_t count = kept.size();
  PointSet<D> out(count);
  std::vector<double> out_scale(scale.empty() ? 0 : count);
  std::vector<std::uint32_t> round(count);
  for (std::size_t size = count; size >= 2; size /= 2) {
    for (std::size_t i = 0; i < size; ++i) {
      out[i] = points[kept[i]];
      if (!scale.empty()) out_scale[i] = scale[kept[i]];
    }
    d_max *= std::pow(2.0, 1.0 / growth_dim);
    const WeightFunction weight(d_max, d_min, alpha);
    const std::vector<std::uint32_t> order =
        eliminate_round<D>(std::span<const Point<D>>(out.data(), size),
                           std::span<const double>(out_scale.data(), scale.empty() ? 0 : size), size / 2, domain, d_max,
                           weight, reporter, done, /*ordered=*/true, by_heap);
    done += static_cast<double>(size - size / 2);
    for (std::size_t i = 0; i < size; ++i) round[i] = kept[order[i]];
    std::copy(round.begin(), round.begin() + static_cast<std::ptrdiff_t>(size), kept.begin());
  }
}

// The work counted by progress: every candidate removed, in the first round
// and in the halvings of the progressive order.
double removals_of(std::size_t candidates, std::size_t count, bool progressive) {
  double removals = static_cast<double>(candidates - count);
  if (progressive)
    for (std::size_t size = count; size >= 2; size /= 2) removals += static_cast<double>(size - size / 2);
  return removals;
}

// The paper's weight limit (section 3.2): d_min = d_max (1 - (N/M)^gamma) beta,
// for N kept of M candidates; the progressive rounds keep it.
double weight_limit(double d_max, std::size_t count, std::size_t candidates, const EliminationWeights& weights) {
  const double ratio = static_cast<double>(count) / static_cast<double>(candidates);
  return d_max * (1.0 - std::pow(ratio, weights.gamma)) * weights.beta;
}

template <int D>
std::vector<std::uint32_t> eliminate_all(std::span<const Point<D>> points, std::span<const double> scale,
                                         std::size_t count, const Domain<D>& domain, double d_max,
                                         const EliminationWeights& weights, bool progressive, int growth_dim,
                                         const Progress& progress, bool by_heap) {
  const double d_min = weight_limit(d_max, count, points.size(), weights);
  const WeightFunction first(d_max, d_min, weights.alpha);
  ProgressReporter reporter(progress, removals_of(points.size(), count, progressive));
  std::vector<std::uint32_t> kept =
      eliminate_round<D>(points, scale, count, domain, d_max, first, reporter, 0.0, /*ordered=*/false, by_heap);
  kept.resize(count);
  if (progressive)
    order_progressively<D>(points, scale, kept, domain, d_max, d_min, weights.alpha, growth_dim, reporter,
                           static_cast<double>(points.size() - count), by_heap);
  reporter.finish();
  return kept;
}

// eliminate_all on candidates it may consume: the first round's index takes
// them over, and the later rounds work on the survivors alone, so the
// candidates are held once (eliminate_all's caller keeps its own). The same
// points out, in the same order.
template <int D>
PointSet<D> eliminate_consuming(PointSet<D>&& candidates, std::span<const double> scale, std::size_t count,
                                const Domain<D>& domain, double d_max, const EliminationWeights& weights,
                                bool progressive, const Progress& progress) {
  const std::size_t m = candidates.size();
  const double d_min = weight_limit(d_max, count, m, weights);
  const WeightFunction first(d_max, d_min, weights.alpha);
  ProgressReporter reporter(progress, removals_of(m, count, progressive));
  PointSet<D> survivors;
  std::vector<std::uint32_t> kept;
  const auto first_round = [&]<bool Scaled>() {
    // From 2D, one cell a candidate at most: with few candidates for the
    // count (Bridson's count path removes about 1%) the cells of edge
    // d_max / 2 outnumber them 3.5 to 1, and their starts were the largest
    // array after the points. From 5N candidates the limit does not bind. (In
    // 1D, where the output is small, the cells stay as they were: ties of
    // weight are common there, broken by the cells' order.)
    RoundEliminator<D, Scaled> round(std::move(candidates), scale, domain, d_max, first, D >= 2 ? 1.0 : 4.0);
    kept = round.run(count, /*ordered=*/false, /*by_heap=*/false, reporter, 0.0, /*indices=*/progressive);
    survivors = round.take_survivors();
  };
  if (scale.empty())
    first_round.template operator()<false>();
  else
    first_round.template operator()<true>();
  if (!progressive) {
    reporter.finish();
    return survivors;
  }
  std::vector<double> survivors_scale(scale.empty() ? 0 : count);
  for (std::size_t i = 0; i < survivors_scale.size(); ++i) survivors_scale[i] = scale[kept[i]];
  for (std::uint32_t i = 0; i < count; ++i) kept[i] = i;  // now indices into the survivors
  order_progressively<D>(survivors, survivors_scale, kept, domain, d_max, d_min, weights.alpha, D, reporter,
                         static_cast<double>(m - count), false);
  reporter.finish();
  PointSet<D> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = survivors[kept[i]];
  return out;
}

// A grid cell edge of at least `edge`, doubled while the grid would have more
// than 8 cells a point (of `points`): a thin axis would otherwise make far
// more cells than points.
template <int D>
double capped_cell_edge(const Domain<D>& domain, double edge, std::size_t points) {
  return Grid<D>::edge_for_at_most(
      domain, edge, std::min(8.0 * static_cast<double>(points) + 64.0, static_cast<double>(kMaxGridCells)));
}

// Moves the points of pairs closer than `spacing` (EliminationParams::min_rho)
// to free places nearby. From 5N candidates the closest pairs sit near 0.69
// d_max, yet the set has room for ~11% more points at 0.72 (random
// sequential adsorption saturates near 0.76): the few points too near a
// neighbour can move, while no better candidate lay near them (a swap with an
// eliminated candidate gained < 0.005, docs/elimination.md).
//
// A move of point i must leave every pair (i, j) at least max(spacing,
// mu(k)) apart, mu(k) the minimum distance of the first k points before any
// move and k = max(i, j) + 1: then no prefix of the progressive order gets a
// pair closer than it had, and the moved point is spacing from every other.
// Only points of the second half move in the progressive order: the first
// half's pairs are ~0.88 d_max(N) apart (its own ~0.62 at half the count),
// above 0.72, so every close pair has a point there. Before any move the
// pairs that break a rule are exactly those closer than spacing (mu(k) is at
// most the distance of the k-th point to its nearest earlier one), and a
// kept move breaks none, so only those pairs' points are visited.
//
// Point i goes to the best of random trials in cubes of half-edge spacing,
// 2 spacing and 3 spacing around it, each refined by three rounds around the
// best so far with the half-edge halved; the best trial keeps every prefix's
// rule and has the farthest nearest point. Points that find no place spacing
// from the others are tried again, with 8 times the trials, while some of
// them move (at most 8 passes), and then also go to a place better than
// theirs: the closest pair still moves apart when min_rho asks for more than
// there is room for (0.74 gives about 0.73 at 10^5 points).
//
// `fixed` leading points never move (the halvings' first half, or the levels
// before this one); `progressive` adds the rule for every prefix. `level`
// picks the stream of trials. `relocate`: one pass of trials near, then the
// points left without a place try the empty cells anywhere (below). `reporter`, if
// given, hears a poll a point (for a prompt stop; the count does not move).
template <int D>
PointSet<D> spread_closest_pairs(PointSet<D> points, const Domain<D>& domain, double spacing, std::size_t fixed,
                                 bool progressive, std::uint64_t seed, std::uint64_t level = 0, bool relocate = false,
                                 ProgressReporter* reporter = nullptr) {
  const std::size_t n = points.size();
  if (n < 2 || !(spacing > 0.0)) return points;
  const std::size_t half = std::min(fixed, n);
  // Every rule is below `reach`: spacing, or a prefix's minimum distance mu,
  // which from the first half on lies below the half's d_max (where it does
  // not, the points stay: below).
  const double reach =
      progressive ? std::max(spacing, 2.0 * max_packing_radius(domain.volume(), std::max<std::size_t>(half, 1), D))
                  : spacing;
  // Cells of edge spacing, about two a point.
  const double edge = capped_cell_edge(domain, spacing, n);
  Grid<D> grid(domain, edge);
  grid.reserve(n);
  // prefix2[k - half]: mu(k)^2, the squared minimum distance of the first k
  // points, k >= half, from each point's nearest earlier one. `close`: the
  // points of pairs closer than spacing.
  const double spacing2 = spacing * spacing;
  std::vector<double> prefix2(progressive ? n - half + 1 : 0);
  std::vector<std::uint32_t> close;
  double mu2 = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n; ++k) {
    bool near = false;
    // A fixed point's pairs with the points before it (fixed too) matter
    // only to the prefixes' minima.
    if (progressive || k >= half)
      grid.for_each_within(points[k], reach, [&](std::int32_t j, double d2) {
        mu2 = std::min(mu2, d2);
        if (d2 < spacing2) {
          near = true;
          if (static_cast<std::size_t>(j) >= half) close.push_back(static_cast<std::uint32_t>(j));
        }
        return true;
      });
    if (near && k >= half) close.push_back(static_cast<std::uint32_t>(k));
    grid.insert(points[k]);
    if (progressive && k + 1 >= half) prefix2[k + 1 - half] = mu2;
  }
  points = PointSet<D>();
  // A prefix with no pair within reach: mu is unknown there, so its points
  // stay.
  std::size_t first = half;
  if (progressive)
    while (first < n && !(prefix2[first + 1 - half] < reach * reach)) ++first;
  std::sort(close.begin(), close.end());
  close.erase(std::unique(close.begin(), close.end()), close.end());
  close.erase(close.begin(), std::lower_bound(close.begin(), close.end(), static_cast<std::uint32_t>(first)));
  if (relocate) {
    // Visited in the grid's order, not the points' (a level's points are in
    // farthest-first order, all over the domain): each visit's cells are
    // then mostly in cache from the one before.
    std::vector<std::pair<std::size_t, std::uint32_t>> by_cell(close.size());
    for (std::size_t k = 0; k < close.size(); ++k) by_cell[k] = {grid.cell_of(grid.points()[close[k]]), close[k]};
    std::sort(by_cell.begin(), by_cell.end());
    for (std::size_t k = 0; k < close.size(); ++k) close[k] = by_cell[k].second;
  }

  const PointSet<D>& at = grid.points();
  // Where point i could go: -infinity if some pair (i, j) would be closer
  // than mu(max(i, j) + 1), else the smallest squared distance to a point
  // near x over spacing^2 (>= 1: every pair keeps both rules). Point i's
  // widest rule is with the points before it. The walk stops once the score
  // is at most `beaten` (a trial that cannot beat the best so far): the
  // decisions are those of the whole walk, in fewer reads.
  constexpr double kRefused = -std::numeric_limits<double>::infinity();
  const auto score = [&](const Point<D>& x, std::size_t i, double beaten = -std::numeric_limits<double>::infinity()) {
    const double widest2 = progressive ? std::max(spacing2, prefix2[i + 1 - half]) : spacing2;
    double worst = std::numeric_limits<double>::infinity();
    grid.for_each_within(x, std::sqrt(widest2), [&](std::int32_t j, double d2) {
      const auto ju = static_cast<std::size_t>(j);
      if (ju == i) return true;
      if (progressive && d2 < prefix2[std::max(i, ju) + 1 - half]) {
        worst = kRefused;
        return false;
      }
      worst = std::min(worst, d2 / spacing2);
      return worst > beaten;
    });
    return worst;
  };
  Rng rng = level == 0 ? Rng(seed, {0x73707265616455}) : Rng(seed, {0x73707265616455, level});  // streams of their own
  constexpr int kPasses = 8, kRounds = 4, kTrials = 16, kRelocationTrials = 1 << 14;
  const double kFits = std::nextafter(1.0, 0.0);  // a score below 1 does not fit
  // `relocate`: a point takes the first trial that keeps every rule (not the
  // best of its round: 10% faster, no change in rho or the prefixes at 10^5
  // points), and after the first pass a point still without a place spacing
  // from the others may go anywhere that has one: trials in the grid's
  // empty cells, listed once and taken in the grid's order by a cursor,
  // uniform within a cell (a trial anywhere in the domain found room half
  // as often, and empty cells drawn at random missed the caches at 10^6
  // points); the later passes then take the few left. Around fixed levels
  // the room at 0.72 is rarely near the point: without this the levels'
  // full set stopped at rho 0.68 at 10^5 points, with it 0.72, and the
  // later passes' trials near the point took three quarters of the time.
  // Once kHopeless points in a row found no place, min_rho asks for more
  // room than the set has (0.8 at 20,000 points took 31 s before, 5.6 s
  // since, with the levels), and the rest stay for the passes.
  constexpr int kHopeless = 4;
  const auto relocate_stuck = [&] {
    std::vector<std::uint32_t> stuck, empty;
    int failed = 0;
    std::size_t cursor = 0;
    for (std::size_t c = 0; c < grid.cell_count(); ++c)
      if (grid.cell_empty(c)) empty.push_back(static_cast<std::uint32_t>(c));
    for (const std::uint32_t i : close) {
      if (reporter != nullptr) reporter->poll();
      if (score(at[i], i) >= 1.0) continue;
      bool placed = false;
      for (int t = 0; t < kRelocationTrials && !placed && failed < kHopeless && !empty.empty(); ++t) {
        const std::array<int, D> c = grid.neighbourhood().coords(empty[cursor]);
        cursor = cursor + 1 == empty.size() ? 0 : cursor + 1;
        Point<D> x;
        for (int a = 0; a < D; ++a) x[a] = domain.lo[a] + (c[a] + rng.uniform()) * grid.cell_edge(a);
        if (!domain.contains(x)) continue;
        if (score(x, i, kFits) >= 1.0) {
          grid.move(static_cast<std::int32_t>(i), x);
          placed = true;
        }
      }
      failed = placed ? 0 : failed + 1;
      if (!placed) stuck.push_back(i);
    }
    close = std::move(stuck);
  };
  bool relocated = !relocate;
  for (int pass = 0; pass < kPasses && !close.empty(); ++pass) {
    if (pass > 0 && !relocated) {
      relocate_stuck();
      relocated = true;
      if (close.empty()) break;
    }
    std::vector<std::uint32_t> stuck;
    std::size_t moved = 0;
    const int trials = pass == 0 ? kTrials : 8 * kTrials;
    for (const std::uint32_t i : close) {
      if (reporter != nullptr) reporter->poll();
      const double now = score(at[i], i);
      if (now >= 1.0) continue;  // its partner moved
      double best_score = now;
      Point<D> best = at[i];
      for (const double scale : {1.0, 2.0, 3.0}) {
        // With `relocate` the first pass takes the first scale only: a
        // point with no room there rarely finds it at the larger ones, and
        // the relocation finds room in about a hundred trials.
        if (best_score >= 1.0 || (relocate && pass == 0 && scale > 1.0)) break;
        double half_edge = scale * spacing;
        for (int round = 0; round < kRounds && !(relocate && best_score >= 1.0); ++round, half_edge *= 0.5) {
          const Point<D> centre = round == 0 ? at[i] : best;
          for (int t = 0; t < trials && !(relocate && best_score >= 1.0); ++t) {
            Point<D> x;
            for (int a = 0; a < D; ++a) x[a] = centre[a] + half_edge * (2.0 * rng.uniform() - 1.0);
            if (domain.periodic)
              x = domain.wrap(x);
            else if (!domain.contains(x))
              continue;
            const double s = score(x, i, best_score);
            if (s > best_score) {
              best_score = s;
              best = x;
            }
          }
        }
      }
      // The first pass moves a point only to a place that keeps every rule;
      // later ones also to a better one, which pushes the closest pair apart
      // as far as the trials found room.
      if (best_score >= 1.0 || (pass > 0 && best_score > now)) {
        grid.move(static_cast<std::int32_t>(i), best);
        ++moved;
      }
      if (best_score < 1.0) stuck.push_back(i);
    }
    close = std::move(stuck);
    if (moved == 0 && relocated) break;
  }
  return std::move(grid).take_points();
}

// Orders points[fixed, n) farthest first: each next one is, of those left,
// the farthest from every point before it (ties: the earlier one). Lazily: a
// point's key is its squared distance to the prefix when last measured, an
// upper bound once the prefix has grown, and it is measured again when it
// reaches the top. `edge`: the grid's cell edge, about the points' spacing.
template <int D>
void order_farthest_first(PointSet<D>& points, std::size_t fixed, const Domain<D>& domain, double edge) {
  const std::size_t n = points.size();
  if (n < fixed + 2) return;
  edge = capped_cell_edge(domain, edge, n);
  Grid<D> grid(domain, edge);
  grid.reserve(n);
  for (std::size_t i = 0; i < fixed; ++i) grid.insert(points[i]);
  double diameter2 = 0.0;
  for (int a = 0; a < D; ++a) diameter2 += domain.extent(a) * domain.extent(a);
  // The squared distance from x to the nearest point of the prefix, whose
  // distance is at most sqrt(bound) when bound is finite; else searched in
  // balls doubling from the cell edge.
  const auto nearest2 = [&](const Point<D>& x, double bound) {
    double best = std::numeric_limits<double>::infinity();
    if (grid.size() == 0) return best;
    double r = std::isfinite(bound) ? std::sqrt(bound) * (1.0 + 1e-9) : edge;
    for (;;) {
      grid.for_each_within(x, r, [&](std::int32_t, double d2) {
        best = std::min(best, d2);
        return true;
      });
      if (std::isfinite(best) || r * r > diameter2) return best;
      r *= 2.0;
    }
  };
  struct Entry {
    double d2;
    std::uint32_t i;
  };
  // std::make_heap's order: the top is the largest key, then the smallest i.
  const auto below = [](const Entry& a, const Entry& b) { return a.d2 < b.d2 || (a.d2 == b.d2 && a.i > b.i); };
  std::vector<Entry> heap(n - fixed);
  for (std::size_t i = 0; i < heap.size(); ++i)
    heap[i] = {std::numeric_limits<double>::infinity(), static_cast<std::uint32_t>(i)};
  std::make_heap(heap.begin(), heap.end(), below);
  std::vector<std::uint32_t> order;
  order.reserve(heap.size());
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), below);
    Entry e = heap.back();
    heap.pop_back();
    e.d2 = nearest2(points[fixed + e.i], e.d2);
    if (heap.empty() || !below(e, heap.front())) {
      order.push_back(e.i);
      grid.insert(points[fixed + e.i]);
    } else {
      heap.push_back(e);
      std::push_heap(heap.begin(), heap.end(), below);
    }
  }
  PointSet<D> tail(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) tail[k] = points[fixed + order[k]];
  std::copy(tail.begin(), tail.end(), points.begin() + static_cast<std::ptrdiff_t>(fixed));
}

// The progressive order built coarse to fine (EliminationParams::levels).
// The paper's halvings pick each half from the set below it, and a set
// spread for N points holds no subset spread for N/2 much beyond rho 0.63
// (docs/elimination.md). Here each level is made for its own count: the
// counts shrink by sqrt(2) from N down to kFirstLevel, and level n keeps n
// points of the first kLowerFactor x n candidates (all of them for N),
// eliminating around the points of the levels below, which stay (their terms
// are constant weights).
// Then its new points move apart to min_rho x its d_max (below N, from 2D
// on, a little less: kLowerRhoSlack; the levels below stay put) and follow
// the levels below farthest first. So every level is a prefix with about the
// minimum distance a set of its own count gets, and the prefixes between two
// levels lose what the farthest-first order cannot keep.
template <int D>
PointSet<D> eliminate_in_levels(PointSet<D>&& candidates, std::size_t count, const Domain<D>& domain,
                                const EliminationWeights& weights, double min_rho, std::uint64_t seed,
                                const Progress& progress) {
  // Counts shrink by sqrt(2) a level: by 2 the prefixes just past a level
  // fell to rho 0.645 (the level's holes are few and small), by sqrt(2) no
  // prefix went below 0.679 (every level then at min_rho; docs/elimination.md).
  constexpr std::size_t kFirstLevel = 16;
  // The levels below N draw on at most 2 candidates a point: the moves, not
  // the candidates, set their spacing (2, 3 and 5 gave the same prefixes at
  // 10^5 points, 2 in three quarters of 5's time).
  constexpr double kLowerFactor = 2.0;
  // From 2D on the levels below N move their points apart to min_rho less
  // this (N itself keeps min_rho): the prefixes sit about 0.01 lower, still
  // well above 0.65, and a level run takes about 12% less time
  // (docs/elimination.md). 1D keeps min_rho: its prefixes are the weakest
  // (with the slack the test's 1D case fell from 0.620 to 0.592).
  constexpr double kLowerRhoSlack = D >= 2 ? 0.02 : 0.0;
  const std::size_t m = candidates.size();
  const double factor = static_cast<double>(m) / static_cast<double>(count);
  std::vector<std::size_t> sizes{count};
  while (sizes.back() > kFirstLevel)
    sizes.push_back(static_cast<std::size_t>(std::ceil(static_cast<double>(sizes.back()) / std::numbers::sqrt2)));
  std::reverse(sizes.begin(), sizes.end());
  std::vector<std::size_t> pools(sizes.size(), m);
  double total = 0.0;
  for (std::size_t j = 0; j < sizes.size(); ++j) {
    if (j + 1 < sizes.size())
      pools[j] = std::min(
          m, static_cast<std::size_t>(std::ceil(std::min(factor, kLowerFactor) * static_cast<double>(sizes[j]))));
    total += static_cast<double>(pools[j] - sizes[j]);
  }
  ProgressReporter reporter(progress, total);
  double done = 0.0;
  std::vector<bool> taken(m);  // candidates some level below has kept
  PointSet<D> set;
  set.reserve(count);
  for (std::size_t j = 0; j < sizes.size(); ++j) {
    const std::size_t n = sizes[j], pool = pools[j], below = set.size();
    const bool top = j + 1 == sizes.size();
    const double d_max = 2.0 * max_packing_radius(domain.volume(), n, D);
    const WeightFunction weight(d_max, weight_limit(d_max, n, pool, weights), weights.alpha);
    Grid<D> fixed(domain, capped_cell_edge(domain, d_max, below));
    fixed.reserve(below);
    for (const Point<D>& p : set) fixed.insert(p);
    // This level's candidates: the first `pool`, less those the levels below
    // kept. The top level takes the whole array over.
    PointSet<D> own;
    std::vector<std::uint32_t> from;
    if (top) {
      std::size_t to = 0;
      for (std::size_t c = 0; c < m; ++c)
        if (!taken[c]) candidates[to++] = candidates[c];
      candidates.resize(to);
      own = std::move(candidates);
    } else {
      own.reserve(pool - below);
      from.reserve(pool - below);
      for (std::size_t c = 0; c < pool; ++c)
        if (!taken[c]) {
          own.push_back(candidates[c]);
          from.push_back(static_cast<std::uint32_t>(c));
        }
    }
    RoundEliminator<D, false> round(std::move(own), {}, domain, d_max, weight, D >= 2 ? 1.0 : 4.0, &fixed);
    const std::vector<std::uint32_t> kept =
        round.run(n - below, /*ordered=*/false, /*by_heap=*/false, reporter, done, /*indices=*/!top);
    for (const std::uint32_t k : kept) taken[from[k]] = true;
    const PointSet<D> added = round.take_survivors();
    done += static_cast<double>(pool - n);
    set.insert(set.end(), added.begin(), added.end());
    const double rho = top ? min_rho : min_rho - kLowerRhoSlack;  // <= 0: no moves
    set = spread_closest_pairs<D>(std::move(set), domain, rho * d_max, below, /*progressive=*/false, seed, j + 1,
                                  /*relocate=*/true, &reporter);
    order_farthest_first<D>(set, below, domain, d_max);
  }
  reporter.finish();
  return set;
}

}  // namespace

namespace detail {

template <int D>
std::vector<std::uint32_t> eliminate_indices(std::span<const Point<D>> points, std::span<const double> scale,
                                             std::size_t count, const Domain<D>& domain, double d_max,
                                             const EliminationWeights& weights, bool progressive, int growth_dim,
                                             const Progress& progress) {
  return eliminate_all<D>(points, scale, count, domain, d_max, weights, progressive, growth_dim, progress, false);
}

template <int D>
std::vector<std::uint32_t> eliminate_indices_by_heap(std::span<const Point<D>> points, std::span<const double> scale,
                                                     std::size_t count, const Domain<D>& domain, double d_max,
                                                     const EliminationWeights& weights, bool progressive,
                                                     int growth_dim) {
  return eliminate_all<D>(points, scale, count, domain, d_max, weights, progressive, growth_dim, {}, true);
}

void validate_elimination_weights(const EliminationWeights& weights) { validate(weights); }

}  // namespace detail

template <int D>
PointSet<D> eliminate(PointSet<D>&& candidates, std::uint64_t count, const Domain<D>& domain,
                      const EliminationWeights& weights, bool progressive, const Progress& progress) {
  domain.validate();
  validate(weights);
  if (count == 0) throw InvalidArgument("elimination: count must be at least 1, got 0");
  if (count > candidates.size())
    throw InvalidArgument("elimination: count " + std::to_string(count) + " is more than the " +
                          std::to_string(candidates.size()) + " candidates");
  if (candidates.size() > kMaxCandidates)
    throw InvalidArgument("elimination: more than 2^31 candidates (" + std::to_string(candidates.size()) + ")");
  for (const Point<D>& p : candidates)
    if (!domain.contains(p)) {
      std::ostringstream os;
      os << "elimination: candidate " << p << " lies outside " << domain;
      throw InvalidArgument(os.str());
    }
  const auto n = static_cast<std::size_t>(count);
  const double d_max = 2.0 * max_packing_radius(domain.volume(), n, D);
  return eliminate_consuming<D>(std::move(candidates), {}, n, domain, d_max, weights, progressive, progress);
}

template <int D>
PointSet<D> eliminate(const PointSet<D>& candidates, std::uint64_t count, const Domain<D>& domain,
                      const EliminationWeights& weights, bool progressive, const Progress& progress) {
  return eliminate(PointSet<D>(candidates), count, domain, weights, progressive, progress);
}

template <int D>
PointSet<D> elimination(const EliminationParams& params, const Domain<D>& domain, std::uint64_t seed) {
  domain.validate();
  validate(params.weights);
  if (params.count == 0) throw InvalidArgument("elimination: count must be at least 1, got 0");
  if (!(params.candidates >= 1.0) || !std::isfinite(params.candidates))
    throw InvalidArgument("elimination: candidates must be a factor of at least 1, got " +
                          detail::format_number(params.candidates));
  const double m = std::ceil(params.candidates * static_cast<double>(params.count));
  if (m > static_cast<double>(kMaxCandidates))
    throw InvalidArgument("elimination: " + detail::format_number(m) + " candidates, more than 2^31");
  if (!(params.min_rho >= 0.0 && params.min_rho <= 0.8))
    throw InvalidArgument("elimination: min_rho must be in [0, 0.8], got " + detail::format_number(params.min_rho));
  Rng rng(seed);
  PointSet<D> candidates = detail::vector_in_huge_pages<Point<D>>(static_cast<std::size_t>(m));
  for (Point<D>& p : candidates) p = uniform_point(rng, domain);
  if (params.progressive && params.levels && params.min_rho > 0.0)
    return eliminate_in_levels<D>(std::move(candidates), static_cast<std::size_t>(params.count), domain, params.weights,
                                  params.min_rho, seed, params.progress);
  PointSet<D> kept =
      eliminate(std::move(candidates), params.count, domain, params.weights, params.progressive, params.progress);
  const double spacing = params.min_rho * 2.0 * max_packing_radius(domain.volume(), params.count, D);
  return spread_closest_pairs<D>(std::move(kept), domain, spacing, params.progressive ? params.count / 2 : 0,
                                 params.progressive, seed);
}

template <int D>
PointSet<D> elimination(const EliminationParams& params, const SamplingConstraints<D>& constraints,
                        const Domain<D>& domain, std::uint64_t seed) {
  if (!constraints.fixed.empty())
    throw InvalidArgument("elimination: fixed points are not taken (bridson and dart-throwing keep them)");
  if (!constraints.active()) return elimination(params, domain, seed);
  domain.validate();
  validate(params.weights);
  if (!(params.candidates >= 1.0) || !std::isfinite(params.candidates))
    throw InvalidArgument("elimination: candidates must be a factor of at least 1, got " +
                          detail::format_number(params.candidates));
  const bool field = static_cast<bool>(constraints.radius);
  const double rmin = constraints.rmin, rmax = constraints.rmax;
  if (field) {
    require_radius(rmin, "rmin");
    require_radius(rmax, "rmax");
    if (!(rmin <= rmax))
      throw InvalidArgument("elimination: the radius range needs rmin <= rmax, got " + detail::format_number(rmin) +
                            " > " + detail::format_number(rmax));
  }
  // The weight of a point: 0 outside the mask, else (rmin / r(x))^D in (0, 1].
  auto weight_at = [&](const Point<D>& p) {
    if (constraints.inside && !constraints.inside(p)) return 0.0;
    if (!field) return 1.0;
    const double r = constraints.radius(p);
    if (std::isnan(r)) throw InvalidArgument("elimination: the radius field returned NaN");
    return std::pow(rmin / std::clamp(r, rmin, rmax), D);
  };
  std::uint64_t count = params.count;
  if (count == 0) {
    if (!field) throw InvalidArgument("elimination: count must be at least 1, got 0");
    // The weighted volume from a pilot of uniform draws (a stream of its own).
    constexpr int kPilot = 65536;
    Rng pilot(seed, {1});
    double sum = 0.0;
    for (int i = 0; i < kPilot; ++i) sum += weight_at(uniform_point(pilot, domain));
    if (sum == 0.0) throw InvalidArgument("elimination: the mask leaves no room in the domain");
    const double volume = domain.volume() * sum / kPilot;
    count = static_cast<std::uint64_t>(
        std::max(1.0, std::round(volume / packing_volume_per_point(rmin / (2.0 * kTypicalRho), D))));
  }
  const double m_real = std::ceil(params.candidates * static_cast<double>(count));
  if (m_real > static_cast<double>(kMaxCandidates))
    throw InvalidArgument("elimination: " + detail::format_number(m_real) + " candidates, more than 2^31");
  const auto m = static_cast<std::size_t>(m_real);
  const double bound = 64.0 * m_real * (field ? std::pow(rmax / rmin, D) : 1.0) + 1e6;
  Rng rng(seed);
  PointSet<D> candidates;
  candidates.reserve(m);
  std::vector<double> scale;
  if (field) scale.reserve(m);
  double draws = 0.0;
  while (candidates.size() < m) {
    if (++draws > bound)
      throw Failure("elimination: " + detail::format_number(bound) + " draws gave " +
                    std::to_string(candidates.size()) + " of " + std::to_string(m) +
                    " candidates (the mask leaves too little room)");
    const Point<D> p = uniform_point(rng, domain);
    const double w = weight_at(p);
    if (w > 0.0 && (w >= 1.0 || rng.uniform() < w)) {
      candidates.push_back(p);
      if (field) scale.push_back(std::pow(w, -1.0 / D));
    }
  }
  const double volume = domain.volume() * static_cast<double>(m) / draws;
  const auto n = static_cast<std::size_t>(count);
  const double d_max = 2.0 * max_packing_radius(volume, n, D);
  return eliminate_consuming<D>(std::move(candidates), scale, n, domain, d_max, params.weights, params.progressive,
                                params.progress);
}

#define PDS_INSTANTIATE(D)                                                                                           \
  template PointSet<D> elimination<D>(const EliminationParams&, const SamplingConstraints<D>&, const Domain<D>&,     \
                                      std::uint64_t);                                                                \
  template std::vector<std::uint32_t> detail::eliminate_indices<D>(                                                  \
      std::span<const Point<D>>, std::span<const double>, std::size_t, const Domain<D>&, double,                     \
      const EliminationWeights&, bool, int, const Progress&);                                                        \
  template std::vector<std::uint32_t> detail::eliminate_indices_by_heap<D>(                                          \
      std::span<const Point<D>>, std::span<const double>, std::size_t, const Domain<D>&, double,                     \
      const EliminationWeights&, bool, int);                                                                         \
  template PointSet<D> elimination<D>(const EliminationParams&, const Domain<D>&, std::uint64_t);                    \
  template PointSet<D> eliminate<D>(const PointSet<D>&, std::uint64_t, const Domain<D>&, const EliminationWeights&,  \
                                    bool, const Progress&);                                                          \
  template PointSet<D> eliminate<D>(PointSet<D>&&, std::uint64_t, const Domain<D>&, const EliminationWeights&, bool, \
                                    const Progress&);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
