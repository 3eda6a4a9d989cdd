// Maximal dart throwing, exact, parallel.
//
// M. S. Ebeida, S. A. Mitchell, A. Patney, A. A. Davidson, J. D. Owens, "A
// simple algorithm for maximal Poisson-disk sampling in high dimensions",
// Computer Graphics Forum 31(2), 2012: a flat grid of cells of edge just
// under r/sqrt(D) (a sample covers its own cell, so a cell holds one sample
// at most), darts uniform over the cells still open, a dart kept when no
// sample lies within r; then every open cell is split into 2^D sub-cells and
// a sub-cell is dropped when one disk covers it (its farthest corner is
// inside), level after level, until nothing is open. Each dart is uniform
// over a superset of the uncovered area, so the samples are those of plain
// sequential dart throwing run until no dart fits.
//
// How darts are ordered here. Darts form a Poisson process in space and time
// on the open area (every unit of a level, cell or sub-cell, receives a
// Poisson number of darts a window, with uniform times), so taken in time
// order they are the papers' sequence of independent uniform darts. Time is
// cut into windows; a window runs in four sweeps over contiguous chunks of
// the grid, each chunk on whichever thread is free:
//   1. draw the window's darts of every open unit and drop those within r of
//      a sample kept in an earlier window (a unit that such a sample covers
//      whole is closed);
//   2. publish the surviving darts (candidates) in the grid's cells;
//   3. decide each candidate: kept when no candidate of the window that is
//      earlier in time, within r and itself kept exists (a recursion on ever
//      earlier candidates, short in a short window; memoised);
//   4. commit the kept candidates, in cell order, as samples.
// The decision in 3 is a function of the candidates alone, so it is the same
// whichever thread evaluates it first (two threads may both evaluate one
// candidate and store the same answer), and the output depends neither on
// the thread count nor on the chunking. Ying, Xin, Sun and He ("An intrinsic
// algorithm for parallel Poisson disk sampling on arbitrary surfaces", IEEE
// TVCG 2013) resolve conflicts by random priorities in the same way.
//
// Why not ebeida.cpp: that sampler sweeps cells in memory order and settles
// each dart by recursively settling its neighbours' earlier darts, on one
// thread (two threads settling one neighbour would need a lock). Here every
// sweep is data-parallel without locks. The cost a sample is about the same
// (cachegrind at 10^5: 7,400 instructions against 8,100, docs/benchmarks.md):
// both need about 10 darts and 7.5 sub-cell refinements a sample to find the
// last gaps of the process, whatever each costs.
//
// Determinism: the darts of unit u in window w of level l come from hashes of
// (seed, l, w, u); times are 64-bit integers (a tie, probability 2^-64 a
// pair, goes to the lower cell). The samples are returned in commit order.
//
// Guarantees: minimum distance r (Domain::distance2, the analysis's function
// at the grid's seams); maximal up to a slack of 1e-12 r plus rounding (5e-10
// r where sub-cells reach the deepest level); the distribution of maximal
// dart throwing. A torus shorter than 2 reach + 2
// cells along an axis (a neighbour offset would meet the same cell twice)
// is handed to ebeida, the same process.
//
// Memory: a 4-byte state per grid cell, the samples, one window's
// candidates, and from level 1 the open sub-cells (packed by parent while
// they are many: Siblings).
#include "pds/samplers/maximal_darts.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "cover_cells.h"
#include "mapped_pages.h"
#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/grid_neighbourhood.h"
#include "pds/parallel.h"
#include "pds/portable_math.h"
#include "pds/rng.h"
#include "pds/samplers/ebeida.h"

namespace pds {
namespace {

// Window lengths in expected darts per unit (a cell at level 0, a sub-cell
// after). Short first windows keep the first, dense windows' candidate
// conflicts few; these only change the speed, never the distribution.
constexpr double kFirstLevelWindows[] = {0.125, 0.125, 0.25, 0.5, 0.5, 0.5};
constexpr double kLevelWindows[] = {0.5};
// Sub-cells are split down to edge 2^-31 cells (the codes' 32 bits; a thin
// axis, split later, to its delay's fewer bits); those
// still open then are dropped when their centre lies within r plus half a
// diagonal of a sample (every point within r + 5e-10 r of it), the others
// (whose inscribed ball is uncovered) take darts without further splitting,
// for at most kMaxFinalRounds levels' worth of windows.
constexpr int kMaxLevel = 31;
constexpr int kMaxFinalRounds = 1000;
constexpr int kMaxDepth = 20000;             // a chain of ever earlier candidates in one window
constexpr int kPoissonTerms = 24;            // P(K >= 24) below 1e-30 for the means above
constexpr std::size_t kSerialUnits = 16384;  // fewer open sub-cells: one thread
constexpr int kChunkBits = 8;                // at most 256 chunks
constexpr std::size_t kMaxChunkCandidates = (std::size_t{1} << 22) - 1;
constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL;

/// Poisson(mean) by inversion of a 53-bit uniform (probabilities by
/// multiplication from the portable e^-mean, so the same on every platform).
struct PoissonTable {
  double cdf[kPoissonTerms];
  explicit PoissonTable(double mean) {
    double p = exp_neg(mean), sum = p;
    cdf[0] = sum;
    for (int k = 1; k < kPoissonTerms; ++k) {
      p *= mean / k;
      sum += p;
      cdf[k] = sum;
    }
    zero_below = static_cast<std::uint64_t>(std::ceil(std::ldexp(cdf[0], 53)));
  }
  std::uint64_t zero_below = 0;  // (bits >> 11) below this: none (the same test as u < cdf[0])
  int draw(std::uint64_t bits) const {
    if ((bits >> 11) < zero_below) return 0;
    const double u = uniform_from_bits(bits);
    int k = 0;
    while (k < kPoissonTerms - 1 && u >= cdf[k]) ++k;
    return k;
  }
};

template <int D>
class MaximalDartsSampler {
  static constexpr std::int32_t kOpen = -1, kCovered = -2, kMarker = -3;  // marker: kMarker - (local << 8 | chunk)
  static constexpr std::uint8_t kUndecided = 0, kKept = 1, kRejected = 2;
  static constexpr int kChildren = 1 << D;
  using Coords = std::array<int, D>;
  using Stencil = typename GridNeighbourhood<D>::Stencil;

  struct Candidate {
    Point<D> x;
    std::uint64_t time;
    std::uint32_t cell;
    std::uint8_t status;  // read and written through std::atomic_ref in sweep 3
    bool border;          // the cell's stencil crosses the grid's edge
  };

  /// A sub-cell's position in its cell, axis_bits(a, level) bits along axis a.
  using Code = std::array<std::uint32_t, D>;

  /// An open sub-cell: its cell and its code.
  struct Unit {
    std::uint32_t cell;  // kDead once a sample covers it whole
    Code code;
  };
  static constexpr std::uint32_t kDead = 0xffffffffu;

  /// The open children of one parent, in 8 bytes: the cell (32 bits), which
  /// of the 2^D children are open (one bit each), and the first child's code
  /// (kSiblingBits bits an axis). Levels 1 to kSiblingBits, among them those
  /// that hold millions of open sub-cells, keep them so: 1.8 a record at
  /// levels 1-2 at 10^6 in 2D, 4.6 bytes an open sub-cell where a Unit takes
  /// 12. Deeper levels, which hold a few thousand, keep Units.
  struct Siblings {
    std::uint64_t bits;
  };
  static constexpr int kSiblingBits = (32 - kChildren) / D;  // 14 in 2D, 8 in 3D
  static_assert(kSiblingBits >= 1 && D * kSiblingBits + kChildren <= 32);
  static constexpr std::uint64_t kAxisMask = (std::uint64_t{1} << kSiblingBits) - 1;

  static Siblings make_siblings(std::uint32_t cell, unsigned open, const Code& first) {
    std::uint64_t bits = std::uint64_t{cell} << 32 | std::uint64_t{open} << (D * kSiblingBits);
    for (int a = 0; a < D; ++a) bits |= std::uint64_t{first[a]} << (a * kSiblingBits);
    return {bits};
  }
  static std::uint32_t cell_of(Siblings g) { return static_cast<std::uint32_t>(g.bits >> 32); }
  static unsigned open_of(Siblings g) {
    return static_cast<unsigned>(g.bits >> (D * kSiblingBits)) & ((1u << kChildren) - 1);
  }
  static Code code_of(Siblings g, int child) {
    Code code;
    for (int a = 0; a < D; ++a)
      code[a] = static_cast<std::uint32_t>((g.bits >> (a * kSiblingBits)) & kAxisMask) + ((child >> a) & 1);
    return code;
  }
  static void close_child(Siblings& g, int child) { g.bits &= ~(std::uint64_t{1} << (D * kSiblingBits + child)); }

  struct Chunk {
    std::uint32_t begin = 0, end = 0;  // cells [begin, end)
    std::vector<Candidate> candidates;
    std::vector<std::uint32_t> closed;  // cells found covered, applied after the sweep
    // Open sub-cells (level >= 1), in cell order: one of the two is empty.
    std::vector<Siblings> siblings;
    std::vector<Unit> units;
    std::size_t kept = 0, base = 0;
  };

 public:
  MaximalDartsSampler(const MaximalDartsParams& params, const Domain<D>& domain, std::uint64_t seed)
      : domain_(domain),
        r_(params.radius),
        r2_(params.radius * params.radius),
        threads_(params.threads),
        progress_(params.progress),
        reporter_(params.progress, typical_count(sizing_volume(domain, params.radius), params.radius, D)) {
    detail::CoverCells<D> grid("maximal-darts", domain, r_);
    if (grid.count > static_cast<double>(1 << 30))
      throw InvalidArgument("maximal-darts: radius " + detail::format_number(r_) +
                            " needs more than 2^30 grid cells for this domain");
    grid.make_corners(domain);
    n_ = grid.n;
    cover2_ = grid.cover2;
    corners_ = std::move(grid.corners);
    hood_ = GridNeighbourhood<D>(domain, n_);
    delay_ = detail::quadtree_axis_delays<D>(domain, n_, kMaxLevel);
    // The own cell, then every cell that can hold a sample closer than r to a
    // point of the cell, nearest first (a rejected dart stops early).
    std::vector<Coords> steps{Coords{}};
    for (const Coords& step : hood_.stencil_within(r_, 1e-6).steps) steps.push_back(step);
    near_ = hood_.stencil(std::move(steps));
    for (int a = 0; a < D; ++a)
      if (domain.periodic && n_[a] < 2 * near_.reach[a] + 2) fallback_ = true;
    if (fallback_) return;

    const std::size_t size = hood_.size();
    // Written whole here, so in huge pages where offered (mapped_pages.h).
    state_ = detail::map_zeroed<std::int32_t>(size, detail::Pages::kHuge);
    std::fill_n(state_.get(), size, kOpen);
    const std::size_t chunks = std::clamp<std::size_t>(size / 2048, 1, std::size_t{1} << kChunkBits);
    chunks_.resize(chunks);
    for (std::size_t k = 0; k < chunks; ++k) {
      chunks_[k].begin = static_cast<std::uint32_t>(size * k / chunks);
      chunks_[k].end = static_cast<std::uint32_t>(size * (k + 1) / chunks);
    }
    // Virtual until written: the typical count with a margin (a box packs a
    // little denser at its faces); past it the vector grows as usual.
    const double expected = typical_count(sizing_volume(domain, r_), r_, D) * 1.6 + 1024.0;
    samples_.reserve(static_cast<std::size_t>(std::min(expected, static_cast<double>(size))));
    detail::advise_huge_pages(samples_);
    key_ = mix64(seed ^ 0x6d6178696d616c64ULL);
  }

  PointSet<D> run(std::uint64_t seed) {
    if (fallback_) return ebeida<D>({r_, std::numeric_limits<std::uint64_t>::max(), progress_}, domain_, seed);
    for (level_ = 0;; ++level_) {
      if (level_ > kMaxLevel + kMaxFinalRounds)
        throw Failure("maximal-darts: " + std::to_string(open_units()) + " sub-cells still open after " +
                      std::to_string(kMaxLevel) + " levels of refinement and " + std::to_string(kMaxFinalRounds) +
                      " rounds of darts (numerical breakdown)");
      for (int a = 0; a < D; ++a) scale_[a] = std::ldexp(1.0, -axis_bits(a, level_));
      if (level_ > 0) {
        refine();
        if (open_units() == 0) break;
      }
      const auto windows =
          level_ == 0 ? std::span<const double>(kFirstLevelWindows) : std::span<const double>(kLevelWindows);
      for (std::size_t w = 0; w < windows.size(); ++w) run_window(w, windows[w]);
    }
    reporter_.finish();
    return std::move(samples_);
  }

 private:
  /// Times axis a has been halved at `level` (none while it waits; no more
  /// past kMaxLevel, where units are kept as they are).
  int axis_bits(int a, int level) const { return std::max(0, std::min(level, kMaxLevel) - delay_[a]); }

  std::size_t open_units() const {
    std::size_t n = 0;
    for (const Chunk& chunk : chunks_) {
      n += chunk.units.size();
      for (const Siblings g : chunk.siblings) n += static_cast<std::size_t>(std::popcount(open_of(g)));
    }
    return n;
  }

  /// Runs body(k, chunk) over the chunks on the pool, or on this thread when
  /// the sweep's work is the open sub-cells and they are few: the deep levels
  /// hold a few thousand, less work than waking the pool for each sweep (the
  /// output does not depend on it). Level 0's sweeps, and the refinement
  /// that splits level 0's open cells, work on the grid.
  template <class Body>
  void for_chunks(bool on_units, Body&& body) {
    const int threads = on_units && open_units() < kSerialUnits ? 1 : threads_;
    parallel_for(0, chunks_.size(), 1, threads, [&](std::size_t b, std::size_t e) {
      for (std::size_t k = b; k < e; ++k) body(k, chunks_[k]);
    });
  }

  bool interior(const Coords& c) const {
    for (int a = 0; a < D; ++a)
      if (c[a] < near_.reach[a] || c[a] + near_.reach[a] >= n_[a]) return false;
    return true;
  }

  static double distance2_plain(const Point<D>& x, const Point<D>& y) {
    double d2 = 0.0;
    for (int a = 0; a < D; ++a) d2 += (x[a] - y[a]) * (x[a] - y[a]);
    return d2;
  }

  /// A sample kept in an earlier window within r of x (in the cell `cell` at
  /// c), or -1.
  std::int32_t blocker(const Point<D>& x, std::size_t cell, const Coords& c, bool border) const {
    if (!border) {
      for (const std::ptrdiff_t off : near_.linear) {
        const std::int32_t s = state_[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(cell) + off)];
        if (s >= 0 && distance2_plain(x, samples_[static_cast<std::size_t>(s)]) < r2_) return s;
      }
      return -1;
    }
    std::int32_t found = -1;
    hood_.any(near_, c, cell, [&](std::size_t n) {
      const std::int32_t s = state_[n];
      if (s >= 0 && domain_.distance2(x, samples_[static_cast<std::size_t>(s)]) < r2_) {
        found = s;
        return true;
      }
      return false;
    });
    return found;
  }

  /// Whether every corner of the box [lo, lo + edge] is closer to s than r
  /// minus the slack (the farther face along each axis). On a torus both
  /// faces must see the same image of s, else the box is reported open.
  bool covers_box(const Point<D>& s, const Point<D>& lo, const std::array<double, D>& edge) const {
    double far2 = 0.0;
    for (int a = 0; a < D; ++a) {
      const double near_face = domain_.delta(lo[a], s[a], a), far_face = domain_.delta(lo[a] + edge[a], s[a], a);
      if (domain_.periodic && !(std::abs(near_face - far_face - edge[a]) < 0.5 * edge[a])) return false;
      far2 += std::max(near_face * near_face, far_face * far_face);
    }
    return far2 < cover2_;
  }

  /// Draws the darts of one unit (a cell at level 0: code all zero) for this
  /// window and keeps the candidates; returns false when a sample covers the
  /// unit whole.
  bool throw_darts(Chunk& chunk, std::size_t cell, const Coords* coords, const Code& code, std::uint64_t stream,
                   const PoissonTable& poisson) {
    std::uint64_t counter = stream;
    const auto next = [&counter] { return mix64(counter += kGolden); };
    const int darts = poisson.draw(next());
    if (darts == 0) return true;
    const Coords c = coords ? *coords : hood_.coords(cell);
    const bool border = !interior(c);
    Point<D> lo, hi;
    std::array<double, D> edge;
    for (int a = 0; a < D; ++a) {
      const double cell_lo = corners_[a][static_cast<std::size_t>(c[a])];
      hi[a] = corners_[a][static_cast<std::size_t>(c[a]) + 1];
      edge[a] = (hi[a] - cell_lo) * scale_[a];  // exact: a power of 2
      lo[a] = cell_lo + static_cast<double>(code[a]) * edge[a];
    }
    for (int k = 0; k < darts; ++k) {
      const std::uint64_t time = next();
      Point<D> x;
      for (int a = 0; a < D; ++a) {
        x[a] = lo[a] + uniform_from_bits(next()) * edge[a];
        if (!(x[a] < hi[a])) x[a] = std::nextafter(hi[a], lo[a]);
      }
      const std::int32_t s = blocker(x, cell, c, border);
      if (s < 0) {
        chunk.candidates.push_back(Candidate{x, time, static_cast<std::uint32_t>(cell), kUndecided, border});
      } else if (covers_box(samples_[static_cast<std::size_t>(s)], lo, edge)) {
        return false;  // no candidate came before: that sample blocks the whole unit
      }
    }
    return true;
  }

  std::uint64_t window_key(std::size_t window) const {
    return mix64(key_ + mix64(static_cast<std::uint64_t>(level_) * 64 + window));
  }

  void run_window(std::size_t window, double length) {
    const PoissonTable poisson(length);
    const std::uint64_t key = window_key(window);
    // 1. Darts, filtered against the samples of earlier windows.
    for_chunks(level_ > 0, [&](std::size_t, Chunk& chunk) {
      chunk.candidates.clear();
      chunk.closed.clear();
      if (level_ == 0) {
        const Code zero{};
        Coords c = hood_.coords(chunk.begin);
        for (std::size_t cell = chunk.begin; cell < chunk.end; ++cell) {
          if (state_[cell] == kOpen && !throw_darts(chunk, cell, &c, zero, mix64(key ^ (cell * kGolden)), poisson))
            chunk.closed.push_back(static_cast<std::uint32_t>(cell));
          for (int a = 0; a < D && ++c[a] == n_[a]; ++a) c[a] = 0;
        }
      } else {
        // Returns false when the unit is found covered.
        const auto throw_on = [&](std::uint32_t cell, const Code& code) {
          std::uint64_t stream = mix64(key ^ (cell * kGolden));
          for (int a = 0; a < D; ++a) stream = mix64(stream + code[a]);
          return throw_darts(chunk, cell, nullptr, code, stream, poisson);
        };
        for (Siblings& g : chunk.siblings)
          for (unsigned open = open_of(g); open != 0; open &= open - 1) {
            const int child = std::countr_zero(open);
            if (!throw_on(cell_of(g), code_of(g, child))) close_child(g, child);
          }
        for (Unit& unit : chunk.units)
          if (!throw_on(unit.cell, unit.code)) unit.cell = kDead;
      }
      if (chunk.candidates.size() > kMaxChunkCandidates)
        throw Failure("maximal-darts: more than " + std::to_string(kMaxChunkCandidates) +
                      " candidates in one chunk of the grid");
    });
    // 2. Publish: each cell with candidates points at its first one.
    for_chunks(level_ > 0, [&](std::size_t k, Chunk& chunk) {
      for (const std::uint32_t cell : chunk.closed) state_[cell] = kCovered;
      const auto& cands = chunk.candidates;
      for (std::size_t j = 0; j < cands.size(); ++j)
        if (j == 0 || cands[j - 1].cell != cands[j].cell)
          state_[cands[j].cell] = kMarker - static_cast<std::int32_t>((j << kChunkBits) | k);
    });
    // 3. Decide.
    for_chunks(level_ > 0, [&](std::size_t, Chunk& chunk) {
      std::size_t kept = 0;
      for (Candidate& d : chunk.candidates) kept += decide(d, 0) ? 1 : 0;
      chunk.kept = kept;
    });
    // 4. Commit, in chunk order.
    std::size_t total = samples_.size();
    for (Chunk& chunk : chunks_) {
      chunk.base = total;
      total += chunk.kept;
      reporter_.update(static_cast<double>(total));  // between parallel phases: may throw Cancelled
    }
    samples_.resize(total);
    for_chunks(level_ > 0, [&](std::size_t, Chunk& chunk) {
      std::size_t next = chunk.base;
      for (const Candidate& d : chunk.candidates) {
        std::int32_t& state = state_[d.cell];
        if (d.status == kKept) {
          samples_[next] = d.x;
          state = static_cast<std::int32_t>(next++);
        } else if (state <= kMarker) {
          state = kOpen;
        }
      }
      if (level_ > 0) {
        std::erase_if(chunk.siblings, [&](Siblings g) { return open_of(g) == 0 || state_[cell_of(g)] >= 0; });
        std::erase_if(chunk.units, [&](const Unit& unit) { return unit.cell == kDead || state_[unit.cell] >= 0; });
      }
      // The first windows' candidates are the most; later ones need far less
      // room. From level 1 a level has one window, and its candidates are
      // freed with it: the next level's sub-cells then reuse their heap (held
      // until the next window, they left holes that raised the peak by 2.5 MB
      // at 10^6 in 2D).
      if (level_ > 0 || chunk.candidates.capacity() > 4 * chunk.candidates.size() + 1024) {
        chunk.candidates.clear();
        chunk.candidates.shrink_to_fit();
      }
    });
  }

  /// Whether candidate d is kept: no earlier candidate of the window within r
  /// is kept. Memoised in d.status; any thread may evaluate any candidate.
  bool decide(Candidate& d, int depth) {
    std::atomic_ref<std::uint8_t> status(d.status);
    const std::uint8_t known = status.load(std::memory_order_relaxed);
    if (known != kUndecided) return known == kKept;
    if (depth > kMaxDepth)
      throw Failure("maximal-darts: a chain of more than " + std::to_string(kMaxDepth) + " conflicting darts");
    const auto blocked_by = [&](std::size_t cell) {
      const std::int32_t s = state_[cell];
      if (s > kMarker) return false;
      const auto m = static_cast<std::uint32_t>(kMarker - s);
      auto& cands = chunks_[m & ((1u << kChunkBits) - 1)].candidates;
      for (std::size_t j = m >> kChunkBits; j < cands.size() && cands[j].cell == cell; ++j) {
        Candidate& e = cands[j];
        if (&e == &d) continue;
        const bool earlier =
            e.time < d.time || (e.time == d.time && (e.cell < d.cell || (e.cell == d.cell && &e < &d)));
        if (!earlier) continue;
        const double d2 = d.border ? domain_.distance2(d.x, e.x) : distance2_plain(d.x, e.x);
        if (d2 < r2_ && decide(e, depth + 1)) return true;
      }
      return false;
    };
    bool blocked = false;
    if (!d.border) {
      for (const std::ptrdiff_t off : near_.linear)
        if (blocked_by(static_cast<std::size_t>(static_cast<std::ptrdiff_t>(d.cell) + off))) {
          blocked = true;
          break;
        }
    } else {
      blocked = hood_.any(near_, hood_.coords(d.cell), d.cell, blocked_by);
    }
    status.store(blocked ? kRejected : kKept, std::memory_order_relaxed);
    return !blocked;
  }

  /// Splits every open unit into 2^D children for the level now starting
  /// (halves along the axes whose delay is over; one along the others) and
  /// keeps those that no single disk covers; a cell left with none is closed.
  void refine() {
    const int parent_level = level_ - 1;
    // Past the deepest level the units are kept as they are, less those whose
    // centre a disk covers.
    const bool final = level_ > kMaxLevel;
    // The axes halved at this level; children along the others are not made
    // (they start covered).
    std::array<bool, D> halved;
    unsigned waiting = 0;
    bool as_siblings = !final;  // the children's codes fit Siblings
    for (int a = 0; a < D; ++a) {
      halved[a] = axis_bits(a, level_) > axis_bits(a, parent_level);
      as_siblings = as_siblings && axis_bits(a, level_) <= kSiblingBits;
    }
    for (int child = 0; child < kChildren; ++child)
      for (int a = 0; a < D; ++a)
        if ((child >> a) & 1 && !halved[a]) waiting |= 1u << child;
    // Only samples that can cover a whole child: along each axis the child's
    // far side lies at least a child edge (half of one in the same column)
    // beyond the gap between the cells. At level 1 that leaves the 3^D block.
    const Stencil cover = hood_.filter(near_, [&](const Coords& off) {
      double least2 = 0.0;
      for (int a = 0; a < D; ++a) {
        const double edge = hood_.edge(a), child = edge * scale_[a];
        const double least = off[a] == 0 ? 0.5 * child : (std::abs(off[a]) - 1) * edge + child;
        least2 += least * least;
      }
      return least2 < r2_;
    });
    for_chunks(parent_level > 0, [&](std::size_t, Chunk& chunk) {
      std::vector<Siblings> sibling_children;
      std::vector<Unit> unit_children;
      std::vector<Code> parents;                // the open units of one cell
      std::vector<std::array<double, D>> near;  // nearby samples' images, relative to the cell's lower corner
      chunk.closed.clear();
      const auto split_parents = [&](std::uint32_t cell) {
        const Coords c = hood_.coords(cell);
        std::array<double, D> cell_lo, edge;
        for (int a = 0; a < D; ++a) {
          cell_lo[a] = corners_[a][static_cast<std::size_t>(c[a])];
          edge[a] = (corners_[a][static_cast<std::size_t>(c[a]) + 1] - cell_lo[a]) * scale_[a];
        }
        near.clear();
        hood_.for_each_image(final ? near_ : cover, c, cell, [&](std::size_t n, const Coords& periods) {
          if (state_[n] < 0) return;
          const Point<D>& s = samples_[static_cast<std::size_t>(state_[n])];
          std::array<double, D> d;
          for (int a = 0; a < D; ++a) d[a] = s[a] - cell_lo[a] + periods[a] * domain_.extent(a);
          near.push_back(d);
        });
        bool any_open = false;
        for (const Code& code : parents) {
          if (final) {
            // Within r + half a diagonal of a sample, every point of the unit
            // lies within r + a diagonal (5e-10 r); otherwise the unit's
            // inscribed ball is uncovered and darts find it.
            double diagonal2 = 0.0;
            for (int a = 0; a < D; ++a) diagonal2 += edge[a] * edge[a];
            const double reach = r_ + 0.5 * std::sqrt(diagonal2);
            const bool covered = std::any_of(near.begin(), near.end(), [&](const std::array<double, D>& d) {
              double d2 = 0.0;
              for (int a = 0; a < D; ++a) {
                const double gap = d[a] - (static_cast<double>(code[a]) + 0.5) * edge[a];
                d2 += gap * gap;
              }
              return d2 < reach * reach;
            });
            if (!covered) unit_children.push_back(Unit{cell, code});
            any_open = any_open || !covered;
            continue;
          }
          // The children's faces along each axis, relative to the cell's corner
          // (an axis not split: the parent's two faces, the second twice).
          std::array<std::array<double, 3>, D> face;
          Code first;
          for (int a = 0; a < D; ++a) {
            first[a] = halved[a] ? code[a] * 2 : code[a];
            for (int f = 0; f < 3; ++f)
              face[a][f] = static_cast<double>(std::uint64_t{first[a]} +
                                               static_cast<std::uint64_t>(halved[a] ? f : std::min(f, 1))) *
                           edge[a];
          }
          unsigned covered = waiting;
          for (const auto& d : near) {
            // Every child has the point of the middle faces as a corner (the
            // parent's centre; along an axis not split, its upper face): a
            // disk that misses it covers no child.
            std::array<double, D> q1;
            double centre2 = 0.0;
            for (int a = 0; a < D; ++a) {
              q1[a] = (d[a] - face[a][1]) * (d[a] - face[a][1]);
              centre2 += q1[a];
            }
            if (!(centre2 < cover2_)) continue;
            std::array<std::array<double, 2>, D> far;
            for (int a = 0; a < D; ++a) {
              const double q0 = (d[a] - face[a][0]) * (d[a] - face[a][0]);
              const double q2 = (d[a] - face[a][2]) * (d[a] - face[a][2]);
              far[a] = {std::max(q0, q1[a]), std::max(q1[a], q2)};
            }
            for (int child = 0; child < kChildren; ++child) {
              double far2 = 0.0;
              for (int a = 0; a < D; ++a) far2 += far[a][(child >> a) & 1];
              if (far2 < cover2_) covered |= 1u << child;
            }
            if (covered == (1u << kChildren) - 1) break;
          }
          const unsigned open = ~covered & ((1u << kChildren) - 1);
          if (open == 0) continue;
          any_open = true;
          if (as_siblings) {
            sibling_children.push_back(make_siblings(cell, open, first));
            continue;
          }
          for (int child = 0; child < kChildren; ++child) {
            if (!((open >> child) & 1)) continue;
            Unit unit{cell, {}};
            for (int a = 0; a < D; ++a) unit.code[a] = first[a] + static_cast<std::uint32_t>((child >> a) & 1);
            unit_children.push_back(unit);
          }
        }
        if (!any_open) chunk.closed.push_back(cell);
      };
      // The parents cell by cell, in the order of their units.
      if (parent_level == 0) {
        parents.assign(1, Code{});
        for (std::size_t cell = chunk.begin; cell < chunk.end; ++cell)
          if (state_[cell] == kOpen) split_parents(static_cast<std::uint32_t>(cell));
      }
      const std::span<const Siblings> groups(chunk.siblings);
      for (std::size_t i = 0; i < groups.size();) {
        parents.clear();
        std::size_t j = i;
        for (; j < groups.size() && cell_of(groups[j]) == cell_of(groups[i]); ++j)
          for (unsigned open = open_of(groups[j]); open != 0; open &= open - 1)
            parents.push_back(code_of(groups[j], std::countr_zero(open)));
        split_parents(cell_of(groups[i]));
        i = j;
      }
      const std::span<const Unit> units(chunk.units);
      for (std::size_t i = 0; i < units.size();) {
        parents.clear();
        std::size_t j = i;
        for (; j < units.size() && units[j].cell == units[i].cell; ++j) parents.push_back(units[j].code);
        split_parents(units[i].cell);
        i = j;
      }
      // A vector grown by doubling would hold up to twice the open units.
      chunk.siblings = std::move(sibling_children);
      chunk.siblings.shrink_to_fit();
      chunk.units = std::move(unit_children);
      chunk.units.shrink_to_fit();
    });
    for (Chunk& chunk : chunks_)
      for (const std::uint32_t cell : chunk.closed) state_[cell] = kCovered;
    const std::size_t open = open_units();
    // Open sub-cells peak near one per grid cell (level 1 or 2): a level that
    // leaves far more would keep growing 2^D-fold with each further one.
    if (open > 4 * hood_.size() + 4096)
      throw Failure("maximal-darts: " + std::to_string(open) + " sub-cells still open at refinement level " +
                    std::to_string(level_) + ", more than 4 per grid cell (numerical breakdown)");
  }

  const Domain<D>& domain_;
  double r_, r2_, cover2_ = 0.0;
  int threads_;
  Progress progress_;  // for the fallback to ebeida
  ProgressReporter reporter_;
  bool fallback_ = false;
  int level_ = 0;
  std::array<int, D> delay_{};     // levels an axis waits before it is split (detail::quadtree_axis_delays)
  std::array<double, D> scale_{};  // a sub-cell's edge over its cell's along each axis, 2^-axis_bits
  std::uint64_t key_ = 0;
  Coords n_{};
  GridNeighbourhood<D> hood_;
  std::array<std::vector<double>, D> corners_;  // cell boundaries per axis, n + 1 each
  Stencil near_;                                // the own cell, then every cell that can hold a sample within r
  detail::MappedArray<std::int32_t> state_;     // per cell: >= 0 a sample, kOpen, kCovered, or a candidate marker
  std::vector<Chunk> chunks_;
  PointSet<D> samples_;
};

}  // namespace

template <int D>
PointSet<D> maximal_darts(const MaximalDartsParams& params, const Domain<D>& domain, std::uint64_t seed) {
  domain.validate();
  require_radius_budget(domain, params.radius, params.max_points);
  if (params.threads < 0)
    throw InvalidArgument("maximal-darts: threads must be 0 (all) or positive, got " + std::to_string(params.threads));
  return MaximalDartsSampler<D>(params, domain, seed).run(seed);
}

template PointSet<2> maximal_darts<2>(const MaximalDartsParams&, const Domain<2>&, std::uint64_t);
template PointSet<3> maximal_darts<3>(const MaximalDartsParams&, const Domain<3>&, std::uint64_t);

}  // namespace pds
