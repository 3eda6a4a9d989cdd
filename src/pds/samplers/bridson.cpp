// R. Bridson, Fast Poisson disk sampling in arbitrary dimensions, ACM
// SIGGRAPH 2007 sketches, article 22.
//
// Method: a background grid of cell edge r/sqrt(D) holds at most one sample a
// cell. Start from one uniform sample and make it active. While samples are
// active: pick one at random, draw up to k candidates uniformly from the
// spherical annulus between r and 2r around it (uniform by volume); the first
// candidate with no sample closer than r (the grid cells within reach) becomes
// a sample and is made active; if all k fail, the active sample retires.
// On a torus candidates are wrapped into the domain and distances are to the
// nearest periodic image; in a box candidates outside are discarded (they
// count towards k).
//
// SciPy's loop (BridsonParams::scipy, docs/bridson.md "SciPy's loop"): a
// picked sample leaves the pool at once after exactly k candidates in the ball
// of radius 2r, every free one kept; those inside r are only counted.
//
// Guarantees: minimum distance >= r in the exact arithmetic of
// Domain::distance2 (the same formula, so the all-pairs oracle agrees to the
// last bit); samples in [lo, hi); same seed, same points. Near-maximal, not
// proven maximal. Relative radius ~0.73 (2D) measured, docs/bridson.md. In
// 2D each accepted candidate is moved onto the grid's lattice (float
// offsets from a tile corner: a move of under 3e-5 r) and tested there,
// so the samples are points of that lattice.
//
// Complexity: O(k N) candidate checks, each a fixed number of cells (the own
// cell and 15 neighbours in 2D, and 90 in 3D, for the usual reach of 2; typically
// the first 8, nearest cells first). Memory: the grid, about 3 cells a sample
// in 2D (8 bytes each) and 9 in 3D (4 bytes each), and the output.
//
// Speed (why not pds::Grid): this is the hot loop of the project, so the grid
// here is specialised (docs/bridson.md, "Speed"). In 2D cells store the
// sample itself (float offsets from its tile's corner), in 1D its coordinate,
// in 3D its index in the output (BridsonGrid says why); an empty cell reads
// as NaN coordinates, which compare
// as "not closer", so the scan has no occupancy branch; a margin of `reach` cells around the
// domain removes bounds checks and, on a torus, holds copies of the samples
// near the opposite faces (their original coordinates, so the distance is the
// domain's min-image formula); away from the faces the min-image correction
// provably never applies and is skipped. Neighbour cells are read nearest
// first (own cell first), eight at a time with one branch, two cells a
// vector (their offsets are pds::GridNeighbourhood's, over the padded grid;
// its wrap is not used: the margin leaves the scan plain index arithmetic);
// the rows a picked sample's candidates can touch are prefetched; annulus
// offsets are drawn ahead in branch-free batches.

#include "pds/samplers/bridson.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/grid.h"
#include "pds/grid_neighbourhood.h"
#include "pds/limits.h"
#include "pds/rng.h"
#include "pds/samplers/elimination.h"
#include "pds/samplers/random.h"
#include "pds/samplers/sizing.h"
#include "annulus_offsets.h"
#include "mapped_pages.h"
#include "pds/detail/instantiate.h"

namespace pds {
namespace {

template <int D, bool Periodic>
class BridsonGrid {
  // What a cell holds (NaN when empty: the scan has no occupancy branch).
  // In 2D the sample itself, as float offsets from the lower corner of its
  // tile of kTile x kTile cells: the scan reads it with no indirection (twice
  // as fast as through an index at 10^6) in half the bytes of double
  // coordinates. Every sample is put on that lattice (a move of under 3e-5 r)
  // before it is tested (is_free), so tile corner + offset, rounded to
  // double, is the sample exactly and the scan's distances are the output's. 1D keeps double coordinates (no smaller). In 3D, with nine
  // cells a sample, coordinates made the grid ten times the output (224 MB
  // at 10^6); there a cell holds the sample's index in the store (0, the NaN
  // marker, when empty): a sixth of the memory and no slower (measured,
  // docs/bridson.md).
  static constexpr bool kIndexed = D >= 3;
  static constexpr bool kLattice = D == 2;
  using Cell = std::conditional_t<kIndexed, std::uint32_t, std::conditional_t<kLattice, std::array<float, D>, Point<D>>>;
  static constexpr int kTileBits = 8, kTile = 1 << kTileBits;

 public:
  using Offsets = std::array<float, D>;
  /// A candidate that is_free() accepted, as it becomes a sample: the point
  /// (on the lattice in 2D) and its offsets there.
  struct Placed {
    Point<D> point;
    Offsets offsets;
  };
  /// `store` holds the samples, store[0] the empty marker (NaN); a cell
  /// holds its sample's index there.
  BridsonGrid(const Domain<D>& domain, double radius, const PointSet<D>& store)
      : radius2_(radius * radius),
        // A point on the lattice lies within 3e-5 r of where it was drawn
        // (float offsets below 256 cells, 512 units of at most r / sqrt 2:
        // half a float step is under 1.1e-5 r, a whole one at a cell's face
        // 2.2e-5 r), and 1e-4 r covers that with room for the rounding of any
        // distance.
        inner_radius2_(radius * radius * (1.0 - 1e-4) * (1.0 - 1e-4)),
        store_(store) {
    // Slightly under r/sqrt(D) so that two samples r apart can never share a
    // cell, whatever the rounding of the cell arithmetic.
    const double max_edge = radius / std::sqrt(static_cast<double>(D)) * (1.0 - 1e-9);
    // Lattice offsets are counted in a power of two near a cell's edge, so
    // that floats hold them at every scale a domain may have (extents from
    // 1e-150 to 1e150) and scaling by it is exact.
    unit_ = std::ldexp(1.0, std::ilogb(max_edge));
    inv_unit_ = 1.0 / unit_;
    inner_radius2_f_ = static_cast<float>(radius * inv_unit_ * radius * inv_unit_ * kInnerFloat * kInnerFloat);
    double total = 1.0;
    for (int i = 0; i < D; ++i) {
      lo_[i] = domain.lo[i];
      extent_[i] = domain.extent(i);
      half_[i] = 0.5 * extent_[i];
      const double n = std::max(1.0, std::ceil(extent_[i] / max_edge));
      if (n > 1e9)
        throw InvalidArgument("bridson: radius " + detail::format_number(radius) + " is too small for the domain");
      cells_[i] = static_cast<int>(n);
      inv_edge_[i] = n / extent_[i];
      twice_inv_edge_[i] = 2.0 * inv_edge_[i];
    }
    // Cells within reach along an axis: |dx| < r spans at most floor(r/e) + 1
    // cells from the sample's own, and more than the axis's cell count adds
    // nothing (a box has no more; a torus repeats). With cell counts rounded
    // up this is at most 3 for D <= 3.
    reach_ = 1;
    for (int i = 0; i < D; ++i)
      reach_ = std::max(reach_, static_cast<int>(std::min(std::floor(radius * inv_edge_[i]) + 1.0, double(cells_[i]))));
    if (reach_ > kMaxReach)
      throw InvalidArgument("bridson: dimension " + std::to_string(D) + " needs a wider neighbourhood than supported");
    // A cell is interior when its neighbourhood (reach cells each way) lies
    // in the domain. On a torus the min-image correction is then a no-op:
    // two points in cells at most reach apart along an axis differ by less
    // than (reach + 1) cells, which is under half the period by half a cell
    // or more when the axis has more than 2 (reach + 1) cells (a margin far
    // above the rounding of the cell arithmetic). On shorter axes no cell is
    // interior.
    for (int i = 0; i < D; ++i)
      interior_cells_[i] = cells_[i] > 2 * (reach_ + 1) ? static_cast<unsigned>(cells_[i] - 2 * reach_) : 0u;
    if (!Periodic) interior_cells_.fill(std::numeric_limits<unsigned>::max());
    // The padded grid: the domain and `reach` cells of margin each way, as a
    // box (the margin, not an index wrap, takes care of the torus).
    Domain<D> padded_box = Domain<D>::box(domain.lo, domain.hi);
    std::array<int, D> padded;
    for (int i = 0; i < D; ++i) {
      padded[i] = cells_[i] + 2 * reach_;
      total *= padded[i];
      if (total > static_cast<double>(kMaxGridCells))
        throw InvalidArgument("bridson: radius " + detail::format_number(radius) + " needs more than " +
                              std::to_string(kMaxGridCells) + " background cells for this domain");
      padded_box.lo[i] -= reach_ * extent_[i] / cells_[i];
      padded_box.hi[i] += reach_ * extent_[i] / cells_[i];
    }
    // A local, not a member: grow() inlines this constructor, and the code
    // of its hot loop moved with what the setup did with `this` (callgrind,
    // 3D torus: 1.5% more instructions with a member, 1.1% with a local, as
    // much as an unrelated getenv() in this constructor moved it).
    const GridNeighbourhood<D> layout(padded_box, padded);
    for (int i = 0; i < D; ++i) {
      padded_[i] = padded[i];
      stride_[i] = layout.stride(i);
    }
    // Huge pages where offered (mapped_pages.h): the front sweeps over
    // every cell, and with coordinates every cell is written here (a tenth
    // of the 2D run at 10^6 went to 4 KiB page faults). A zero index is empty.
    grid_ = detail::map_zeroed<Cell>(layout.size(), detail::Pages::kHuge);
    if constexpr (!kIndexed) {
      Cell empty;
      empty.fill(std::numeric_limits<typename Cell::value_type>::quiet_NaN());
      std::fill_n(grid_.get(), layout.size(), empty);
    }
    if constexpr (kLattice) {
      for (int i = 0; i < D; ++i) {
        const double step = extent_[i] / cells_[i];
        // Each padded position's tile corner: in the margin of a torus that
        // of the cell it mirrors (its copies keep their offsets from there).
        tile_corner_[i].resize(static_cast<std::size_t>(padded[i]));
        for (int j = 0; j < padded[i]; ++j) {
          const int c = ((j - reach_) % cells_[i] + cells_[i]) % cells_[i];
          tile_corner_[i][static_cast<std::size_t>(j)] = lo_[i] + static_cast<double>(c >> kTileBits << kTileBits) * step;
        }
        // Each cell's faces (the last one's upper face: hi exactly).
        cell_lo_[i].resize(static_cast<std::size_t>(cells_[i]));
        cell_hi_[i].resize(static_cast<std::size_t>(cells_[i]));
        for (int c = 0; c < cells_[i]; ++c) {
          cell_lo_[i][static_cast<std::size_t>(c)] = c == 0 ? lo_[i] : lo_[i] + static_cast<double>(c) * step;
          cell_hi_[i][static_cast<std::size_t>(c)] =
              c + 1 == cells_[i] ? domain.hi[i] : lo_[i] + static_cast<double>(c + 1) * step;
        }
      }
    }
    build_offsets(layout, radius);
    // Offsets of the rows (along axis 0) that prefetch_around() fetches, axis
    // 1 fastest.
    std::vector<std::array<int, D>> rows;
    std::array<int, D> o;
    o.fill(-kPrefetchReach);
    o[0] = 0;
    while (true) {
      rows.push_back(o);
      int axis = 1;
      while (axis < D && ++o[axis] > kPrefetchReach) o[axis++] = -kPrefetchReach;
      if (axis == D) break;
    }
    prefetch_rows_ = layout.stencil(std::move(rows)).linear;
  }

  /// True if no stored sample is closer than the radius to p; `cell` receives
  /// p's cell for insert(). In 2D p is moved onto the lattice (by at most
  /// 3e-5 r; it stays in its cell and in the domain) and the point on the
  /// lattice is what is tested; one that cannot be placed there is refused.
  [[gnu::always_inline]] bool is_free(const Point<D>& p, std::size_t& cell, Placed& placed) const {
    cell = 0;
    unsigned half = 0;     // which half of its cell p lies in, along each axis
    bool interior = true;  // all cells within reach are inside the domain, none in the margin
    bool one_tile = true;   // all cells within reach are in p's tile (or empty margin cells of a box)
    std::array<int, D> at;  // p's position in the padded grid
    for (int i = 0; i < D; ++i) {
      // Position in half-cells (doubling is exact): its low bit is the half.
      const int h = std::min(static_cast<int>((p[i] - lo_[i]) * twice_inv_edge_[i]), 2 * cells_[i] - 1);
      const int c = h >> 1;
      half |= static_cast<unsigned>(h & 1) << i;
      interior &= static_cast<unsigned>(c - reach_) < interior_cells_[i];
      one_tile &= static_cast<unsigned>((c & (kTile - 1)) - reach_) <= static_cast<unsigned>(kTile - 1 - 2 * reach_);
      at[i] = c + reach_;
      cell += static_cast<std::size_t>(at[i]) * stride_[i];
    }
    if constexpr (kLattice) {
      // Most candidates fail. A sample closer than the inner radius to p is
      // closer than r to p's point on the lattice, so p is tested first, as
      // it is, and only a candidate that passes is moved onto the lattice
      // (a chain of conversions the test would otherwise wait for) and
      // tested again, exactly. Within one tile, off the faces of a torus
      // (nearly every candidate) the first test runs in float, in the
      // tile's frame, four cells a vector.
      if (one_tile && !(Periodic && !interior)) {
        if (!scan_in_tile(p, cell, at, half)) return false;
      } else if (!scan_any(p, cell, at, half, interior, one_tile, inner_radius2_)) {
        return false;
      }
      return settle_on_lattice(p, cell, at, interior, one_tile, placed);
    }
    if (!scan_any(p, cell, at, half, interior, one_tile, radius2_)) return false;
    placed.point = p;
    return true;
  }

  // Asks for the cells that the candidates around `centre` will read, all at
  // once: picks jump around the front, so otherwise each candidate waits for
  // its own cache misses in turn.
  [[gnu::always_inline]] void prefetch_around(const Point<D>& centre) const {
    std::ptrdiff_t cell = 0;
    for (int i = 0; i < D; ++i) {
      const int c = std::min(static_cast<int>((centre[i] - lo_[i]) * inv_edge_[i]), cells_[i] - 1);
      cell += static_cast<std::ptrdiff_t>(c + reach_) * static_cast<std::ptrdiff_t>(stride_[i]);
    }
    // A fixed number of lines a row, so that the loops are predicted; a
    // prefetch never faults, so lines past either end of the grid are harmless.
    constexpr int kLines = ((2 * kPrefetchReach + 1) * static_cast<int>(sizeof(Cell)) + 63) / 64 + 1;
    const std::uintptr_t base = reinterpret_cast<std::uintptr_t>(grid_.get());
    for (std::ptrdiff_t row : prefetch_rows_) {
      const std::uintptr_t first =
          base + static_cast<std::uintptr_t>(cell + row - kPrefetchReach) * sizeof(Cell);
      for (int line = 0; line < kLines; ++line) __builtin_prefetch(reinterpret_cast<const char*>(first + 64 * line));
    }
  }

  /// Files store[index] in its cell (p and cell from the is_free() just
  /// before, which said yes).
  void insert(const Placed& placed, std::size_t cell, std::size_t index) {
    Cell value;
    if constexpr (kIndexed)
      value = static_cast<std::uint32_t>(index);  // fewer than kMaxGridCells < 2^32 samples
    else if constexpr (kLattice)
      value = placed.offsets;
    else
      value = placed.point;
    grid_[cell] = value;
    if constexpr (Periodic) copy_to_margin(value, cell);
  }

 private:
  // The rare second step of is_free(): p passed against the inner radius;
  // moves it onto the lattice and tests it exactly. Not inlined: the hot
  // loop is the first step.
  // (The candidate itself is not touched: passed by reference to a call, it
  // would live in memory, not registers, in the hot loop.)
  [[gnu::noinline]] bool settle_on_lattice(const Point<D>& candidate, std::size_t cell, const std::array<int, D>& at,
                                           bool interior, bool one_tile, Placed& placed) const {
    Point<D>& p = placed.point;
    p = candidate;
    if (!to_lattice(p, at, placed.offsets)) return false;
    unsigned half = 0;
    for (int i = 0; i < D; ++i) {
      // The half of the cell p now lies in (the cell stays: to_lattice keeps
      // p within its faces, which the formula may place an ulp off).
      const int h = static_cast<int>((p[i] - lo_[i]) * twice_inv_edge_[i]) - 2 * (at[i] - reach_);
      half |= static_cast<unsigned>(std::clamp(h, 0, 1)) << i;
    }
    return scan_any(p, cell, at, half, interior, one_tile, radius2_);
  }

  // The first test of a candidate whose neighbours all share its tile, in
  // float, in units from the tile's corner: false if a sample lies closer
  // than kInnerFloat r. Conservative: p's offset rounds by at most 1.1e-5 r
  // (half a float step below 512 units), so a distance near r comes out
  // within 2.2e-5 r (5e-5 r^2 squared, with the rounding of squares and
  // sums), far inside the 1e-3 r between kInnerFloat r and r; and a point on
  // the lattice lies within 3e-5 r of p.
  [[gnu::always_inline]] bool scan_in_tile(const Point<D>& p, std::size_t cell, const std::array<int, D>& at,
                                           unsigned half) const {
    typedef float Two __attribute__((vector_size(8)));
    typedef float Four __attribute__((vector_size(16)));
    typedef std::int32_t Mask4 __attribute__((vector_size(16)));
    const std::vector<std::ptrdiff_t>& offsets = offsets_[half];
    const Cell* base = grid_.get() + cell;
    std::array<Four, D> q;
    for (int i = 0; i < D; ++i) {
      const float x = static_cast<float>((p[i] - tile_corner_[i][static_cast<std::size_t>(at[i])]) * inv_unit_);
      q[i] = Four{x, x, x, x};
    }
    const Four inner2 = {inner_radius2_f_, inner_radius2_f_, inner_radius2_f_, inner_radius2_f_};
    for (std::size_t j = 0; j < offsets.size(); j += kBlock) {
      Mask4 closer = {0, 0, 0, 0};
      for (std::size_t t = j; t < j + kBlock; t += 4) {
        Two c0, c1, c2, c3;
        std::memcpy(&c0, &base[offsets[t]], sizeof c0);
        std::memcpy(&c1, &base[offsets[t + 1]], sizeof c1);
        std::memcpy(&c2, &base[offsets[t + 2]], sizeof c2);
        std::memcpy(&c3, &base[offsets[t + 3]], sizeof c3);
        const Four a = __builtin_shufflevector(c0, c1, 0, 1, 2, 3), b = __builtin_shufflevector(c2, c3, 0, 1, 2, 3);
        const Four dx = __builtin_shufflevector(a, b, 0, 2, 4, 6) - q[0];
        const Four dy = __builtin_shufflevector(a, b, 1, 3, 5, 7) - q[1];
        closer |= dx * dx + dy * dy < inner2;  // an empty cell's NaN compares as "not closer"
      }
      if (closer[0] | closer[1] | closer[2] | closer[3]) return false;
    }
    return true;
  }

  // Away from the faces of a torus no neighbour is a periodic image and the
  // min-image correction never applies (see interior_cells_).
  [[gnu::always_inline]] bool scan_any(const Point<D>& p, std::size_t cell, const std::array<int, D>& at,
                                       unsigned half, bool interior, [[maybe_unused]] bool one_tile,
                                       double radius2) const {
    if (Periodic && !interior) return scan<true, false>(p, cell, at, half, radius2);
    if constexpr (kLattice)
      if (one_tile) return scan<false, true>(p, cell, at, half, radius2);
    return scan<false, false>(p, cell, at, half, radius2);
  }

  // Moves p to its tile's corner + a float offset times unit_ (rounded to
  // double, as the scan reconstructs it), the nearest such point within p's cell (the
  // cell at padded position `at`): two samples of one cell would be closer
  // than r. False in the rare case where rounding leaves no such point next
  // to p (p against a cell's face far from the origin), which then counts
  // as a rejected candidate.
  [[gnu::always_inline]] bool to_lattice(Point<D>& p, const std::array<int, D>& at, Offsets& lattice) const {
    for (int i = 0; i < D; ++i) {
      const double corner = tile_corner_[i][static_cast<std::size_t>(at[i])];
      const double lower = cell_lo_[i][static_cast<std::size_t>(at[i] - reach_)];
      const double upper = cell_hi_[i][static_cast<std::size_t>(at[i] - reach_)];
      float offset = static_cast<float>((p[i] - corner) * inv_unit_);
      double q = corner + static_cast<double>(offset) * unit_;
      if (!(q >= lower)) {
        offset = std::nextafter(static_cast<float>((lower - corner) * inv_unit_), std::numeric_limits<float>::infinity());
        q = corner + static_cast<double>(offset) * unit_;
      } else if (!(q < upper)) {
        offset = std::nextafter(static_cast<float>((upper - corner) * inv_unit_), 0.0f);
        q = corner + static_cast<double>(offset) * unit_;
      }
      if (!(q >= lower && q < upper)) return false;
      p[i] = q;
      lattice[i] = offset;
    }
    return true;
  }

  // False if a sample lies closer than sqrt(limit2) to p. Reads the cells of
  // the half-cell's list around p's cell, kBlock at a time with one branch
  // a block (the exit is taken once, not tested and mispredicted once a
  // cell), two cells a vector: the arithmetic is Domain::distance2's, term
  // for term, lane by lane (an empty cell's NaN compares as "not closer").
  // With MinImage the torus correction is applied as in Domain::delta (the
  // two masks exclude each other, and subtracting a masked 0 changes
  // nothing); without it the difference is taken as is, which is the same
  // arithmetic where the correction never applies (is_free's `interior`).
  template <bool MinImage, bool OneTile>
  [[gnu::always_inline]] bool scan(const Point<D>& p, std::size_t cell, [[maybe_unused]] const std::array<int, D>& at,
                                   unsigned half, double limit2) const {
    typedef double Pair __attribute__((vector_size(16)));
    typedef std::int64_t Mask __attribute__((vector_size(16)));
    const std::vector<std::ptrdiff_t>& offsets = offsets_[half];
    const Cell* base = grid_.get() + cell;
    const Point<D>* store = store_.data();
    // Lattice cells: each neighbour's tile corner, p's when all share its
    // tile, else looked up through the neighbour's steps along each axis.
    [[maybe_unused]] std::array<const double*, D> corner;
    [[maybe_unused]] std::array<const std::int8_t*, D> step;
    if constexpr (kLattice)
      for (int i = 0; i < D; ++i) {
        corner[i] = tile_corner_[i].data() + at[i];
        step[i] = steps_[half][i].data();
      }
    const Pair radius2 = {limit2, limit2};
    for (std::size_t j = 0; j < offsets.size(); j += kBlock) {
      if constexpr (kIndexed) {
        // A block of empty cells (a third of them in 3D) is passed over
        // without reading the store: 3-4% of the 3D run at 10^6.
        std::uint32_t any = 0;
        for (std::size_t t = j; t < j + kBlock; ++t) any |= base[offsets[t]];
        if (any == 0) continue;
      }
      Mask closer = {0, 0};
      for (std::size_t t = j; t < j + kBlock; t += 2) {
        // The two cells' samples, axis by axis (lane 0 cell t, lane 1 cell t + 1).
        std::array<Pair, D> xs;
        if constexpr (kLattice) {
          // Both offsets of a cell converted at once, then regrouped by axis;
          // plus the tile corners: the samples exactly as to_lattice() made them.
          typedef float Floats __attribute__((vector_size(8)));
          Floats fa, fb;
          std::memcpy(&fa, &base[offsets[t]], sizeof fa);
          std::memcpy(&fb, &base[offsets[t + 1]], sizeof fb);
          const Pair a = __builtin_convertvector(fa, Pair), b = __builtin_convertvector(fb, Pair);
          const Pair unit = {unit_, unit_};  // a power of two: exact
          xs[0] = __builtin_shufflevector(a, b, 0, 2) * unit;
          xs[1] = __builtin_shufflevector(a, b, 1, 3) * unit;
          for (int i = 0; i < D; ++i)
            xs[i] += OneTile ? Pair{corner[i][0], corner[i][0]} : Pair{corner[i][step[i][t]], corner[i][step[i][t + 1]]};
        } else {
          for (int i = 0; i < D; ++i) {
            if constexpr (kIndexed)
              xs[i] = Pair{store[base[offsets[t]]][i], store[base[offsets[t + 1]]][i]};
            else
              xs[i] = Pair{base[offsets[t]][i], base[offsets[t + 1]][i]};
          }
        }
        Pair s;
        for (int i = 0; i < D; ++i) {
          const Pair& x = xs[i];
          Pair d = x - p[i];
          if constexpr (MinImage) {
            const Pair half = {half_[i], half_[i]}, extent = {extent_[i], extent_[i]};
            const Mask above = d > half, below = d < -half;
            d -= (Pair)((Mask)extent & above);
            d += (Pair)((Mask)extent & below);
          }
          s = i == 0 ? d * d : s + d * d;
        }
        closer |= s < radius2;
      }
      if (closer[0] | closer[1]) return false;
    }
    return true;
  }

  // For each sub-cell (half of the cell along each axis) the neighbour cells
  // that can hold a point closer than the radius to a point of that sub-cell,
  // nearest first. Splitting by sub-cell drops 9 of the 24 cells in 2D, 34 of 124 in 3D.
  // The gaps are shrunk by 1e-6 of a cell so that rounding in the sub-cell
  // choice can never drop a cell that matters. The candidates are
  // GridNeighbourhood's offsets within the radius (cell to cell, a superset:
  // a sub-cell's gap is at most 1e-6 of a cell below its cell's, which the
  // tolerance covers), within reach, ordered by the sub-cell's gap (ties in
  // the order of enumeration, axis 0 fastest), own cell first; their linear
  // offsets are the padded grid's.
  void build_offsets(const GridNeighbourhood<D>& layout, double radius) {
    using Step = std::array<int, D>;
    const std::array<double, D> inv_edge = inv_edge_;
    const int reach = reach_;
    const auto within = layout.stencil_within(radius, 1e-4);
    for (unsigned half = 0; half < (1u << D); ++half) {
      // Squared distance from the sub-cell to the neighbour cell.
      const auto gap2 = [&](const Step& o) {
        double g2 = 0.0;
        for (int i = 0; i < D; ++i) {
          const double edge = 1.0 / inv_edge[i];
          const bool upper = half >> i & 1;  // p in [0.5, 1) of its cell along axis i
          double g = 0.0;
          if (o[i] > 0) g = (o[i] - (upper ? 1.0 : 0.5)) * edge;
          if (o[i] < 0) g = (-o[i] - (upper ? 0.5 : 1.0)) * edge;
          g = std::max(0.0, g - 1e-6 * edge);
          g2 += g * g;
        }
        return g2;
      };
      const auto near = layout.filter(within, [&](const Step& o) {
        for (int i = 0; i < D; ++i)
          if (std::abs(o[i]) > reach) return false;
        return gap2(o) < radius * radius;
      });
      std::vector<std::pair<double, Step>> list;
      list.push_back({-1.0, Step{}});
      for (const Step& o : near.steps) list.push_back({gap2(o), o});
      std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) {
        if (a.first != b.first) return a.first < b.first;
        for (int i = D - 1; i >= 0; --i)
          if (a.second[i] != b.second[i]) return a.second[i] < b.second[i];
        return false;
      });
      std::vector<Step> steps;
      for (const auto& [g2, o] : list) steps.push_back(o);
      for (int i = 0; i < D; ++i) {
        steps_[half][i].clear();
        for (const Step& o : steps) steps_[half][i].push_back(static_cast<std::int8_t>(o[i]));
      }
      offsets_[half] = layout.stencil(std::move(steps)).linear;
      // Pad to whole blocks with the own cell, which is empty when scanned.
      while (offsets_[half].size() % kBlock) offsets_[half].push_back(0);
      for (int i = 0; i < D; ++i) steps_[half][i].resize(offsets_[half].size(), 0);
    }
  }

  // Measured (2D and 3D): blocks of 8 beat 4 (more mispredicted exits) and
  // 16 (more cells read); the list starts with the own cell, so an occupied
  // one rejects in the first block.
  static constexpr std::size_t kBlock = 8;
  // Rows of cells fetched ahead around a picked sample, each way: 5 covers
  // every cell a 2D candidate reads (2r + r = 4.2 cell edges); in 3D the same
  // cover is ~1000 cells, so only the nearest 5^3 are fetched (measured).
  static constexpr int kPrefetchReach = D == 2 ? 5 : 2;
  static constexpr int kMaxReach = 3;  // floor(sqrt(D)) + 1 for D <= 4

  // On a torus, the margin cells mirror the cells of the opposite faces: a
  // sample is written to every padded position congruent to its cell.
  void copy_to_margin(const Cell& value, std::size_t cell) {
    // At most 1 + 2 * reach positions an axis (a period of one cell).
    std::array<std::array<int, 2 * kMaxReach + 1>, D> positions{};
    std::array<int, D> count{};
    for (int i = 0; i < D; ++i) {
      const int c = static_cast<int>(cell / stride_[i] % static_cast<std::size_t>(padded_[i]));
      for (int k = c % cells_[i]; k < padded_[i]; k += cells_[i]) positions[i][count[i]++] = k;
    }
    std::array<int, D> at{};
    while (true) {
      std::size_t at_index = 0;
      for (int i = 0; i < D; ++i) at_index += static_cast<std::size_t>(positions[i][at[i]]) * stride_[i];
      grid_[at_index] = value;
      int axis = 0;
      while (axis < D && ++at[axis] == count[axis]) at[axis++] = 0;
      if (axis == D) break;
    }
  }

  static constexpr double kInnerFloat = 1.0 - 1e-3;
  double radius2_, inner_radius2_;
  double unit_ = 1.0, inv_unit_ = 1.0;  // lattice offsets count units of unit_
  float inner_radius2_f_ = 0.0f;         // in units of unit_ squared
  std::array<double, D> lo_{}, extent_{}, half_{}, inv_edge_{}, twice_inv_edge_{};
  std::array<int, D> cells_{}, padded_{};
  std::array<unsigned, D> interior_cells_{};
  std::array<std::size_t, D> stride_{};  // the padded grid's
  int reach_ = 1;
  const PointSet<D>& store_;
  detail::MappedArray<Cell> grid_;
  std::array<std::vector<std::ptrdiff_t>, (1u << D)> offsets_;
  // Lattice cells only, per axis: the steps of offsets_, the tile corner of
  // every padded position and the faces of every cell of the domain; and the
  // (is_free() hands insert() the point's offsets).
  std::array<std::array<std::vector<std::int8_t>, D>, (1u << D)> steps_;
  std::array<std::vector<double>, D> tile_corner_, cell_lo_, cell_hi_;
  std::vector<std::ptrdiff_t> prefetch_rows_;
};

// From 4 dimensions the specialised grid's block of (2 sqrt(D) + 1)^D cells
// around a candidate outgrows everything else: there the shared grid with
// cells of edge r and a pruned walk (Grid::for_conflicts) answers instead
// (docs/dimensions.md has the measurements).
//
// A picked sample's candidates fall around it, so the samples that rejected
// its last few candidates often reject the next one (a fifth of the
// candidates in 4D at 10^5): the last eight are tried first, from a copy of
// their coordinates, before the walk. Speed only: a candidate is refused only
// for a stored sample closer than r, in the grid's own arithmetic, so the
// answers are the grid's.
template <int D>
class ConflictGrid {
 public:
  ConflictGrid(const Domain<D>& domain, double radius, const PointSet<D>&)
      : grid_(Grid<D>::for_conflicts(domain, radius)), radius_(radius), radius2_(radius * radius) {}
  struct Placed {
    Point<D> point;
  };
  bool is_free(const Point<D>& p, std::size_t&, Placed& placed) {
    for (int i = 0; i < recent_count_; ++i)
      if (grid_.domain().distance2(p, recent_[i]) < radius2_) return false;
    const std::int32_t hit = grid_.find_closer_than(p, radius_);
    if (hit >= 0) {
      recent_[next_recent_] = grid_.points()[static_cast<std::size_t>(hit)];
      next_recent_ = (next_recent_ + 1) % kRecent;
      recent_count_ = std::min(recent_count_ + 1, kRecent);
      return false;
    }
    placed.point = p;
    return true;
  }
  void insert(const Placed& placed, std::size_t, std::size_t) { grid_.insert(placed.point); }
  void prefetch_around(const Point<D>&) const {}

 private:
  static constexpr int kRecent = 8;
  Grid<D> grid_;
  double radius_, radius2_;
  std::array<Point<D>, kRecent> recent_{};
  int recent_count_ = 0, next_recent_ = 0;
};

// How many of k points uniform in the ball of radius 2r lie outside the ball
// of radius r: k groups of D random bits, those not all zero.
template <int D>
int annulus_hits(int k, Rng& rng) {
  int hits = 0;
  std::uint64_t bits = 0;
  int left = 0;
  for (int j = 0; j < k; ++j) {
    if (left < D) {
      bits = rng.next();
      left = 64;
    }
    hits += (bits & ((std::uint64_t{1} << D) - 1)) != 0;
    bits >>= D;
    left -= D;
  }
  return hits;
}

// Grows the set at `radius` from `seed`. With count_only, where the grid does
// not read the samples back (every dimension but 3, whose grid holds indices
// into them), the samples are counted into *count_only and not kept (the
// result is empty): the same draws and decisions, without the output's
// memory.
template <int D, bool Periodic, bool Scipy>
PointSet<D> grow(const Domain<D>& domain, double radius, const BridsonParams& params, std::uint64_t seed,
                 const Progress& progress, std::size_t* count_only) {
  // Reported every kReportEvery samples (a branch taken that rarely costs
  // nothing measurable in the loop), against the usual count at the radius.
  constexpr std::size_t kReportEvery = 256;
  ProgressReporter reporter(progress, typical_count(sizing_volume(domain, radius), radius, D));
  const int k = params.k;
  const bool surface = params.surface;
  Rng rng(seed);
  bool short_reach = true;
  for (int i = 0; i < D; ++i) short_reach &= 2.0 * radius < domain.extent(i);
  // The samples, after points[0]: the grid's empty marker, removed at the
  // end. Room for the usual count at once (Bridson's sets hold about half
  // the densest packing's points; 3/4 of it is reserved, pages untouched
  // until written): growing by doubling copied the samples about twice over
  // and held the old and the new block together at the peak.
  // (After the grid, which refuses a radius too small for the domain.)
  PointSet<D> points;
  std::conditional_t<(D <= 3), BridsonGrid<D, Periodic>, ConflictGrid<D>> grid(domain, radius, points);
  typename decltype(grid)::Placed placed{};  // the candidate is_free() last accepted, as a sample
  const bool keep = count_only == nullptr || D == 3;
  if (keep) {
    points.reserve(static_cast<std::size_t>(0.75 * packing_count(sizing_volume(domain, radius), radius, D)) + 64);
    detail::advise_huge_pages(points);
  }
  points.push_back(Point<D>{});
  points[0].fill(std::numeric_limits<double>::quiet_NaN());
  std::size_t count = 0;  // samples placed
  // Files the candidate is_free() just accepted.
  const auto add = [&](std::size_t at) __attribute__((always_inline)) {
    if (keep) points.push_back(placed.point);
    grid.insert(placed, at, ++count);
    if (count % kReportEvery == 0) reporter.update(static_cast<double>(count));
  };
  const auto finish = [&] {
    reporter.finish();
    if (count_only) *count_only = count;
    if (!keep) return PointSet<D>{};
    points.erase(points.begin());
    return std::move(points);
  };
  // The active list holds coordinates, not indices: one memory access less
  // for each random pick.
  PointSet<D> active;
  detail::AnnulusOffsets<D, Scipy ? 32 : 53> offsets(radius, surface, seed);
  // Along an axis of a box shorter than r an annulus offset leaves the box
  // almost always (a 1 x 1 x 0.001 slab at r = 0.01 grew 4 points): there
  // candidates take a uniform coordinate instead, from a stream of their own
  // so that other domains keep their bytes. The other axes keep the offset,
  // and the grid still decides every candidate.
  std::array<bool, D> flat{};
  bool any_flat = false;
  if constexpr (!Periodic) {
    for (int i = 0; i < D; ++i) {
      flat[i] = domain.extent(i) < radius;
      any_flat = any_flat || flat[i];
    }
  }
  Rng flat_rng(seed, {0x666c6174 /* "flat" */});
  std::size_t cell = 0;
  // (The grid is empty: only a point that cannot go on the lattice, about
  // 2^-24 of the draws at most, is refused.)
  Point<D> first = uniform_point(rng, domain);
  for (int redraw = 0; !grid.is_free(first, cell, placed); ++redraw) {
    if (redraw == 64) throw Failure("bridson: no first sample could be placed on the grid's lattice");
    first = uniform_point(rng, domain);
  }
  add(cell);
  active.push_back(placed.point);
  // The next candidate around `centre` in c: wrapped into a torus; false
  // where it leaves a box.
  const auto next_candidate = [&](const Point<D>& centre, Point<D>& c) __attribute__((always_inline)) {
    c = centre;
    const Point<D>& v = offsets.next();
    for (int i = 0; i < D; ++i) c[i] += v[i];
    if constexpr (Periodic) {
      // One period at most when 2r is shorter than every period; else the
      // general wrap.
      if (short_reach) {
        for (int i = 0; i < D; ++i) {
          if (c[i] < domain.lo[i])
            c[i] += domain.extent(i);
          else if (c[i] >= domain.hi[i])
            c[i] -= domain.extent(i);
        }
        if (!domain.contains(c)) c = domain.wrap(c);  // rounding onto hi
      } else {
        c = domain.wrap(c);
      }
      return true;
    } else {
      if (any_flat)
        for (int i = 0; i < D; ++i)
          if (flat[i]) c[i] = flat_rng.uniform(domain.lo[i], domain.hi[i]);
      return domain.contains(c);
    }
  };
  if constexpr (Scipy) {
    // SciPy's loop: the picked sample leaves the pool, and its k candidates
    // are uniform in the ball of radius 2r, every free one kept. A candidate
    // within r of the centre is never free, so only the number of those in
    // the annulus matters: each of the k lands there with probability
    // 1 - 2^-D (the ball of radius r is 2^-D of the ball of 2r), which is
    // the chance that D random bits are not all zero. Those are drawn from
    // the annulus like Bridson's.
    while (!active.empty()) {
      const std::size_t slot = rng.below(active.size());
      const Point<D> centre = active[slot];
      active[slot] = active.back();
      active.pop_back();
      grid.prefetch_around(centre);
      const int tries = surface ? k : annulus_hits<D>(k, rng);
      for (int attempt = 0; attempt < tries; ++attempt) {
        Point<D> c;
        if (next_candidate(centre, c) && grid.is_free(c, cell, placed)) {
          add(cell);
          active.push_back(placed.point);
        }
      }
    }
    return finish();
  }
  while (!active.empty()) {
    const std::size_t slot = rng.below(active.size());
    const Point<D> centre = active[slot];
    grid.prefetch_around(centre);
    // Look ahead (speed only: the picks stay the same). The stream draws
    // nothing else in this loop, so the next pick is below(n') of its next
    // number, n' the list's size after this pick, one more or one less:
    // within one entry of what a copy of the stream draws for the size now.
    // Those entries are fetched while this pick's candidates are tried; a
    // random entry of a large list is otherwise a cache miss a pick (7% of
    // a 3D run at 10^6, perf).
    {
      Rng ahead = rng;
      const std::size_t next = ahead.below(active.size());
      __builtin_prefetch(active.data() + (next == 0 ? 0 : next - 1));
      __builtin_prefetch(active.data() + next + 1);
    }
    bool found = false;
    for (int attempt = 0; attempt < k; ++attempt) {
      Point<D> c;
      if (!next_candidate(centre, c)) continue;
      if (grid.is_free(c, cell, placed)) {
        add(cell);
        active.push_back(placed.point);
        found = true;
        break;
      }
    }
    if (!found) {
      active[slot] = active.back();
      active.pop_back();
    }
  }
  return finish();
}

template <int D>
PointSet<D> grow(const Domain<D>& domain, double radius, const BridsonParams& params, std::uint64_t seed,
                 const Progress& progress, std::size_t* count_only = nullptr) {
  if (params.scipy)
    return domain.periodic ? grow<D, true, true>(domain, radius, params, seed, progress, count_only)
                           : grow<D, false, true>(domain, radius, params, seed, progress, count_only);
  return domain.periodic ? grow<D, true, false>(domain, radius, params, seed, progress, count_only)
                         : grow<D, false, false>(domain, radius, params, seed, progress, count_only);
}

// Count mode. A finished set at the radius holds more than the count; taking
// a subset of it thins the pattern (a uniformly random subset adds white
// noise: low-frequency power 0.30 against 0.11 at the method's own radius, 2D box,
// 1024 points). So the radius is searched upward (the count falls as r^-D)
// until a finished set holds at most kCountSurplus more than the count, by
// the count's scaling and bisection between a radius that holds the count and
// one that does not, at most kCountSearchSteps sets; weighted sample
// elimination (samplers/elimination.h) then removes the few extra from the
// most crowded places. Every radius tried is at least params.radius, so the
// minimum distance still holds; each set is grown from the same seed, so a
// set is the same whenever it is grown again. The first set (a quarter more
// than the count, at the registry's radius) is only counted where the grid
// allows (grow's count_only): held, it was the peak of the whole run. It is
// grown again only if the search keeps it (rare: it already fits, or every
// step failed).
constexpr double kCountSurplus = 0.02;
constexpr int kCountSearchSteps = 8;
// Progress with a count: the first set, each radius of the search (the
// steps not taken are skipped), the first set again where needed, the
// elimination.
constexpr std::size_t kCountParts = kCountSearchSteps + 3;

// `points` is the set at params.radius, or empty when only its size
// `first_size` was kept.
template <int D>
PointSet<D> trim_to_count(PointSet<D> points, std::size_t first_size, std::uint64_t count, const Domain<D>& domain,
                          const BridsonParams& params, std::uint64_t seed) {
  const auto n = static_cast<double>(count);
  const double most = n * (1.0 + kCountSurplus);
  double holds = params.radius, fails = std::numeric_limits<double>::infinity();
  std::size_t held = first_size;  // the size of the set at `holds`
  for (int step = 0; step != kCountSearchSteps && static_cast<double>(held) > most; ++step) {
    // Aim at half the allowed surplus, inside the bracket.
    double next = holds * std::pow(static_cast<double>(held) / (n * (1.0 + kCountSurplus / 2)), 1.0 / D);
    if (!(next < fails)) next = std::sqrt(holds * fails);
    PointSet<D> grown = grow(domain, next, params, seed, part_of(params.progress, static_cast<std::size_t>(1 + step), kCountParts));
    if (grown.size() >= count) {
      holds = next;
      held = grown.size();
      points = std::move(grown);
    } else {
      fails = next;
    }
  }
  if (points.size() != held)  // the first set, only counted
    points = grow(domain, holds, params, seed, part_of(params.progress, kCountParts - 2, kCountParts));
  return eliminate(std::move(points), count, domain, {}, /*progressive=*/false,
                   part_of(params.progress, kCountParts - 1, kCountParts));
}

template <int D>
void validate(const BridsonParams& params, const Domain<D>& domain) {
  domain.validate();
  require_radius(params.radius);
  // A torus far thinner than the radius would need that many periodic images
  // of every cell (the limit of the shared grid neighbourhood).
  for (int a = 0; a < D && domain.periodic; ++a)
    if (params.radius > GridNeighbourhood<D>::kMaxStencilReach * domain.extent(a))
      throw InvalidArgument("bridson: on a torus every period must be at least radius / " +
                            std::to_string(GridNeighbourhood<D>::kMaxStencilReach) + "; axis " + std::to_string(a) +
                            " has " + detail::format_number(domain.extent(a)) + " for radius " +
                            detail::format_number(params.radius));
  if (params.k < 1) throw InvalidArgument("bridson: k must be at least 1, got " + std::to_string(params.k));
  if (params.count) {
    if (*params.count == 0) throw InvalidArgument("bridson: count must be at least 1, got 0");
    require_count_fits("bridson", *params.count, params.radius, domain);
  }
}

}  // namespace

template <int D>
PointSet<D> bridson(const BridsonParams& params, const Domain<D>& domain, std::uint64_t seed) {
  validate(params, domain);
  if (!params.count) return grow(domain, params.radius, params, seed, params.progress);
  std::size_t first_size = 0;
  PointSet<D> points = grow(domain, params.radius, params, seed, part_of(params.progress, 0, kCountParts), &first_size);
  if (first_size < *params.count)
    throw InvalidArgument("bridson: only " + std::to_string(first_size) + " points fit at radius " +
                          detail::format_number(params.radius) + " (k " + std::to_string(params.k) +
                          "), fewer than the " + std::to_string(*params.count) +
                          " requested; ask for fewer points or a smaller radius");
  return trim_to_count(std::move(points), first_size, *params.count, domain, params, seed);
}

#define PDS_INSTANTIATE(D) template PointSet<D> bridson<D>(const BridsonParams&, const Domain<D>&, std::uint64_t);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
