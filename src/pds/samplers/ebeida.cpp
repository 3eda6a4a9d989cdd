// M. S. Ebeida, S. A. Mitchell, A. Patney, A. A. Davidson, J. D. Owens, "A
// simple algorithm for maximal Poisson-disk sampling in high dimensions",
// Computer Graphics Forum 31(2), 2012; and M. S. Ebeida, A. A. Davidson,
// A. Patney, P. M. Knupp, S. A. Mitchell, J. D. Owens, "Efficient maximal
// Poisson-disk sampling", ACM SIGGRAPH 2011.
//
// Method, as in the papers:
// - A background grid of cells of edge s < r/sqrt(D): a sample covers its own
//   cell, so a cell holds one sample at most, and a dart only needs the samples
//   of the few cells within r of its own.
// - Darts land uniformly on the cells still open; a dart at distance >= r from
//   every sample becomes a sample. After a while the open area is a small part
//   of the open cells, so every open cell is split into 2^D sub-cells and a
//   sub-cell is dropped when one disk covers it (all its corners inside the
//   disk): a flat quadtree, refined a level at a time, until nothing is open.
//   Every dart is uniform over a superset of the uncovered area, so the kept
//   samples are those of plain dart throwing run until no dart fits.
//
// What we add: the papers draw each dart from the whole list of open cells,
// which makes every dart a cache miss on a large grid. Here each open cell has
// its own stream of darts, a Poisson process in time of rate one per open
// sub-cell (all sub-cells of a level have the same size), and a dart is kept
// if no sample kept EARLIER IN TIME lies within r. The superposition of the
// cells' streams is one Poisson process on the open area, so ordering the
// darts by time is exactly the papers' sequence of uniform darts; but the
// decision for a dart only needs the darts of nearby cells with earlier
// times, so the grid can be swept in memory order: a dart first asks its
// neighbours to settle their own darts up to its time (recursively, with
// ever earlier times), then checks their samples. Time runs in windows of 1/2
// (a neighbour chain in one window is short) and a level runs for a fixed time
// before it is refined; neither choice changes the distribution.
//
// Determinism: dart j of cell c at level l comes from a hash of (seed, l, c,
// j); the waiting times use the portable logarithm of pds/portable_math.h,
// so a seed gives the same samples on every platform.
//
// Guarantees: minimum distance r (checked with Domain::distance2, the same
// function the analysis uses); maximal up to a slack of 1e-12 r plus rounding
// (a sub-cell is dropped only when its corners are within r minus that slack
// of one sample); the distribution is maximal dart throwing's.
//
// Complexity: O(1) expected work per cell and level, and the open cells shrink
// geometrically from level to level: O(N) time and memory (measured in
// docs/benchmarks.md). Memory: a 4-byte state per grid cell (about 2.9 cells
// per sample in 2D) plus the open cells of the current level.
#include "pds/samplers/ebeida.h"

#include <algorithm>
#include <bitset>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "block_vector.h"
#include "cover_cells.h"
#include "mapped_pages.h"
#include "union_cover.h"
#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/grid.h"
#include "pds/grid_neighbourhood.h"
#include "pds/portable_math.h"
#include "pds/rng.h"

namespace pds {
namespace {

// A sub-cell's position in its cell: D coordinates, axis a of `level` bits
// less its delay (detail::quadtree_axis_delays; none but on thin axes), each
// after the bits of the axes before it.
using Code = u128;
using SubCellCodes = detail::NarrowableBlockVector<Code, std::uint32_t>;
// Deepest level: 63 in 2D, 41 in 3D (codes of up to 126 bits), sub-cells of edge below 1e-12 r,
// the slack of the coverage test. A Voronoi vertex of the samples at distance r - delta from
// them needs sub-cells of diagonal below delta to close: about log2(r / delta) levels (15 are
// common at 10^5 samples).
template <int D>
constexpr int kMaxLevel = 128 / D - 1;
constexpr double kFirstLevelTime = 1.5;       // expected darts per cell at level 0 (tuned, docs/ebeida.md)
constexpr double kLevelTime = 0.5;            // expected darts per sub-cell at every further level
constexpr double kWindow = 0.5;               // darts are settled window by window in time
constexpr std::uint32_t kReportEvery = 1024;  // open cells settled between progress reports
constexpr int kMaxDepth = 2000;  // a chain of ever earlier darts (measured: 14 at 10^6); keeps the stack small
// Open sub-cells per grid cell at any level (measured peaks: 0.8 in 2D, 1.6
// in 3D, 4.5 in 4D, where a cell has 16 children; unit torus, 2,000 and
// 20,000 samples).
template <int D>
constexpr std::size_t kMaxSubsPerCell = D <= 3 ? 4 : std::size_t{1} << D;
constexpr double kInf = std::numeric_limits<double>::infinity();
// From here on the sampler lists open sub-cells and draws darts in sequence
// (EbeidaListSampler); below, darts are swept in time order (EbeidaSampler).
constexpr int kFirstListedDim = 5;

template <int D>
class EbeidaSampler {
  // Grid cell states: >= 0 a sample index, kCovered (no sample and no dart can
  // land), and <= kOpen an open cell whose slot is kOpen - state.
  static constexpr std::int32_t kCovered = -1;
  static constexpr std::int32_t kOpen = -2;
  static constexpr int kChildren = 1 << D;
  using Stencil = typename GridNeighbourhood<D>::Stencil;

  /// The open sub-cells of a slot: subs_[begin, begin + count) (level 0: the
  /// whole cell, nothing stored, so a slot there takes 16 bytes).
  struct Subs {
    std::uint32_t begin, count;
  };

  struct Open {
    std::uint32_t cell;
    std::uint32_t darts;  // darts of this cell drawn so far at this level
    double next_time;     // time of its next dart; infinity once settled
  };

 public:
  EbeidaSampler(const EbeidaParams& params, const Domain<D>& domain, std::uint64_t seed)
      : domain_(domain),
        seed_(seed),
        r2_(params.radius * params.radius),
        progress_(params.progress, typical_count(sizing_volume(domain, params.radius), params.radius, D)) {
    const double r = params.radius;
    detail::CoverCells<D> grid("ebeida", domain, r);
    if (grid.count > static_cast<double>(1 << 30))
      throw InvalidArgument("ebeida: radius " + detail::format_number(r) +
                            " needs more than 2^30 grid cells for this domain");
    grid.make_corners(domain);
    n_ = grid.n;
    cover2_ = grid.cover2;
    corners_ = std::move(grid.corners);
    hood_ = GridNeighbourhood<D>(domain, n_);
    const std::size_t stride = hood_.size();
    // The cells that can hold a sample closer than r to a point of a cell: the
    // gap between the two cells along each axis is (|offset| - 1) edges;
    // nearest cells first (a rejected dart usually stops at the first few).
    // On a torus whose period is short next to r, offsets beyond half the
    // cells revisit cells but reach other periodic images of their samples;
    // refine() needs every image that can cover a sub-cell, so the stencil is
    // not cut at half a period.
    delay_ = detail::quadtree_axis_delays<D>(domain, n_, kMaxLevel<D>);
    set_level(0);
    near_ = hood_.stencil_within(r, 1e-6);
    // The state grid, the slots (one a cell) and the samples in huge pages
    // where offered: they are written all over at once, and their 4 KiB page
    // faults (and the samples' doubling copies) were a fifth of the run at
    // 10^6 in 2D. The samples get room for 1.1 times the usual count at this
    // radius: sets measured held 0.5-0.85 of that room in 2D-4D (the pages
    // past them are never touched), a thin strip 1.13 (one doubling).
    state_ = detail::vector_in_huge_pages<std::int32_t>(stride, kOpen);
    open_ = detail::vector_in_huge_pages<Open>(stride);
    reserved_ = static_cast<std::size_t>(1.1 * typical_count(sizing_volume(domain, r), r, D)) + 16;
    samples_.reserve(reserved_);
    detail::advise_huge_pages(samples_);
    const std::uint64_t key = key_ = level_key(0);
    for (std::uint32_t c = 0; c < stride; ++c) {
      open_[c] = Open{c, 0, 0.0};
      state_[c] = kOpen - static_cast<std::int32_t>(c);
      open_[c].next_time = waiting_time(key, c, 0, 1);
    }
  }

  PointSet<D> run() {
    double start = 0.0;
    for (level_ = 0; !open_.empty(); ++level_) {
      if (level_ > kMaxLevel<D>)
        throw Failure("ebeida: " + std::to_string(open_.size()) + " cells still open after " +
                      std::to_string(kMaxLevel<D>) + " levels of refinement (numerical breakdown)");
      set_level(level_);
      if (level_ > 0) refine(start);
      if (open_.empty()) break;
      const double end = start + (level_ == 0 ? kFirstLevelTime : kLevelTime);
      for (double until = start + kWindow;; until += kWindow) {
        until = std::min(until, end);
        for (std::uint32_t slot = 0; slot < open_.size(); ++slot) {
          if (open_[slot].next_time < until) settle(slot, until, 0);
          if ((slot & (kReportEvery - 1)) == 0) progress_.update(static_cast<double>(samples_.size()));
        }
        compact();
        if (until >= end) break;
      }
      start = end;
      if (samples_.size() > sorted_ + sorted_ / 64) sort_samples();
    }
    progress_.finish();
    return std::move(samples_);
  }

 private:
  /// Each axis's bits in a sub-cell's code at `level` (none until its delay
  /// is over), where they start, and the sub-cells' edge over the cell's.
  void set_bits(int level, std::array<int, D>& bits, std::array<int, D>& offset) const {
    int at = 0;
    for (int a = 0; a < D; ++a) {
      bits[a] = std::max(0, level - delay_[a]);
      offset[a] = at;
      at += bits[a];
    }
  }
  void set_level(int level) {
    set_bits(level, bits_, offset_);
    for (int a = 0; a < D; ++a) scale_[a] = std::ldexp(1.0, -bits_[a]);
  }
  /// Axis a's index in `code` at bits/offset.
  static Code index_of(Code code, int bits, int offset) { return (code >> offset) & ((Code{1} << bits) - 1); }

  std::uint64_t level_key(int level) const { return mix64(mix64(seed_ ^ 0x6562656964614c76ULL) + mix64(level)); }

  /// The random bits of dart `dart` of `cell`: part 0 its waiting time, parts
  /// 1..D its position, part D + 1 its sub-cell.
  static std::uint64_t dart_base(std::uint64_t key, std::uint32_t cell, std::uint32_t dart) {
    return mix64(key ^ ((std::uint64_t{cell} << 32) | dart));
  }
  static std::uint64_t dart_bits(std::uint64_t base, int part) {
    return mix64(base + 0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(part + 1));
  }

  /// Waiting time before dart `dart` of a cell with `subs` open sub-cells.
  static double waiting_time(std::uint64_t key, std::uint32_t cell, std::uint32_t dart, std::uint32_t subs) {
    return neg_log(uniform_open_from_bits(dart_bits(dart_base(key, cell, dart), 0))) / subs;
  }

  /// The lower corner and edge of sub-cell `code` of `cell` at the current level.
  void sub_box(const std::array<int, D>& c, Code code, Point<D>& lo, std::array<double, D>& edge) const {
    for (int a = 0; a < D; ++a) {
      const double cell_lo = corners_[a][static_cast<std::size_t>(c[a])];
      edge[a] = (corners_[a][static_cast<std::size_t>(c[a]) + 1] - cell_lo) * scale_[a];  // exact: a power of 2
      lo[a] = cell_lo + static_cast<double>(static_cast<std::uint64_t>(index_of(code, bits_[a], offset_[a]))) * edge[a];
    }
  }

  /// Settles the darts of open slot `slot` with times before `until`: each is
  /// kept if no sample kept earlier in time lies closer than r.
  void settle(std::uint32_t slot, double until, int depth) {
    if (depth > kMaxDepth) throw Failure("ebeida: dart dependency chain deeper than " + std::to_string(kMaxDepth));
    Open& open = open_[slot];
    if (!(open.next_time < until)) return;
    const std::uint64_t key = key_;
    const std::array<int, D> c = hood_.coords(open.cell);
    while (open.next_time < until) {
      const double time = open.next_time;
      const std::uint32_t dart = open.darts++;
      // Advance first: a neighbour settling up to an earlier time must not
      // see this dart again.
      const Subs subs = level_ == 0 ? Subs{0, 1} : subs_of_[slot];
      open.next_time += waiting_time(key, open.cell, dart + 1, subs.count);
      Point<D> lo;
      std::array<double, D> edge;
      Code code = 0;
      const std::uint64_t base = dart_base(key, open.cell, dart);
      if (level_ > 0) {
        const u128 pick = static_cast<u128>(dart_bits(base, D + 1)) * subs.count;
        code = subs_[subs.begin + static_cast<std::uint32_t>(pick >> 64)];
      }
      sub_box(c, code, lo, edge);
      Point<D> x;
      for (int a = 0; a < D; ++a) {
        x[a] = lo[a] + uniform_from_bits(dart_bits(base, a + 1)) * edge[a];
        const double upper = corners_[a][static_cast<std::size_t>(c[a]) + 1];
        if (!(x[a] < upper)) x[a] = std::nextafter(upper, lo[a]);
      }
      // Each neighbour first settles its own darts up to this dart's time
      // (work it would do later anyway), then its sample, if any, is checked.
      // A sample seen here was kept earlier than this dart: a cell keeps a
      // dart only after settling all its neighbours up to that dart's time.
      std::int32_t blocker = -1;
      const bool blocked = hood_.any(near_, c, open.cell, [&](std::size_t n) {
        std::int32_t s = state_[n];
        if (s <= kOpen) {
          const auto neighbour = static_cast<std::uint32_t>(kOpen - s);
          if (!(open_[neighbour].next_time < time)) return false;
          settle(neighbour, time, depth + 1);
          s = state_[n];
        }
        if (s >= 0 && domain_.distance2(x, samples_[static_cast<std::size_t>(s)]) < r2_) {
          blocker = s;
          return true;
        }
        return false;
      });
      if (!blocked) {
        state_[open.cell] = static_cast<std::int32_t>(samples_.size());
        samples_.push_back(x);
        open.next_time = kInf;
        return;
      }
      // A blocker that covers the whole cell blocks every later dart too (at
      // level 0 the dart's box is the cell).
      if (level_ == 0 && covers_box(samples_[static_cast<std::size_t>(blocker)], lo, edge)) {
        state_[open.cell] = kCovered;
        open.next_time = kInf;
        return;
      }
    }
  }

  /// Whether every corner of the box is closer to s than r minus the slack:
  /// the farthest corner takes, along each axis, the farther of the two faces
  /// (the same sum, term for term, as distance2 to that corner).
  /// On a torus the two faces must see the same image of s: a box that holds
  /// the point half a period from s has its farthest point inside, not at a
  /// corner, and is reported as not covered (refine() then decides it).
  bool covers_box(const Point<D>& s, const Point<D>& lo, const std::array<double, D>& edge) const {
    double far2 = 0.0;
    for (int a = 0; a < D; ++a) {
      const double near_face = domain_.delta(lo[a], s[a], a), far_face = domain_.delta(lo[a] + edge[a], s[a], a);
      if (domain_.periodic && !(std::abs(near_face - far_face - edge[a]) < 0.5 * edge[a])) return false;
      far2 += std::max(near_face * near_face, far_face * far_face);
    }
    return far2 < cover2_;
  }

  /// Renumbers the samples in cell order: the samples near a cell are then
  /// near each other in memory (the sweeps append them in several passes).
  void sort_samples() {
    PointSet<D> sorted;
    // The room reserved for the samples to come, not a doubled capacity's:
    // both buffers are held during the copy.
    sorted.reserve(std::max(reserved_, samples_.size() + samples_.size() / 8));
    detail::advise_huge_pages(sorted);
    for (std::int32_t& state : state_)
      if (state >= 0) {
        const auto index = static_cast<std::int32_t>(sorted.size());
        sorted.push_back(samples_[static_cast<std::size_t>(state)]);
        state = index;
      }
    samples_ = std::move(sorted);
    sorted_ = samples_.size();
  }

  /// Drops the settled slots; the open ones keep their order.
  void compact() {
    std::uint32_t kept = 0;
    for (std::uint32_t slot = 0; slot < open_.size(); ++slot) {
      const Open& open = open_[slot];
      if (state_[open.cell] > kOpen) continue;
      open_[kept] = open;
      if (level_ > 0) subs_of_[kept] = subs_of_[slot];
      state_[open.cell] = kOpen - static_cast<std::int32_t>(kept);
      ++kept;
    }
    open_.resize(kept);
    if (level_ > 0) subs_of_.resize(kept);
    detail::release_unused(open_);  // a copy to shrink it was the run's peak (10^6 in 2D)
  }

  /// Splits the open sub-cells of every open cell into 2^D children for the
  /// level now starting (halves along the axes whose delay is over; one
  /// along the others), keeping the children that no single disk covers.
  void refine(double start) {
    // The level's codes in 4 bytes while its bits fit 32 (to level 16 in
    // 2D, 10 in 3D, 8 in 4D: the levels that hold nearly all sub-cells), 16
    // past that: the level-1 codes were the largest block of a run (38 MB at
    // 10^6 in 2D at 16 bytes each, 19 MB at 8).
    int code_bits = 0;
    for (int a = 0; a < D; ++a) code_bits += bits_[a];
    SubCellCodes subs(code_bits <= 32);
    std::vector<Subs> subs_of;
    subs_of.reserve(open_.size());  // at most one a slot: never reallocated
    // The open slots are rewritten in place (a slot moves only down, after it
    // has been read): at level 1 a second slot array would be the peak's
    // largest part after the new sub-cells.
    std::uint32_t kept = 0;
    std::vector<std::array<double, D>> near;  // nearby samples, relative to the cell's lower corner
    const std::uint64_t key = key_ = level_key(level_);
    const int parent_level = level_ - 1;
    std::array<int, D> parent_bits, parent_offset;
    set_bits(parent_level, parent_bits, parent_offset);
    // Children along axes still waiting are not made: they start covered.
    std::bitset<kChildren> waiting;
    for (int child = 0; child < kChildren; ++child)
      for (int a = 0; a < D; ++a)
        if ((child >> a) & 1 && bits_[a] == parent_bits[a]) waiting.set(child);
    // Only samples that can cover a whole child: along each axis the child's
    // far side lies at least a child edge (half of one in the same column)
    // beyond the gap between the cells. At level 1 that leaves the 3^D block.
    const Stencil cover = hood_.filter(near_, [&](const std::array<int, D>& off) {
      double least2 = 0.0;
      for (int a = 0; a < D; ++a) {
        const double edge = domain_.extent(a) / n_[a], child = edge * scale_[a];
        const double least = off[a] == 0 ? 0.5 * child : (std::abs(off[a]) - 1) * edge + child;
        least2 += least * least;
      }
      return least2 < r2_;
    });
    for (std::uint32_t slot = 0; slot < open_.size(); ++slot) {
      const Open o = open_[slot];
      const std::array<int, D> c = hood_.coords(o.cell);
      std::array<double, D> cell_lo, edge;
      for (int a = 0; a < D; ++a) {
        cell_lo[a] = corners_[a][static_cast<std::size_t>(c[a])];
        edge[a] = (corners_[a][static_cast<std::size_t>(c[a]) + 1] - cell_lo[a]) * scale_[a];
      }
      near.clear();
      // Each neighbour offset is one periodic image of the neighbour's sample:
      // the image that lies in the cell at that offset, whole periods away
      // from the stored sample. A torus shorter than 2r along an axis puts
      // several images of one sample within r of a cell, and a sub-cell may
      // be covered by any one of them (the minimum-image distance of the
      // darts sees them all); the image nearest the cell's corner alone
      // would leave such sub-cells open for ever.
      hood_.for_each_image(cover, c, o.cell, [&](std::size_t n, const std::array<int, D>& periods) {
        if (state_[n] >= 0) {
          const Point<D>& s = samples_[static_cast<std::size_t>(state_[n])];
          std::array<double, D> d;
          for (int a = 0; a < D; ++a) {
            d[a] = s[a] - cell_lo[a];
            if (periods[a] != 0) d[a] += periods[a] * domain_.extent(a);
          }
          near.push_back(d);
        }
      });
      const auto begin = static_cast<std::uint32_t>(subs.size());
      const Subs parent_subs = parent_level == 0 ? Subs{0, 1} : subs_of_[slot];
      const std::uint32_t parents = parent_subs.count;
      // The slots' sub-cells lie in slot order: those before this slot's are
      // read for the last time, so their blocks go back now and the parent
      // level's codes are not held whole beside the children's (at 10^6 in
      // 2D that pair was the run's peak).
      if (parent_level > 0) subs_.release_before(parent_subs.begin);
      for (std::uint32_t k = 0; k < parents; ++k) {
        const Code parent = parent_level == 0 ? 0 : subs_[parent_subs.begin + k];
        // The children's faces along each axis, relative to the cell's corner
        // (an axis not split: the parent's two faces, the second twice).
        std::array<std::array<double, 3>, D> face;
        std::array<Code, D> first;
        for (int a = 0; a < D; ++a) {
          const Code index = index_of(parent, parent_bits[a], parent_offset[a]);
          const bool split = bits_[a] > parent_bits[a];
          first[a] = split ? index * 2 : index;
          for (int f = 0; f < 3; ++f)
            face[a][f] =
                static_cast<double>(static_cast<std::uint64_t>(first[a]) + (split ? f : std::min(f, 1))) * edge[a];
        }
        // A child is covered when its farthest corner is inside one disk: the
        // sum over axes of the larger squared distance to its two faces (the
        // slack in cover2_ absorbs the rounding of these relative coordinates).
        std::bitset<kChildren> covered = waiting;  // 2^D children: 256 in 8D
        for (const auto& d : near) {
          std::array<std::array<double, 2>, D> far;
          for (int a = 0; a < D; ++a) {
            const double q0 = (d[a] - face[a][0]) * (d[a] - face[a][0]);
            const double q1 = (d[a] - face[a][1]) * (d[a] - face[a][1]);
            const double q2 = (d[a] - face[a][2]) * (d[a] - face[a][2]);
            far[a] = {std::max(q0, q1), std::max(q1, q2)};
          }
          for (int child = 0; child < kChildren; ++child) {
            double far2 = 0.0;
            for (int a = 0; a < D; ++a) far2 += far[a][(child >> a) & 1];
            if (far2 < cover2_) covered.set(child);
          }
          if (covered.all()) break;
        }
        // From 4D, children that only a union of disks covers are dropped
        // too (UnionCover): in 4D that halves the peak memory (108 to 50 MB
        // at 35,000 samples on the unit torus) in the same time; in 2D and 3D
        // it costs a fifth more time for little memory.
        if constexpr (D >= 4)
          for (int child = 0; child < kChildren; ++child) {
            if (covered.test(child)) continue;
            std::array<double, D> centre, child_edge;  // from the cell's lower corner
            for (int a = 0; a < D; ++a) {
              const int bit = (child >> a) & 1;
              centre[a] = 0.5 * (face[a][bit] + face[a][bit + 1]);
              child_edge[a] = face[a][bit + 1] - face[a][bit];
            }
            if (union_.covers(near, centre, child_edge, cover2_)) covered.set(child);
          }
        for (int child = 0; child < kChildren; ++child) {
          if (covered.test(child)) continue;
          Code code = 0;
          for (int a = 0; a < D; ++a) code |= (first[a] + static_cast<unsigned>((child >> a) & 1)) << offset_[a];
          subs.push_back(code);
        }
      }
      const auto count = static_cast<std::uint32_t>(subs.size()) - begin;
      if (count == 0) {
        state_[o.cell] = kCovered;
        continue;
      }
      state_[o.cell] = kOpen - static_cast<std::int32_t>(kept);
      open_[kept++] = Open{o.cell, 0, start + waiting_time(key, o.cell, 0, count)};
      subs_of.push_back(Subs{begin, count});
    }
    open_.resize(kept);
    // Level 0 has a slot for every cell, level 1 for 40% of them: the first
    // array's 16 bytes a cell must not be held through the next level.
    detail::release_unused(open_);
    // Open sub-cells peak at about 1.6 per grid cell (3D, level 2; 0.8 in
    // 2D): a level that leaves far more would keep growing 2^D-fold with each
    // further one, so memory is capped here rather than by the level bound.
    if (subs.size() > kMaxSubsPerCell<D> * state_.size() + 4096)
      throw Failure("ebeida: " + std::to_string(subs.size()) + " sub-cells still open at refinement level " +
                    std::to_string(level_) + ", more than " + std::to_string(kMaxSubsPerCell<D>) +
                    " per grid cell (numerical breakdown)");
    subs_ = std::move(subs);
    subs_of_ = std::move(subs_of);
  }

  const Domain<D>& domain_;
  std::uint64_t seed_;
  double r2_, cover2_ = 0.0;
  ProgressReporter progress_;
  int level_ = 0;
  std::uint64_t key_ = 0;                 // level_key(level_)
  std::array<int, D> delay_{};            // levels an axis waits before it is split (thin axes)
  std::array<int, D> bits_{}, offset_{};  // an axis's bits in a code at the current level, and where they start
  std::array<double, D> scale_{};         // 2^-bits_: a sub-cell's edge over its cell's
  std::array<int, D> n_{};
  GridNeighbourhood<D> hood_;                   // the grid's cell arithmetic: wrap, stencils
  std::array<std::vector<double>, D> corners_;  // cell boundaries per axis, n + 1 each
  Stencil near_;                                // the cells that may hold a sample closer than r to a point of a cell
  std::vector<std::int32_t> state_;
  std::vector<Open> open_;
  SubCellCodes subs_;  // the current level's open sub-cells, slot after slot
  std::vector<Subs> subs_of_;  // per slot, from level 1 on
  detail::UnionCover<D> union_;
  PointSet<D> samples_;
  std::size_t sorted_ = 0;    // samples_ is in cell order up to here
  std::size_t reserved_ = 0;  // the samples' first reservation
};

// From 5 dimensions the sweep stops paying: a dart first settles every open
// cell within r of it, and cells of edge r/sqrt(D) put (2 ceil(sqrt D) + 1)^D
// of them in reach (16,807 in 5D). There the papers' own
// loop runs: each level throws a fixed number of darts, each at a uniformly
// drawn open sub-cell (all sub-cells of a level have one size, so a dart is
// uniform over the open area) and uniform in it, in sequence; samples live in
// a second grid of edge r (Grid::for_conflicts), whose pruned walk answers a
// conflict or coverage query from at most 3^D cells. The distribution is the
// same, maximal dart throwing's; the bits differ from the sweep's.
//
// The papers' test drops a sub-cell that one disk covers; one covered only by
// the union of several disks stays open until it fits in one of them, and
// in high dimensions most of the space is near the edge of the nearest disk,
// so such sub-cells multiply by nearly 2^D a level before they close. Here a
// second test drops sub-cells that a union covers (covered_by_union). Measured
// on the unit torus (2026-12-03): at r = 0.25 in 5D (1,070 samples) 4.1 s
// with the single-disk test alone, 1.8 s with both; at about 700 samples in
// 6D 29 s and 370 MB, then 11 s and 82 MB; in 7D 54 million sub-cells open at
// level 2 for 627 samples (5.5 GB), then 3.9 million at level 1 and no end
// in 100 s. Past 5D the run stays exact but slows steeply with the dimension:
// on the unit torus 234 samples took 26 s in 7D and 44 took 36 s in 8D
// (docs/dimensions.md), most of it in the union test. Splitting one axis a
// level instead of all D (2 children, not 2^D) was tried: it tests fewer
// children but fails more tests, and was slower (13 s against 6 s in 7D).
template <int D>
class EbeidaListSampler {
  /// An open sub-cell at the current level: its lower corner and its grid cell
  /// (whose sample, once it has one, covers it).
  struct Sub {
    Point<D> lo;
    std::uint32_t cell;
  };
  static constexpr int kChildren = 1 << D;
  static constexpr int kMaxLevels = 60;  // sub-cells of diagonal 2^-60 r, far below the slack
  // Open sub-cells per grid cell at any level, which sizes the memory bound
  // below: measured peaks 6 in 5D with the single-disk test alone (unit torus,
  // 700 samples); with both tests 3.8 in 6D, 4.8 in 7D and 2.8 to 10 in 8D on
  // the unit torus, 5.0, 7.4 and 7.0 in unit boxes (6D to 8D, 66 to 414
  // samples), and over 32 on an 8D torus of period r (7 samples), whose disks
  // reach round it. A level past this stops the run.
  static constexpr std::size_t kMaxSubsPerCell = std::min(kChildren / 2, 64);
  static constexpr double kMaxBytes = 0x1.0p32;  // what the bound above may come to: 4 GiB

 public:
  EbeidaListSampler(const EbeidaParams& params, const Domain<D>& domain, std::uint64_t seed)
      : domain_(domain),
        r_(params.radius),
        r2_(params.radius * params.radius),
        rng_(seed, {0x6562656964614844ULL}),
        samples_(Grid<D>::for_conflicts(domain, params.radius)),
        progress_(params.progress, typical_count(sizing_volume(domain, params.radius), params.radius, D)) {
    detail::CoverCells<D> grid("ebeida", domain, r_);
    // A byte of state a cell, a 4-byte entry at level 0, and at worst two
    // lists of kMaxSubsPerCell sub-cells a cell while a level is refined.
    const double bytes = grid.count * (5.0 + 2.0 * kMaxSubsPerCell * static_cast<double>(sizeof(Sub)));
    if (bytes > kMaxBytes)
      throw InvalidArgument("ebeida: radius " + detail::format_number(r_) + " needs " +
                            detail::format_number(grid.count) + " grid cells in " + std::to_string(D) +
                            " dimensions for this domain, and up to " + detail::format_number(bytes / 0x1.0p30) +
                            " GiB for their sub-cells (more than " + detail::format_number(kMaxBytes / 0x1.0p30) +
                            "); bridson or dart-throwing take such sets");
    grid.make_corners(domain);
    n_ = grid.n;
    cover2_ = grid.cover2;
    corners_ = std::move(grid.corners);
    hood_ = GridNeighbourhood<D>(domain, n_);
    delay_ = detail::quadtree_axis_delays<D>(domain, n_, kMaxLevels);
  }

  PointSet<D> run() {
    const std::size_t cells = hood_.size();
    closed_.assign(cells, 0);
    std::vector<std::uint32_t> first(cells);
    for (std::size_t c = 0; c < cells; ++c) first[c] = static_cast<std::uint32_t>(c);
    level_ = 0;
    throw_darts(first, kFirstLevelTime);
    std::vector<Sub> open = refine(first);
    first = {};
    for (level_ = 1; !open.empty(); ++level_) {
      throw_darts(open, kLevelTime);
      if (level_ == kMaxLevels)
        throw Failure("ebeida: " + std::to_string(open.size()) + " sub-cells still open after " +
                      std::to_string(kMaxLevels) + " levels of refinement (numerical breakdown)");
      open = refine(open);
    }
    progress_.finish();
    return std::move(samples_).take_points();
  }

 private:
  static std::uint32_t cell_of(std::uint32_t cell) { return cell; }
  static std::uint32_t cell_of(const Sub& sub) { return sub.cell; }

  /// The box of an open entry at the current level: a whole cell at level 0,
  /// a sub-cell after (halved along each axis whose delay is over).
  void box(std::uint32_t cell, Point<D>& lo, std::array<double, D>& edge, std::array<double, D>& hi) const {
    const std::array<int, D> c = hood_.coords(cell);
    for (int a = 0; a < D; ++a) {
      lo[a] = corners_[a][static_cast<std::size_t>(c[a])];
      hi[a] = corners_[a][static_cast<std::size_t>(c[a]) + 1];
      edge[a] = hi[a] - lo[a];
    }
  }
  void box(const Sub& sub, Point<D>& lo, std::array<double, D>& edge, std::array<double, D>& hi) const {
    box(sub.cell, lo, edge, hi);
    for (int a = 0; a < D; ++a) {
      edge[a] = std::ldexp(edge[a], -std::max(0, level_ - delay_[a]));  // exact: a power of 2
      lo[a] = sub.lo[a];
    }
  }

  /// Whether one disk covers the box whose centre lies `gap` from the sample
  /// along each axis (the nearest image per axis): its farthest corner is
  /// |gap| plus half an edge away along every axis.
  bool covers(const std::array<double, D>& gap, const std::array<double, D>& edge) const {
    double far2 = 0.0;
    for (int a = 0; a < D; ++a) {
      const double far = std::abs(gap[a]) + 0.5 * edge[a];
      far2 += far * far;
    }
    return far2 < cover2_;
  }

  /// Throws darts_per_entry darts per open entry, each at a uniformly drawn
  /// open entry. Entries whose cell took a sample, or that a blocker covers,
  /// leave the list (a dart there could only miss).
  template <class Entry>
  void throw_darts(std::vector<Entry>& open, double darts_per_entry) {
    const auto darts = static_cast<std::uint64_t>(std::ceil(darts_per_entry * static_cast<double>(open.size())));
    const auto drop = [&](std::size_t i) {
      open[i] = open.back();
      open.pop_back();
    };
    for (std::uint64_t thrown = 0; thrown < darts && !open.empty();) {
      const auto i = static_cast<std::size_t>(rng_.below(open.size()));
      const std::uint32_t cell = cell_of(open[i]);
      if (closed_[cell]) {
        drop(i);
        continue;
      }
      if ((++thrown & (kReportEvery - 1)) == 0) progress_.update(static_cast<double>(samples_.size()));
      Point<D> lo, x;
      std::array<double, D> edge, cell_hi;
      box(open[i], lo, edge, cell_hi);
      for (int a = 0; a < D; ++a) {
        x[a] = lo[a] + rng_.uniform() * edge[a];
        if (!(x[a] < cell_hi[a])) x[a] = std::nextafter(cell_hi[a], lo[a]);
      }
      std::int32_t blocker = -1;
      samples_.for_each_within(x, r_, [&](std::int32_t j, double d2) {
        if (!(d2 < r2_)) return true;
        blocker = j;
        return false;
      });
      if (blocker < 0) {
        samples_.insert(x);
        closed_[cell] = 1;
        drop(i);
        continue;
      }
      const Point<D>& s = samples_.points()[static_cast<std::size_t>(blocker)];
      std::array<double, D> gap;
      for (int a = 0; a < D; ++a) gap[a] = domain_.delta(lo[a] + 0.5 * edge[a], s[a], a);
      if (covers(gap, edge)) {
        if (level_ == 0) closed_[cell] = 1;
        drop(i);
      }
    }
  }

  /// The next level's sub-cells: each open entry's 2^D children (halves
  /// along the axes whose delay is over), less those one disk covers.
  template <class Entry>
  std::vector<Sub> refine(std::vector<Entry>& open) {
    std::vector<Sub> next;
    std::vector<std::array<double, D>> cell_near;  // samples near the cell, from its centre
    std::vector<std::array<double, D>> near;       // those near the entry, from the entry's centre
    std::array<bool, D> split;
    for (int a = 0; a < D; ++a) split[a] = level_ + 1 > delay_[a];
    // Children along axes not split are not made: they start covered.
    std::array<bool, kChildren> absent{};
    for (int child = 0; child < kChildren; ++child)
      for (int a = 0; a < D; ++a)
        if ((child >> a) & 1 && !split[a]) absent[child] = true;
    // The samples near a cell are gathered once for all its sub-cells (a walk
    // of the sample grid per sub-cell was three quarters of the run in 5D).
    if constexpr (std::is_same_v<Entry, Sub>)
      std::sort(open.begin(), open.end(),
                [](const Sub& a, const Sub& b) { return a.cell != b.cell ? a.cell < b.cell : a.lo < b.lo; });
    std::uint32_t gathered = std::numeric_limits<std::uint32_t>::max();
    Point<D> cell_centre;
    for (std::size_t k = 0; k < open.size(); ++k) {
      // A level's refinement can take seconds and places no sample: a
      // cancellation is heard here too.
      if ((k & 63) == 0) progress_.poll();
      const Entry& entry = open[k];
      const std::uint32_t cell = cell_of(entry);
      if (closed_[cell]) continue;
      if (cell != gathered) {
        // A sample that covers part of the cell lies within r plus half the
        // cell's diagonal of its centre.
        Point<D> cell_lo;
        std::array<double, D> cell_edge, cell_hi;
        box(cell, cell_lo, cell_edge, cell_hi);
        double half_diagonal2 = 0.0;
        for (int a = 0; a < D; ++a) {
          cell_centre[a] = cell_lo[a] + 0.5 * cell_edge[a];
          half_diagonal2 += 0.25 * cell_edge[a] * cell_edge[a];
        }
        cell_near.clear();
        samples_.for_each_within(cell_centre, r_ + std::sqrt(half_diagonal2), [&](std::int32_t j, double) {
          const Point<D>& s = samples_.points()[static_cast<std::size_t>(j)];
          std::array<double, D> d;
          for (int a = 0; a < D; ++a) d[a] = domain_.delta(cell_centre[a], s[a], a);
          cell_near.push_back(d);
          return true;
        });
        gathered = cell;
      }
      Point<D> lo;
      std::array<double, D> edge, cell_hi, child_edge, offset;
      box(entry, lo, edge, cell_hi);
      for (int a = 0; a < D; ++a) {
        offset[a] = lo[a] + 0.5 * edge[a] - cell_centre[a];
        child_edge[a] = split[a] ? 0.5 * edge[a] : edge[a];
      }
      // A disk that covers a child alone has its centre within r of the
      // entry's; the union test takes the samples within r of some point of
      // a child, so within r plus a child's half diagonal of the child's
      // centre, a child's half diagonal from the entry's.
      double child_half_diagonal2 = 0.0;
      for (int a = 0; a < D; ++a) child_half_diagonal2 += 0.25 * child_edge[a] * child_edge[a];
      const double reach = (r_ + 2.0 * std::sqrt(child_half_diagonal2)) * (1.0 + 1e-12);
      near.clear();
      near_d2_.clear();
      for (const auto& from_cell : cell_near) {
        std::array<double, D> d;
        double d2 = 0.0;
        for (int a = 0; a < D; ++a) {
          d[a] = from_cell[a] - offset[a];
          if (domain_.periodic) {  // back to the nearest image
            const double period = domain_.extent(a);
            if (d[a] > 0.5 * period) d[a] -= period;
            else if (d[a] < -0.5 * period) d[a] += period;
          }
          d2 += d[a] * d[a];
        }
        if (d2 <= reach * reach) {
          near.push_back(d);
          near_d2_.push_back(d2);
        }
      }
      std::array<bool, kChildren> covered = absent;
      for (std::size_t i = 0; i < near.size(); ++i) {
        if (!(near_d2_[i] < r2_)) continue;
        const auto& d = near[i];
        // Per axis and side, the squared far extent of a child from the
        // sample's nearest image along that axis.
        std::array<std::array<double, 2>, D> far;
        for (int a = 0; a < D; ++a)
          for (int side = 0; side < 2; ++side) {
            const double shift = split[a] ? (side ? 0.25 : -0.25) * edge[a] : 0.0;
            double gap = std::abs(d[a] - shift);
            if (domain_.periodic) gap = std::min(gap, domain_.extent(a) - gap);
            const double f = gap + 0.5 * child_edge[a];
            far[a][side] = f * f;
          }
        // Every child's squared far corner, built an axis at a time: 2^D
        // additions rather than D 2^D.
        std::array<double, kChildren> far2;
        far2[0] = 0.0;
        for (int a = 0; a < D; ++a)
          for (int child = (1 << a) - 1; child >= 0; --child) {
            far2[child | (1 << a)] = far2[child] + far[a][1];
            far2[child] += far[a][0];
          }
        bool all = true;
        for (int child = 0; child < kChildren; ++child) {
          covered[child] = covered[child] || far2[child] < cover2_;
          all = all && covered[child];
        }
        if (all) break;
      }
      for (int child = 0; child < kChildren; ++child)
        if (!covered[child]) {
          std::array<double, D> centre;  // the child's, from the entry's
          for (int a = 0; a < D; ++a) centre[a] = split[a] ? (((child >> a) & 1) ? 0.25 : -0.25) * edge[a] : 0.0;
          covered[child] = union_.covers(near, centre, child_edge, cover2_);
        }
      for (int child = 0; child < kChildren; ++child) {
        if (covered[child]) continue;
        Sub sub{lo, cell};
        for (int a = 0; a < D; ++a)
          if ((child >> a) & 1) sub.lo[a] += child_edge[a];
        next.push_back(sub);
      }
      if (next.size() > kMaxSubsPerCell * hood_.size() + 4096)
        throw Failure("ebeida: " + std::to_string(next.size()) + " sub-cells open at refinement level " +
                      std::to_string(level_ + 1) + ", more than " + std::to_string(kMaxSubsPerCell) +
                      " per grid cell, past the memory the run was sized for");
    }
    return next;
  }


  const Domain<D>& domain_;
  double r_, r2_, cover2_ = 0.0;
  detail::UnionCover<D> union_;
  std::vector<double> near_d2_;                 // refine(): squared distances of the nearby samples
  Rng rng_;
  Grid<D> samples_;
  ProgressReporter progress_;
  int level_ = 0;
  std::array<int, D> n_{};
  std::array<int, D> delay_{};  // levels an axis waits before it is split (thin axes)
  GridNeighbourhood<D> hood_;
  std::array<std::vector<double>, D> corners_;  // cell boundaries per axis, n + 1 each
  std::vector<std::uint8_t> closed_;            // per cell: holds a sample or is covered
};

}  // namespace

template <int D>
PointSet<D> ebeida(const EbeidaParams& params, const Domain<D>& domain, std::uint64_t seed) {
  domain.validate();
  require_radius_budget(domain, params.radius, params.max_points);
  if constexpr (D >= kFirstListedDim)
    return EbeidaListSampler<D>(params, domain, seed).run();
  else
    return EbeidaSampler<D>(params, domain, seed).run();
}

#define PDS_INSTANTIATE(D) template PointSet<D> ebeida<D>(const EbeidaParams&, const Domain<D>&, std::uint64_t);
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
