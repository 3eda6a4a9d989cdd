#pragma once
// The neighbour index of the constrained samplers (constrained.cpp) in 1 to 3
// dimensions: is a new point x with radius r in conflict with a stored one,
// under the rule distance < max(r, r_q) (samplers/constraints.h)? It answers
// exactly as RadiusLevels (radius_levels.h, 4 dimensions and more) does,
// point for point, so the samplers' output does not depend on which index
// they use; this one is built for speed, as the uniform Bridson's grid is
// (samplers/bridson.cpp).
//
// The cover, asked first: a bit grid over the domain with cells about
// rmin / 2.5 across its rows and rmin / 5 along them (a row's span is set a
// word at a time, so the finer axis costs little), a bit set where some
// sample's own ball (less a margin far above rounding) holds the whole cell. A point in such a cell conflicts
// with that sample whatever its own radius (distance < r_q <= max(r, r_q)),
// so the samplers reject it before reading the mask or the field. In a
// near-full set that is most queries (the benchmark's candidates and
// restart darts: 96% at 10^5 samples, 94% at 10^6); the rest go to the
// levels below.
//
// Radius levels as in RadiusLevels: level l holds radii in [s_l, s_(l+1)),
// s_0 = rmin, s_(l+1) about sqrt(2) s_l (the last level up to rmax). Each
// level is a flat grid of cells of diagonal just under s_l, so that two
// samples of the level (at least s_l apart) never share a cell, and a cell
// stores its sample's coordinates and squared radius inline (no lists, no
// indices). A conflict within the level needs a distance below s_(l+1),
// about two cell edges in 2D; s_(l+1) is set just below 2 edges there so the
// cells a query can reach from each half of its cell (along each axis) are a
// fixed list, the own cell first, then nearest first: 24 cells in 2D (16
// for a constant radius, as bridson.cpp's). They are read two a vector,
// eight with one branch, from a grid padded with a margin as wide as the
// list reaches, so no bounds are checked: on a box the margin stays empty;
// on a torus it holds copies of the samples near the opposite faces (their
// own coordinates, so the distance is the domain's min-image one), and away
// from the faces the min-image correction never applies and is left out
// (bridson.cpp's argument).
//
// Each level also keeps a bit per other level, per block of 8 cells along
// each axis, that may hold a conflicting sample near it; an insert sets its
// level's bit in the blocks of every other level that it can reach (within
// its radius for finer levels, whose queries have smaller radii; within the
// other level's largest radius for coarser ones), so a query reads the bits
// of its own block and searches only the levels they name, cell by cell
// over the block its reach covers (in a smooth field, mostly none).
//
// Exactness: a stored sample is found whenever Domain::distance2 puts it
// closer than max(r, r_q), the squared distance against the squared larger
// radius, in Domain::distance2's arithmetic (term for term, lane by lane).
// The cell lists and blocks are widened a little against the rounding of
// the cell arithmetic. Two samples that should not share a cell but do (a
// point set given as fixed points, whose pairs are not checked) go to an
// overflow RadiusLevels that queries also ask once it is not empty.
//
// Memory: the level grids are mapped zeroed (mmap) and the kernel gives them
// pages as they are first touched, where the field puts samples of the
// level; a zero cell is empty (a stored radius is never 0). A level has
// 2 / s_l^2 cells a unit area in 2D, 24 bytes each; grids up to 32 MB ask
// for huge pages. The cover has 12.5 / rmin^2 bits a unit area in 2D (at
// most 128 MiB: coarser cells beyond), mapped at once; the blocks' bits 4
// bytes a block.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "pds/detail/format.h"
#include "pds/domain.h"
#include "pds/error.h"
#include "pds/grid.h"
#include "pds/grid_neighbourhood.h"
#include "pds/point.h"
#include "pds/rng.h"
#include "mapped_pages.h"
#include "radius_levels.h"

namespace pds::detail {

template <int D>
class FlatLevels {
  static_assert(D >= 1 && D <= 3, "FlatLevels serves 1 to 3 dimensions (RadiusLevels the others)");

 public:
  /// Radii must lie in [rmin, rmax] (the samplers clamp them).
  FlatLevels(const Domain<D>& domain, double rmin, double rmax) : domain_(domain), rmax_(rmax) {
    for (int i = 0; i < D; ++i) {
      scale_ = std::max({scale_, std::abs(domain.lo[i]), std::abs(domain.hi[i])});
      half_[i] = 0.5 * domain.extent(i);
    }
    // The cells a query reaches along an axis in its own level: m edges, the
    // fewest that cover sqrt(2) s with cells of edge s / sqrt(D).
    const double m = std::ceil(std::sqrt(2.0 * D));
    double start = rmin;
    for (;;) {
      Level level;
      level.start = start;
      const double max_edge = start / std::sqrt(static_cast<double>(D)) * (1.0 - 1e-9);
      double edge_min = std::numeric_limits<double>::infinity();
      for (int i = 0; i < D; ++i) {
        const double n = std::max(1.0, std::ceil(domain.extent(i) / max_edge));
        if (n > 1e9) throw_too_many(start);
        level.cells[i] = static_cast<int>(n);
        level.inv_edge[i] = n / domain.extent(i);
        level.twice_inv_edge[i] = 2.0 * level.inv_edge[i];
        edge_min = std::min(edge_min, domain.extent(i) / n);
      }
      // s_(l+1): sqrt(2) s, or just under m edges if that is less (2D), so
      // that a query's list stops at m cells; never below s itself.
      double next = kLevelRatio * start;
      const double cover = m * edge_min * (1.0 - 1e-6);
      if (cover > start) next = std::min(next, cover);
      const bool last = next > rmax || static_cast<int>(levels_.size()) + 1 == kMaxLevels;
      level.bound = last ? rmax : next;
      levels_.push_back(std::move(level));
      build(levels_.back());
      if (last) break;
      start = next;
    }
    for (Level& level : levels_) {
      starts_.push_back(level.start);
      ends_.push_back(&level == &levels_.back() ? std::numeric_limits<double>::infinity() : level.bound);
      if (levels_.size() > 1) level.others.assign(level.blocks, 0);
    }
    // The cover: cells of edge about rmin / kCoverSplit, and along axis 0
    // (within a row of bits) kRowSplit times finer: a row's span is set a
    // word at a time, so they cost little to mark and leave less of each
    // ball uncovered. Coarser if there would be more than kMaxCoverBits.
    double edge = rmin / kCoverSplit;
    for (;;) {
      double bits = 1.0;
      for (int i = 0; i < D; ++i) bits *= std::ceil(domain.extent(i) / (i == 0 ? edge / kRowSplit : edge));
      if (bits <= kMaxCoverBits) break;
      edge *= 2.0;
    }
    std::size_t rows = 1;
    for (int i = 0; i < D; ++i) {
      cover_cells_[i] = static_cast<int>(std::ceil(domain.extent(i) / (i == 0 ? edge / kRowSplit : edge)));
      cover_inv_edge_[i] = cover_cells_[i] / domain.extent(i);
      cover_edge_[i] = domain.extent(i) / cover_cells_[i];
      if (i > 0) rows *= static_cast<std::size_t>(cover_cells_[i]);
    }
    cover_words_ = (static_cast<std::size_t>(cover_cells_[0]) + 63) / 64;
    cover_row_stride_[0] = 0;
    for (int i = 1; i < D; ++i)
      cover_row_stride_[i] =
          i == 1 ? cover_words_ : cover_row_stride_[i - 1] * static_cast<std::size_t>(cover_cells_[i - 1]);
    // Mapped at once: the cover is read everywhere, by every dart.
    cover_ = detail::map_zeroed<std::uint64_t>(rows * cover_words_, detail::Pages::kPopulate);
  }

  // Where x falls: its level, squared radius, cell (of the padded grid),
  // half-cell and how its list is read.
  struct Query {
    Point<D> x;
    double r, r2;
    int level;
    std::size_t cell;
    std::array<int, D> coords;  // the cell's, unpadded
    unsigned half;
    // 0: the plain difference, no empty cell can pass for a conflict; 1: the
    // plain difference, empty cells masked (x lies within r of the origin,
    // where an empty cell's zeros are); 2: with the torus's min-image
    // correction (near its faces), empty cells masked.
    int mode;
  };

  // A cell of the cover: its word and bit.
  struct Spot {
    std::size_t word;
    std::uint64_t bit;
  };

  /// True if a stored point q has distance(x, q) < max(r, r_q).
  bool conflicts(const Point<D>& x, double r) const { return conflicts(query(x, r, 0)); }

  /// Stores x (in the domain) with radius r.
  void insert(const Point<D>& x, double r) { insert(query(x, r, 0)); }

  /// Where x with radius r (in [rmin, rmax]) falls; `hint` is a level to try
  /// first (a neighbour's: in a smooth field, most often the same).
  [[gnu::always_inline]] Query query(const Point<D>& x, double r, int hint) const {
    Query q;
    q.x = x;
    q.r = r;
    q.r2 = r * r;
    q.level = level_of(r, hint);
    const Level& level = levels_[static_cast<std::size_t>(q.level)];
    q.cell = 0;
    q.half = 0;
    bool interior = true;
    double origin2 = 0.0;  // what an empty cell's zeros give in the plain scan
    for (int i = 0; i < D; ++i) {
      // Position in half-cells (doubling is exact): its low bit is the half.
      const int h =
          std::min(static_cast<int>((x[i] - domain_.lo[i]) * level.twice_inv_edge[i]), 2 * level.cells[i] - 1);
      const int c = h >> 1;
      q.coords[i] = c;
      q.half |= static_cast<unsigned>(h & 1) << i;
      q.cell += static_cast<std::size_t>(c + level.margin[i]) * level.stride[i];
      if (domain_.periodic) interior &= static_cast<unsigned>(c - level.margin[i]) < level.interior[i];
      const double d = 0.0 - x[i];
      origin2 = i == 0 ? d * d : origin2 + d * d;
    }
    q.mode = !interior ? 2 : origin2 < q.r2 ? 1 : 0;
    return q;
  }

  /// x's cell of the cover.
  [[gnu::always_inline]] Spot spot(const Point<D>& x) const {
    Spot s{0, 0};
    for (int i = 0; i < D; ++i) {
      const int c = std::min(static_cast<int>((x[i] - domain_.lo[i]) * cover_inv_edge_[i]), cover_cells_[i] - 1);
      if (i == 0) {
        s.word = static_cast<std::size_t>(c >> 6);
        s.bit = std::uint64_t{1} << (c & 63);
      } else {
        s.word += static_cast<std::size_t>(c) * cover_row_stride_[i];
      }
    }
    return s;
  }

  /// True when the spot lies wholly within some sample's own ball: a point
  /// there conflicts with that sample whatever its radius (distance < r_q <=
  /// max(r, r_q)). Once true, true for good (bits are only set).
  [[gnu::always_inline]] bool covered(const Spot& s) const { return cover_[s.word] & s.bit; }

  /// The cover's size in bytes.
  std::size_t cover_bytes() const { return cover_.get_deleter().bytes; }

  /// Asks for the cover's word of a spot (a dart, drawn ahead).
  void prefetch(const Spot& s) const { __builtin_prefetch(&cover_[s.word]); }

  /// Asks for the cover's words within `reach` of x (2D: the words of x's
  /// column on each row within reach; a picked sample's candidates land
  /// there, and on a large cover each would otherwise wait for its own cache
  /// miss).
  void prefetch_cover(const Point<D>& x, double reach) const {
    if constexpr (D == 2) {
      const double u = x[0] - domain_.lo[0], v = x[1] - domain_.lo[1];
      const int c0 = std::min(static_cast<int>(u * cover_inv_edge_[0]), cover_cells_[0] - 1);
      const std::size_t word = static_cast<std::size_t>(c0 >> 6);
      int a = floor_int((v - reach) * cover_inv_edge_[1]), b = floor_int((v + reach) * cover_inv_edge_[1]);
      const int n = cover_cells_[1];
      if (b - a >= n) {
        a = 0;
        b = n - 1;
      }
      for (int row = a; row <= b; ++row) {
        int r = row;
        if (r < 0) r += n;
        if (r >= n) r -= n;
        if (r < 0 || r >= n) continue;
        __builtin_prefetch(&cover_[static_cast<std::size_t>(r) * cover_words_ + word]);
      }
    }
  }

  // The cover's cells by number, for restart darts aimed at the uncovered
  // ones (constrained.cpp): cell = row x (cells along axis 0) + column, rows
  // numbered axis 1 fastest. All of them fit 32 bits (kMaxCoverBits).

  /// How many cells the cover has (equal volumes tiling the domain).
  std::uint64_t cover_cells() const {
    std::uint64_t n = 1;
    for (int i = 0; i < D; ++i) n *= static_cast<std::uint64_t>(cover_cells_[i]);
    return n;
  }

  /// Calls f(cell) for every cell of the cover not yet covered, in order.
  template <class F>
  void for_each_uncovered(F&& f) const {
    const auto columns = static_cast<std::uint64_t>(cover_cells_[0]);
    const std::uint64_t rows = cover_cells() / columns;
    for (std::uint64_t row = 0; row < rows; ++row)
      for (std::size_t w = 0; w < cover_words_; ++w) {
        const std::uint64_t base = w * 64;
        // Bits past the row's last column are not cells.
        std::uint64_t free = ~cover_[row * cover_words_ + w];
        if (columns - base < 64) free &= (std::uint64_t{1} << (columns - base)) - 1;
        for (; free; free &= free - 1)
          f(static_cast<std::uint32_t>(row * columns + base + static_cast<unsigned>(std::countr_zero(free))));
      }
  }

  /// The spot of a cover cell.
  Spot cover_spot(std::uint32_t cell) const {
    const auto columns = static_cast<std::uint32_t>(cover_cells_[0]);
    const std::uint32_t column = cell % columns;
    return {(cell / columns) * cover_words_ + (column >> 6), std::uint64_t{1} << (column & 63)};
  }

  /// A point uniform in a cover cell (up to the rounding of the cell
  /// arithmetic, which may put it in a neighbouring cell), in the domain.
  Point<D> uniform_in_cover_cell(std::uint32_t cell, Rng& rng) const {
    Point<D> x;
    std::uint32_t rest = cell;
    for (int i = 0; i < D; ++i) {
      const auto n = static_cast<std::uint32_t>(cover_cells_[i]);
      const std::uint32_t c = rest % n;
      rest /= n;
      const double v = domain_.lo[i] + (static_cast<double>(c) + rng.uniform()) * cover_edge_[i];
      x[i] = std::clamp(v, domain_.lo[i], std::nextafter(domain_.hi[i], domain_.lo[i]));
    }
    return x;
  }

  /// conflicts() then, if none, insert(); returns whether x was stored.
  [[gnu::always_inline]] bool insert_if_free(const Query& q) {
    if (conflicts(q)) return false;
    insert(q);
    return true;
  }

  /// The level of radius r (in [rmin, rmax]), trying `hint` first.
  int level_of(double r, int hint) const {
    if (starts_[static_cast<std::size_t>(hint)] <= r && r < ends_[static_cast<std::size_t>(hint)]) return hint;
    return static_cast<int>(std::upper_bound(starts_.begin() + 1, starts_.end(), r) - starts_.begin()) - 1;
  }

  int levels() const { return static_cast<int>(levels_.size()); }

 private:
  // As RadiusLevels: 32 levels fit the 32 bits of Level::others; larger
  // radii share the last level (exact, only slower).
  static constexpr double kLevelRatio = 1.4142135623730951;
  static constexpr int kMaxLevels = 32;
  // Arrays of up to this many bytes ask for huge pages (fewer TLB misses
  // and page faults); the kernel then zeroes them whole, which larger grids,
  // most of whose pages the field may never touch, would pay for.
  static constexpr std::size_t kHugePagesUpTo = std::size_t{32} << 20;
  // Level::others has a word per block of kBlockCells cells along each axis.
  static constexpr int kBlockShift = 3;
  static constexpr int kBlockCells = 1 << kBlockShift;
  // Cells read with one branch (bridson.cpp: 8 beat 4 and 16).
  static constexpr std::size_t kBlock = 8;

  // A cell holds its sample's coordinates and squared radius; zeros when
  // empty (a radius is never 0).
  struct Cell {
    Point<D> p;
    double r2;
  };

  // Zeroed pages (mapped_pages.h), which the kernel gives on first touch
  // (where the field puts samples of the level, and around); huge pages up
  // to kHugePagesUpTo.
  template <class T>
  static detail::MappedArray<T> zeroed(std::size_t count) {
    using detail::Pages;
    return detail::map_zeroed<T>(count, count * sizeof(T) <= kHugePagesUpTo ? Pages::kHuge : Pages::kLazy);
  }

  struct Level {
    double start = 0;  // the smallest radius the level holds
    double bound = 0;  // every radius it holds is below this (the last level: at most rmax = bound)
    std::array<int, D> cells{}, margin{}, padded{};
    std::array<double, D> inv_edge{}, twice_inv_edge{};
    std::array<std::size_t, D> stride{};
    std::array<unsigned, D> interior{};  // torus: cells c with c - margin < interior skip the min-image step
    std::array<std::vector<std::ptrdiff_t>, (1u << D)> lists;  // per half-cell: offsets to read, own first
    detail::MappedArray<Cell> grid;
    double widen = 0;  // added to a reach against the rounding of the cell arithmetic
    // A bit per other level that may hold a sample in conflict with a query
    // here, per block of kBlockCells cells along each axis.
    std::vector<std::uint32_t> others;
    std::array<std::size_t, D> others_stride{};
    std::size_t blocks = 0;
  };

  // floor and ceil as ints (inline: std::floor is a call where SSE4.1 is
  // not assumed), of v clamped into +-1e9, beyond every cell count: a reach
  // of many periods or past a box's faces comes to the same cells.
  static int floor_int(double v) {
    v = std::clamp(v, -1e9, 1e9);
    const int i = static_cast<int>(v);
    return i - (v < i);
  }
  static int ceil_int(double v) {
    v = std::clamp(v, -1e9, 1e9);
    const int i = static_cast<int>(v);
    return i + (v > i);
  }

  [[noreturn]] static void throw_too_many(double radius) {
    throw InvalidArgument("radius " + format_number(radius) + " needs more than " + std::to_string(kMaxGridCells) +
                          " background cells for this domain");
  }

  // The lists of a level, its margin and its zeroed cells.
  void build(Level& level) {
    using Step = std::array<int, D>;
    std::array<double, D> edge;
    for (int i = 0; i < D; ++i) edge[i] = domain_.extent(i) / level.cells[i];
    // Gaps are shrunk by this much (and reaches widened) so that the
    // rounding of the cell arithmetic never drops a cell that matters.
    const double tolerance = 1e-6 * *std::min_element(edge.begin(), edge.end()) + 1e-12 * scale_;
    level.widen = tolerance + 1e-9 * level.bound;
    const double bound = level.bound;
    // The offsets whose cell-to-cell gap is below the bound (with the
    // tolerance), GridNeighbourhood's over a box of the level's cells (on a
    // torus the far images are the margin's copies), then for each half-cell
    // those whose gap from that half is.
    const GridNeighbourhood<D> layout(Domain<D>::box(domain_.lo, domain_.hi), level.cells);
    const auto within = layout.stencil_within(bound + 2.0 * tolerance, 1e-4);
    for (unsigned half = 0; half < (1u << D); ++half) {
      const auto gap2 = [&](const Step& o) {
        double g2 = 0.0;
        for (int i = 0; i < D; ++i) {
          const bool upper = half >> i & 1;  // x in [0.5, 1) of its cell along axis i
          double g = 0.0;
          if (o[i] > 0) g = (o[i] - (upper ? 1.0 : 0.5)) * edge[i];
          if (o[i] < 0) g = (-o[i] - (upper ? 0.5 : 1.0)) * edge[i];
          g = std::max(0.0, g - tolerance);
          g2 += g * g;
        }
        return g2;
      };
      std::vector<std::pair<double, Step>> list{{-1.0, Step{}}};  // the own cell first
      for (const Step& o : within.steps)
        if (const double g2 = gap2(o); g2 < bound * bound) list.push_back({g2, o});
      std::stable_sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      level.lists[half].clear();
      for (const auto& [g2, step] : list)
        for (int i = 0; i < D; ++i) level.margin[i] = std::max(level.margin[i], std::abs(step[i]));
      std::vector<Step> steps;
      for (const auto& [g2, step] : list) steps.push_back(step);
      level.lists[half].resize(steps.size());
      // Linear offsets are taken once the padded strides are known (below).
      scratch_[half] = std::move(steps);
    }
    double total = 1.0;
    std::size_t stride = 1;
    for (int i = 0; i < D; ++i) {
      level.padded[i] = level.cells[i] + 2 * level.margin[i];
      level.stride[i] = stride;
      stride *= static_cast<std::size_t>(level.padded[i]);
      total *= level.padded[i];
      if (total > static_cast<double>(kMaxGridCells)) throw_too_many(level.start);
      // Interior (torus): the list stays inside the domain and the axis has
      // more than 2 (margin + 1) cells, so two points in cells at most
      // `margin` apart differ by under half a period with half a cell to
      // spare: the min-image correction cannot apply.
      level.interior[i] = !domain_.periodic ? std::numeric_limits<unsigned>::max()
                          : level.cells[i] > 2 * (level.margin[i] + 1)
                              ? static_cast<unsigned>(level.cells[i] - 2 * level.margin[i])
                              : 0u;
    }
    for (unsigned half = 0; half < (1u << D); ++half) {
      auto& linear = level.lists[half];
      for (std::size_t j = 0; j < scratch_[half].size(); ++j) {
        std::ptrdiff_t off = 0;
        for (int i = 0; i < D; ++i)
          off += static_cast<std::ptrdiff_t>(scratch_[half][j][i]) * static_cast<std::ptrdiff_t>(level.stride[i]);
        linear[j] = off;
      }
      // Whole blocks, padded with the own cell: when a query gets past the
      // first block its own cell is empty (a sample of the level there would
      // lie closer than s_l).
      while (linear.size() % kBlock) linear.push_back(0);
    }
    std::size_t blocks = 1;
    for (int i = 0; i < D; ++i) {
      level.others_stride[i] = blocks;
      blocks *= static_cast<std::size_t>((level.cells[i] + kBlockCells - 1) >> kBlockShift);
    }
    level.blocks = blocks;
    level.grid = zeroed<Cell>(stride);
  }

  std::size_t block_of(const Level& level, const Query& q) const {
    std::size_t block = 0;
    for (int i = 0; i < D; ++i) block += static_cast<std::size_t>(q.coords[i] >> kBlockShift) * level.others_stride[i];
    return block;
  }

  bool conflicts(const Query& q) const {
    const Level& level = levels_[static_cast<std::size_t>(q.level)];
    const auto& list = level.lists[q.half];
    if (q.mode == 0   ? scan<false, false>(level, q, list)
        : q.mode == 1 ? scan<false, true>(level, q, list)
                      : scan<true, true>(level, q, list))
      return true;
    if (levels_.size() > 1)
      for (std::uint32_t flagged = level.others[block_of(level, q)]; flagged; flagged &= flagged - 1) {
        const int l = std::countr_zero(flagged);
        // Finer levels hold radii below r: out to r; coarser ones out to their bound.
        const Level& other = levels_[static_cast<std::size_t>(l)];
        if (!cells_near(other, q.x, l < q.level ? q.r : other.bound)) continue;
        // Padded indices: the margin shifts every coordinate.
        std::size_t offset = 0;
        for (int i = 0; i < D; ++i) offset += static_cast<std::size_t>(other.margin[i]) * other.stride[i];
        if (!for_each_row(other.stride, offset, [&](std::size_t row) {
              for (const int c : axes_[0])
                if (hit(q, other, row + static_cast<std::size_t>(c))) return false;
              return true;
            }))
          return true;
      }
    return overflow_ && overflow_->conflicts(q.x, q.r);
  }

  void insert(const Query& q) {
    Level& level = levels_[static_cast<std::size_t>(q.level)];
    if (level.grid[q.cell].r2 != 0.0) {
      // Only where the pair rule was not enforced (fixed points).
      if (!overflow_) overflow_ = std::make_unique<RadiusLevels<D>>(domain_, starts_.front(), rmax_);
      overflow_->insert(q.x, q.r);
    } else {
      level.grid[q.cell] = Cell{q.x, q.r2};
      if (domain_.periodic) copy_to_margin(level, q);
    }
    cover(q.x, q.r);
    const std::uint32_t bit = std::uint32_t{1} << q.level;
    for (int l = 0; l < levels(); ++l) {
      if (l == q.level) continue;
      Level& other = levels_[static_cast<std::size_t>(l)];
      // A query at a finer level conflicts within r; at a coarser one, within
      // its own radius, below that level's bound.
      if (!cells_near(other, q.x, l < q.level ? q.r : other.bound, kBlockShift)) continue;
      for_each_row(other.others_stride, 0, [&](std::size_t row) {
        for (const int c : axes_[0]) other.others[row + static_cast<std::size_t>(c)] |= bit;
        return true;
      });
    }
  }

  // Calls f(index of the row's start) for each combination of axes_[1..D-1]
  // (index = offset + the sum of coordinate x stride, axis 0 left out); f
  // returns false to stop. Returns false if stopped.
  template <class F>
  bool for_each_row(const std::array<std::size_t, D>& stride, std::size_t offset, F&& f) const {
    std::array<std::size_t, D> at{};
    for (;;) {
      std::size_t row = offset;
      for (int i = 1; i < D; ++i) row += static_cast<std::size_t>(axes_[i][at[i]]) * stride[i];
      if (!f(row)) return false;
      int axis = 1;
      while (axis < D && ++at[axis] == axes_[axis].size()) {
        at[axis] = 0;
        ++axis;
      }
      if (axis == D) return true;
    }
  }

  // Whether the sample of a cell (padded index) conflicts with the query; an
  // empty cell never does.
  [[gnu::always_inline]] bool hit(const Query& q, const Level& level, std::size_t cell) const {
    const Cell& c = level.grid[cell];
    return c.r2 != 0.0 && domain_.distance2(q.x, c.p) < std::max(q.r2, c.r2);
  }

  // The cells of the list around the query's cell, kBlock at a time with one
  // branch a block, two cells a vector: the arithmetic is Domain::distance2's,
  // term for term, lane by lane. A lane conflicts when d2 < r2 or d2 < the
  // sample's r2. An empty cell holds zeros: its r2 of 0 never passes
  // (d2 >= 0), and its coordinates give d2 = |x|^2, which passes d2 < r2 only
  // when x lies within r of the origin: then (Masked) a lane also needs a
  // sample in the cell. With MinImage the torus correction is applied as in
  // Domain::delta (the two masks exclude each other; always Masked, as an
  // image of the origin may be near); without it the difference is taken as
  // is, the same arithmetic where the correction never applies (away from
  // the faces, Query::mode).
  template <bool MinImage, bool Masked>
  [[gnu::always_inline]] bool scan(const Level& level, const Query& q, const std::vector<std::ptrdiff_t>& list) const {
    typedef double Pair __attribute__((vector_size(16)));
    typedef std::int64_t Mask __attribute__((vector_size(16)));
    const Cell* base = level.grid.get() + q.cell;
    const Pair r2 = {q.r2, q.r2}, zero = {0.0, 0.0};
    for (std::size_t j = 0; j < list.size(); j += kBlock) {
      Mask closer = {0, 0};
      for (std::size_t t = j; t < j + kBlock; t += 2) {
        const Cell& a = base[list[t]];
        const Cell& b = base[list[t + 1]];
        Pair s = zero;  // set at i == 0; initialised for -Wmaybe-uninitialized at -O1
        for (int i = 0; i < D; ++i) {
          Pair d = Pair{a.p[i], b.p[i]} - q.x[i];
          if constexpr (MinImage) {
            const Pair half = {half_[i], half_[i]}, extent = {domain_.extent(i), domain_.extent(i)};
            const Mask above = d > half, below = d < -half;
            d -= (Pair)((Mask)extent & above);
            d += (Pair)((Mask)extent & below);
          }
          s = i == 0 ? d * d : s + d * d;
        }
        const Pair rq2 = {a.r2, b.r2};
        if constexpr (Masked)
          closer |= ((s < r2) & (rq2 > zero)) | (s < rq2);
        else
          closer |= (s < r2) | (s < rq2);
      }
      if (closer[0] | closer[1]) return true;
    }
    return false;
  }

  // Fills axes_ with the real cells of `level`, per axis, that a point
  // closer than `reach` to x can lie in, each once (wrapped on a torus,
  // clipped in a box); false when there are none. With a shift, the blocks
  // of 2^shift cells that hold them instead (on a torus whose count is not a
  // multiple, a block may come twice).
  bool cells_near(const Level& level, const Point<D>& x, double reach, int shift = 0) const {
    reach += level.widen;
    for (int i = 0; i < D; ++i) {
      const double u = x[i] - domain_.lo[i];
      int a = floor_int((u - reach) * level.inv_edge[i]);
      int b = floor_int((u + reach) * level.inv_edge[i]);
      const int n = level.cells[i];
      if (domain_.periodic) {
        if (b - a + 1 >= n) {
          a = 0;
          b = n - 1;
        }
      } else {
        a = std::max(a, 0);
        b = std::min(b, n - 1);
        if (a > b) return false;
      }
      auto& axis = axes_[i];
      axis.clear();
      int c = a;
      if (c < 0 || c >= n) c = ((c % n) + n) % n;
      for (int left = b - a + 1; left > 0;) {
        // From c to the end of its block, or of the axis.
        const int block = c >> shift, end = std::min((block + 1) << shift, n);
        axis.push_back(shift ? block : c);
        const int step = std::min(end - c, left);
        left -= step;
        c += step;
        if (c == n) c = 0;
      }
    }
    return true;
  }

  // Sets the bits of the cover's cells that lie wholly within rho of x,
  // rho = r less a margin far above the rounding of the cell arithmetic and
  // of Domain::distance2 (so every point of such a cell has a computed
  // distance below r from x). Rows (axis 0) are spans of bits; on a torus
  // cells are taken at the image nearest x's, and the distance to that image
  // bounds the min-image one.
  void cover(const Point<D>& x, double r) {
    const double rho = r * (1.0 - 1e-7) - 64.0 * std::numeric_limits<double>::epsilon() * scale_;
    if (!(rho > 0.0)) return;
    // On a torus a period shorter than the ball is left uncovered (nothing
    // is lost but speed), so cells are taken within a period either way.
    for (int i = 0; i < D; ++i)
      if (domain_.periodic && 2.0 * rho >= domain_.extent(i)) return;
    std::array<int, D> first, last, at;
    for (int i = 0; i < D; ++i) {
      const double u = x[i] - domain_.lo[i];
      first[i] = floor_int((u - rho) * cover_inv_edge_[i]);
      last[i] = floor_int((u + rho) * cover_inv_edge_[i]);
      if (!domain_.periodic) {
        first[i] = std::max(first[i], 0);
        last[i] = std::min(last[i], cover_cells_[i] - 1);
      }
      at[i] = first[i];
    }
    for (;;) {
      // The largest squared distance from x over the row's band along axes 1..D-1.
      double far2 = 0.0;
      std::size_t row = 0;
      for (int i = 1; i < D; ++i) {
        const double a = at[i] * cover_edge_[i] + domain_.lo[i] - x[i];
        const double b = (at[i] + 1) * cover_edge_[i] + domain_.lo[i] - x[i];
        const double f = std::max(std::abs(a), std::abs(b));
        far2 += f * f;
        int c = at[i];  // within a period of [0, n) on a torus, itself in a box
        if (c < 0) c += cover_cells_[i];
        if (c >= cover_cells_[i]) c -= cover_cells_[i];
        row += static_cast<std::size_t>(c) * cover_row_stride_[i];
      }
      if (far2 < rho * rho) cover_row(x, rho * rho - far2, row);
      int axis = 1;
      while (axis < D && ++at[axis] > last[axis]) {
        at[axis] = first[axis];
        ++axis;
      }
      if (axis == D) break;
    }
  }

  // Sets the bits of the row's cells (axis 0) whose span lies within
  // sqrt(w2) of x[0] (the margin of cover() absorbs the rounding here).
  void cover_row(const Point<D>& x, double w2, std::size_t row) {
    const double w = std::sqrt(w2);
    const double u = x[0] - domain_.lo[0];
    int a = ceil_int((u - w) * cover_inv_edge_[0]);
    int b = floor_int((u + w) * cover_inv_edge_[0]) - 1;
    const int n = cover_cells_[0];
    if (!domain_.periodic) {
      a = std::max(a, 0);
      b = std::min(b, n - 1);
    }
    if (a > b) return;
    if (b - a + 1 >= n) {
      set_bits(row, 0, n - 1);
      return;
    }
    int start = a;  // within a period of [0, n): a cell of x's or next to it
    if (start < 0) start += n;
    if (start >= n) start -= n;
    const int end = start + (b - a);
    if (end < n) {
      set_bits(row, start, end);
    } else {
      set_bits(row, start, n - 1);
      set_bits(row, 0, end - n);
    }
  }

  // Bits a to b (inclusive) of a row.
  void set_bits(std::size_t row, int a, int b) {
    for (int w = a >> 6; w <= b >> 6; ++w) {
      const int lo = std::max(a - (w << 6), 0), hi = std::min(b - (w << 6), 63);
      const std::uint64_t ones = ~std::uint64_t{0};
      cover_[row + static_cast<std::size_t>(w)] |= (ones >> (63 - hi)) & (ones << lo);
    }
  }

  // On a torus the margin mirrors the cells of the opposite faces: the
  // sample is written to every padded position congruent to its cell (the
  // bits of Level::others are the real cells').
  void copy_to_margin(Level& level, const Query& q) {
    std::array<int, D> first, at;
    bool any = false;
    for (int i = 0; i < D; ++i) {
      const int padded = static_cast<int>(q.cell / level.stride[i] % static_cast<std::size_t>(level.padded[i]));
      first[i] = padded % level.cells[i];
      at[i] = first[i];
      any |= first[i] + level.cells[i] < level.padded[i];
    }
    if (!any) return;
    for (;;) {
      std::size_t index = 0;
      for (int i = 0; i < D; ++i) index += static_cast<std::size_t>(at[i]) * level.stride[i];
      level.grid[index] = Cell{q.x, q.r2};
      int axis = 0;
      while (axis < D && (at[axis] += level.cells[axis]) >= level.padded[axis]) {
        at[axis] = first[axis];
        ++axis;
      }
      if (axis == D) break;
    }
  }

  Domain<D> domain_;
  double rmax_;
  double scale_ = 0.0;  // the largest |coordinate| of the bounds
  std::array<double, D> half_{};
  std::vector<Level> levels_;
  std::vector<double> starts_;  // the smallest radius of each level
  std::vector<double> ends_;    // the next level's start (the last: infinity)
  std::array<std::vector<std::array<int, D>>, (1u << D)> scratch_;
  mutable std::array<std::vector<int>, D> axes_;  // cells_near()'s answer
  std::unique_ptr<RadiusLevels<D>> overflow_;
  // The cover: a bit per cell of a grid of edge about rmin / kCoverSplit,
  // set where a sample's own ball holds the whole cell (cover()).
  static constexpr double kCoverSplit = 2.5;
  static constexpr double kRowSplit = 2.0;
  static constexpr double kMaxCoverBits = 8.0 * (1 << 27);  // 128 MiB
  std::array<int, D> cover_cells_{};
  std::array<double, D> cover_inv_edge_{}, cover_edge_{};
  std::array<std::size_t, D> cover_row_stride_{};  // words; axis 0 is the bit within the row
  std::size_t cover_words_ = 0;                    // a row's
  detail::MappedArray<std::uint64_t> cover_;
};

}  // namespace pds::detail
