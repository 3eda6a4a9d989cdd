// D. Dunbar and G. Humphreys, "A spatial data structure for fast Poisson-disk
// sample generation", ACM SIGGRAPH 2006 (ACM TOG 25(3), 503-508).
//
// Two variants (`variant`), one data structure idea: the part of a front
// sample's neighbourhood where a new sample may still go.
//
// Variant 1, the paper's scalloped sectors. The available region of a front
// sample p is the annulus r..2r around it minus the disks of radius r around
// the samples within 3r (and minus the outside of a box). In polar
// coordinates around p it is a list of scalloped sectors: an angular range
// [t0, t1] and an inner and an outer boundary curve, each an arc of a circle
// (the annulus' circles or a neighbour's disk, near or far crossing of the
// ray) or a wall. The area of a sector is exact: the primitive of rho(t)^2/2
// for a circle at distance d with radius a is closed-form (asin and sin), and
// h^2 tan(t)/2 for a wall. Removing a disk splits each sector at the angles
// where the disk's circle crosses the sector's curves and at the disk's
// tangent directions, and keeps, between those angles, the part below and the
// part above the disk. A new sample: a sector in proportion to its area, the
// angle by inverting the sector's swept area (Newton steps in a bisection
// bracket), the radius with density proportional to rho between the two
// curves. The front sample picked next is a uniformly random one; it is filled
// until its region is empty (as in the paper), and every new sample removes
// its disk and joins the front. (The areas and the uniformity were checked
// against Monte Carlo estimates while developing; notes of issue 6.) The set
// is maximal up to dropped slivers narrower than 1e-12 rad (1e-11 r). Filling one annulus at a time is not the
// order of dart throwing, and the output is measurably denser than saturated
// dart throwing (docs/dunbar-humphreys.md; tested).
//
// Variant 2, the same sectors in dart throwing's order: each new sample is
// uniform over the union of all samples' free annuli (a front sample picked in
// proportion to its area via a sum tree of stored upper bounds, accepted with
// probability true / stored area; the point accepted with probability
// 1 / the number of samples within 2r of it). Maximal as variant 1, and equal
// to maximal dart throwing within statistical error (tested). O(N log N).
//
// Variant 0, the paper's boundary sampling. A sample's "available boundary" is
// the part of the circle of radius r around it that lies outside the disks of
// radius r of all other samples (and inside the domain). The paper keeps the
// available neighbourhood of a sample as scalloped sectors; restricted to the
// circle, that region is a set of angular intervals, which is what we store.
// Front samples are taken in insertion order (breadth first, which keeps
// memory access local; the guarantees do not depend on the order). A front
// sample's available arcs are computed from the samples within 2r (a sample at
// distance d blocks the directions within acos(d / 2r) of its own); then
// points are drawn uniformly in angle on the remaining arcs, each new sample
// blocking +-60 degrees around itself, until no arc remains. The new samples
// join the front; the sample leaves it. Directions are handled without
// trigonometry (detail/diamond_arcs.h): an arc's ends are the neighbour's
// direction rotated by -+acos(d / 2r), which needs one square root, and they
// are ordered by their "diamond angle", which needs one division for both
// ends; a uniform true angle is drawn by rejection (tested there). The free
// arcs come from the blocked ones without sorting
// (FreeArcs::assign_complement_unsorted), and on processors with AVX-512 the
// blocked arcs and their complement are computed eight at a time, with the
// same bits as the scalar code (see ScalarNeighbours below).
//
// Guarantees. Every new sample is at distance >= r from every other (checked
// on the stored coordinates before it is accepted). Maximal: if some region
// were uncovered, its boundary would contain an arc of some sample's circle
// that no disk covers, and that sample would still be on the front. The
// circle radius is r(1 + 1e-10) so that rounding does not put a new sample
// closer than r to the others while the coordinates' spacing (ulp) is far
// below 1e-10 r; hence every point is within r(1 + 1e-10) of a sample.
// Coarser coordinates (a tiny radius far from the origin) make the exact
// check reject candidates, and the run stops with a Failure saying so.
//
// Complexity. Each sample is processed once with a constant number of
// neighbours (7.6 within 2r on average): O(N) time. Memory: the output and
// one int32 per grid cell (about 2.6 per sample); the front is the
// unprocessed tail of the output.
//
// Complexity of variant 1: each sample is processed once against the about
// 20 samples within 3r, each cut touching a bounded number of sectors: O(N),
// with a large constant (transcendental functions per sector and cut).
//
// Limits. 2D only (the paper is 2D). Boundary sampling is not the unbiased
// process: samples sit exactly at distance r from their parent, so the set is
// denser and more regular than dart throwing (measured in
// docs/dunbar-humphreys.md). Variant 1 needs a torus period above 6r.
#include "pds/samplers/dunbar_humphreys.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "pds/detail/diamond_arcs.h"
#include "pds/detail/format.h"
#include "pds/detail/sum_tree.h"
#include "pds/error.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"

// The AVX-512 neighbourhood kernel of boundary sampling: x86-64 with GCC 12
// or later (its target attribute and processor check), chosen at run time when the processor has the x86-64-v4 level.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#define PDS_HAVE_AVX512_KERNEL 1
#include <immintrin.h>
#else
#define PDS_HAVE_AVX512_KERNEL 0
#endif

namespace pds {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Cells of a grid window, each side of the centre cell, per axis.
using Reach = std::array<int, 2>;

/// One sample index per cell (or -1). Cells have edge <= r / sqrt(2), so a
/// set with minimum distance r has at most one sample per cell; a flat int32
/// array is smaller and faster here than the general pds::Grid's lists.
class CellGrid {
 public:
  CellGrid(const Domain<2>& domain, double cell_edge) : domain_(domain) {
    for (int i = 0; i < 2; ++i) {
      const double n = std::max(1.0, std::ceil(domain.extent(i) / cell_edge));
      if (n > 1e9) throw InvalidArgument("dunbar-humphreys: radius too small for the domain");
      n_[i] = static_cast<int>(n);
      inv_edge_[i] = n / domain.extent(i);
    }
    if (static_cast<double>(n_[0]) * n_[1] > static_cast<double>(std::size_t{1} << 31))
      throw InvalidArgument("dunbar-humphreys: radius too small for the domain (grid above 2^31 cells)");
    cells_.assign(static_cast<std::size_t>(n_[0]) * n_[1], -1);
  }
  int n(int axis) const { return n_[axis]; }
  /// How many cells around a sample's cell can hold a sample within
  /// `distance`, per axis (a box one cell thin across has far smaller cells
  /// along its other axis).
  Reach reach(double distance) const {
    return {static_cast<int>(std::ceil(distance * inv_edge_[0])), static_cast<int>(std::ceil(distance * inv_edge_[1]))};
  }
  int coord(double x, int axis) const {
    const int c = static_cast<int>((x - domain_.lo[axis]) * inv_edge_[axis]);
    return std::clamp(c, 0, n_[axis] - 1);
  }
  std::int32_t& at(int cx, int cy) { return cells_[static_cast<std::size_t>(cy) * n_[0] + cx]; }
  std::int32_t& at(const Point<2>& p) { return at(coord(p[0], 0), coord(p[1], 1)); }

  /// Calls f(index) for every stored sample in the cells within `reach`
  /// cells of p's cell (each cell once, wrapping on a torus).
  template <class F>
  void for_each_near(const Point<2>& p, Reach reach, F&& f) const {
    int first[2], last[2];
    window(p, reach, first, last);
    for (int y = first[1]; y <= last[1]; ++y) {
      const std::int32_t* row = this->row(y);
      for (int x = first[0]; x <= last[0]; ++x) {
        const std::int32_t j = row[wrapped(x, 0)];
        if (j >= 0) f(j);
      }
    }
  }

  /// The window of cells within `reach` of p's cell as [first, last] per
  /// axis; true when it needs no nearest image (in a box always; on a torus
  /// when it neither crosses a seam nor covers a whole axis).
  bool plain_window(const Point<2>& p, Reach reach, int first[2], int last[2]) const {
    window(p, reach, first, last);
    return !(first[0] < 0 || first[1] < 0 || last[0] >= n_[0] || last[1] >= n_[1] ||
             (domain_.periodic && (last[0] - first[0] + 1 == n_[0] || last[1] - first[1] + 1 == n_[1])));
  }
  std::size_t bytes() const { return cells_.size() * sizeof(std::int32_t); }
  /// Asks for the rows of p's window to be brought into the cache.
  void prefetch_window(const Point<2>& p, Reach reach) const {
    int first[2], last[2];
    window(p, reach, first, last);
    for (int y = first[1]; y <= last[1]; ++y) __builtin_prefetch(row(y) + std::max(first[0], 0));
  }
  /// Row y of the grid (y in [-n, 2n), wrapped).
  const std::int32_t* row_pointer(int y) const { return row(y); }

  // collect_near's window width: 2 radius is 2.83 cells of radius / sqrt 2,
  // up to 3.33 where rounding the cell count up shrinks the cells (a torus
  // period of 4 radius), so the reach is at most 4; a box that narrow has
  // fewer cells than that across.
  static constexpr int kMaxWindow = 9;

  /// The same samples written to `out` (room for (2 reach + 1)^2), their
  /// number returned: no branch per cell, for the hot loop of variant 0.
  /// `seam` tells whether the window crossed a torus seam.
  int collect_near(const Point<2>& p, Reach reach, std::int32_t* out, bool& seam) const {
    int first[2], last[2];
    seam = !plain_window(p, reach, first, last);
    const int width = last[0] - first[0] + 1;
    if (width > kMaxWindow) throw std::logic_error("dunbar-humphreys: neighbour window wider than planned");
    int n = 0;
    if (width == 7 && first[0] >= 0 && last[0] < n_[0]) {  // the usual case: no column wraps, 7 wide
      for (int y = first[1]; y <= last[1]; ++y) {
        const std::int32_t* row = this->row(y) + first[0];
        for (int x = 0; x < 7; ++x) {
          const std::int32_t j = row[x];
          out[n] = j;
          n += j >= 0;
        }
      }
      return n;
    }
    int columns[kMaxWindow];
    for (int x = 0; x < width; ++x) columns[x] = wrapped(first[0] + x, 0);
    for (int y = first[1]; y <= last[1]; ++y) {
      const std::int32_t* row = this->row(y);
      for (int x = 0; x < width; ++x) {
        const std::int32_t j = row[columns[x]];
        out[n] = j;
        n += j >= 0;
      }
    }
    return n;
  }

 private:
  /// The cell range [first, last] per axis within `reach` of p's cell:
  /// clipped in a box, possibly past the ends (to be wrapped) on a torus.
  void window(const Point<2>& p, Reach reach, int first[2], int last[2]) const {
    for (int i = 0; i < 2; ++i) {
      const int c = coord(p[i], i);
      first[i] = c - reach[i];
      last[i] = c + reach[i];
      if (domain_.periodic) {
        if (last[i] - first[i] + 1 >= n_[i]) {
          first[i] = 0;
          last[i] = n_[i] - 1;
        }
      } else {
        first[i] = std::max(first[i], 0);
        last[i] = std::min(last[i], n_[i] - 1);
      }
    }
  }
  int wrapped(int c, int axis) const { return c < 0 ? c + n_[axis] : (c >= n_[axis] ? c - n_[axis] : c); }
  const std::int32_t* row(int y) const { return cells_.data() + static_cast<std::size_t>(wrapped(y, 1)) * n_[0]; }

  Domain<2> domain_;
  int n_[2];
  double inv_edge_[2];
  std::vector<std::int32_t> cells_;
};

/// Appends q to the samples and records it in its grid cell; returns its index.
std::int32_t append_sample(PointSet<2>& points, CellGrid& grid, const Point<2>& q) {
  if (points.size() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw InvalidArgument("dunbar-humphreys: more than 2^31 - 1 samples");
  const auto index = static_cast<std::int32_t>(points.size());
  points.push_back(q);
  grid.at(q) = index;
  return index;
}

// ---------------------------------------------------------------------------
// Variant 0: boundary sampling.
// ---------------------------------------------------------------------------

/// The samples within 2 rc of a front sample p (p excluded), in the window's
/// row-major cell order: their stored coordinates (sx, sy), and where the
/// window crossed a torus seam also their nearest-image offsets (dx, dy) from
/// p (elsewhere the offsets are sx - p[0], sy - p[1], recomputed where
/// needed: the same subtraction, so the same bits, and two stores per cell
/// fewer in the gather). Then the arcs of p's circle that they (and the walls)
/// block. Arrays have slack past the most neighbours a circle can have (24),
/// for whole-vector stores.
struct Neighbourhood {
  static constexpr int kCap = detail::FreeArcs::kMaxBlocked + 16;
  alignas(64) double sx[kCap];
  alignas(64) double sy[kCap];
  alignas(64) double dx[kCap];  // seam windows only
  alignas(64) double dy[kCap];
  int count = 0;
  alignas(64) double lo[kCap];  // blocked arcs: start and length (diamond angles)
  alignas(64) double len[kCap];
  int blocked = 0;
};

/// What one front sample needs: its neighbourhood (gather), the arcs its
/// neighbours block (block) and the free arcs left (complement). Two kernels
/// compute exactly the same numbers (the same IEEE operations in the same
/// order; no fused multiply-adds: this file is built with -ffp-contract=off):
/// ScalarNeighbours, and on x86-64 with AVX-512 Avx512Neighbours, which
/// blocks and complements eight neighbours or arcs at a time (its gather and
/// exact checks are the scalar ones). Same seed, same bytes either way
/// (tested).
struct ScalarNeighbours {
  /// Fills nb.sx/sy/count (and dx/dy across a seam); `seam` is whether
  /// nearest images were needed. p itself is the one sample at distance 0
  /// (the others are at least r away, and a difference of distinct doubles
  /// is not 0), so d2 > 0 leaves it out.
  static void gather(const CellGrid& grid, const PointSet<2>& points, const Domain<2>& domain, const Point<2>& p,
                     Reach reach, double reach2, Neighbourhood& nb, bool& seam) {
    std::int32_t cells[CellGrid::kMaxWindow * CellGrid::kMaxWindow];
    const int ncells = grid.collect_near(p, reach, cells, seam);
    int n = 0;
    // Kept without a branch, so that the divisions that follow overlap.
    if (!seam) {
      for (int c = 0; c < ncells; ++c) {
        const Point<2>& s = points[static_cast<std::size_t>(cells[c])];
        const double dx = s[0] - p[0], dy = s[1] - p[1];
        const double d2 = dx * dx + dy * dy;
        nb.sx[n] = s[0];
        nb.sy[n] = s[1];
        n += (d2 < reach2) & (d2 > 0.0);
      }
    } else {
      for (int c = 0; c < ncells; ++c) {
        const Point<2>& s = points[static_cast<std::size_t>(cells[c])];
        const double dx = domain.delta(p[0], s[0], 0), dy = domain.delta(p[1], s[1], 1);
        const double d2 = dx * dx + dy * dy;
        nb.sx[n] = s[0];
        nb.sy[n] = s[1];
        nb.dx[n] = dx;
        nb.dy[n] = dy;
        n += (d2 < reach2) & (d2 > 0.0);
      }
    }
    nb.count = n;
  }

  /// Appends the arc each neighbour blocks: the directions within
  /// acos(d / 2rc) of its own. Rotating (dx, dy) by -+ that angle gives
  /// (dx +- dy k, dy -+ dx k) up to scale, with k = sqrt((2rc)^2 - d^2) / d;
  /// scaled by d^2 that is (dx d^2 +- dy t, dy d^2 -+ dx t) with
  /// t = sqrt(((2rc)^2 - d^2) d^2): one square root and no division, and then
  /// one division for both ends (diamond_arc_one_division). Offsets are
  /// first divided by 2rc (times its reciprocal), so that the products stay
  /// near 1 for any radius.
  static void block(double inv_reach, const Point<2>& p, bool seam, Neighbourhood& nb) {
    for (int i = 0; i < nb.count; ++i) {
      const double dx = seam ? nb.dx[i] : nb.sx[i] - p[0], dy = seam ? nb.dy[i] : nb.sy[i] - p[1];
      const double ex = dx * inv_reach, ey = dy * inv_reach;
      const double e2 = ex * ex + ey * ey;
      const double t = std::sqrt(std::max(1.0 - e2, 0.0) * e2);
      const double ax = ex * e2, ay = ey * e2, bx = ey * t, by = ex * t;
      const detail::DiamondArc a = detail::diamond_arc_one_division(ax + bx, ay - by, ax - bx, ay + by);
      nb.lo[nb.blocked] = a.lo;
      nb.len[nb.blocked] = a.len;
      ++nb.blocked;
    }
  }

  /// Whether q is at least r from every neighbour (exactly, on the stored
  /// coordinates; nearest images only when the window crossed a seam).
  static bool clear_of_neighbours(const Neighbourhood& nb, const Point<2>& q, double r2, bool seam,
                                  const Domain<2>& domain) {
    bool clear = true;
    for (int i = 0; clear && i < nb.count; ++i) {
      if (seam) {
        clear = domain.distance2(q, Point<2>{{nb.sx[i], nb.sy[i]}}) >= r2;
      } else {
        const double dx = q[0] - nb.sx[i], dy = q[1] - nb.sy[i];
        clear = dx * dx + dy * dy >= r2;
      }
    }
    return clear;
  }

  /// The free arcs of p's circle: the complement of the blocked ones.
  static void complement(const Neighbourhood& nb, detail::FreeArcs& arcs) {
    arcs.assign_complement_unsorted(nb.lo, nb.len, nb.blocked);
  }
};

#if PDS_HAVE_AVX512_KERNEL
#define PDS_AVX512 __attribute__((target("arch=x86-64-v4")))

struct Avx512Neighbours {
  // Up to 16 neighbours or arcs (the usual case) sit in two vectors. block and
  // the exact check run one masked step for up to 8 (82% of front samples,
  // so the branch is mostly predicted) and two up to 16; the complement
  // always handles both vectors.
  static constexpr int kUsual = 16;

  /// The lanes [0, n) of an 8-lane step, for any n (clamped to 0..8).
  PDS_AVX512 static __mmask8 first_lanes(int n) { return static_cast<__mmask8>((1u << std::clamp(n, 0, 8)) - 1); }
  /// The largest lane (exact; written out rather than _mm512_reduce_max_pd,
  /// which trips a GCC 12 warning in its own header).
  PDS_AVX512 static double max_lane(__m512d v) {
    alignas(64) double lanes[8];
    _mm512_store_pd(lanes, v);
    return std::max(std::max(std::max(lanes[0], lanes[1]), std::max(lanes[2], lanes[3])),
                    std::max(std::max(lanes[4], lanes[5]), std::max(lanes[6], lanes[7])));
  }
  /// Steps of 8 covering n: 1 up to 8, 2 up to 16, then as many as needed.
  static int steps(int n) { return n <= 8 ? 1 : (n <= kUsual ? kUsual / 8 : (n + 7) / 8); }

  /// 2 - copysign(1 + u, y): a diamond angle from its quotient u, as in
  /// diamond_arc_one_division, the copysign as bit operations on the sign bit.
  PDS_AVX512 static __m512d diamond_angle(__m512d u, __m512d y) {
    const __m512i sign = _mm512_set1_epi64(static_cast<long long>(0x8000000000000000ull));
    const __m512d v = _mm512_abs_pd(_mm512_add_pd(_mm512_set1_pd(1.0), u));
    const __m512i signed_v = _mm512_or_si512(_mm512_castpd_si512(v), _mm512_and_si512(sign, _mm512_castpd_si512(y)));
    return _mm512_sub_pd(_mm512_set1_pd(2.0), _mm512_castsi512_pd(signed_v));
  }

  /// As ScalarNeighbours::block, eight neighbours per step.
  PDS_AVX512 static void block(double inv_reach, const Point<2>& p, bool seam, Neighbourhood& nb) {
    const __m512d scale = _mm512_set1_pd(inv_reach), four = _mm512_set1_pd(4.0), one = _mm512_set1_pd(1.0);
    const __m512d zero = _mm512_setzero_pd(), three = _mm512_set1_pd(3.0);
    const __m512d px = _mm512_set1_pd(p[0]), py = _mm512_set1_pd(p[1]);
    for (int step = 0, n = steps(nb.count); step < n; ++step) {
      const int i = 8 * step;
      const __mmask8 live = first_lanes(nb.count - i);
      __m512d dx, dy;
      if (seam) {
        dx = _mm512_maskz_loadu_pd(live, nb.dx + i), dy = _mm512_maskz_loadu_pd(live, nb.dy + i);
      } else {  // the gather's subtraction again
        dx = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, nb.sx + i), px);
        dy = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, nb.sy + i), py);
      }
      // Dead lanes compute on (1, 0): no division by 0.
      const __m512d ex = _mm512_mask_mul_pd(one, live, dx, scale), ey = _mm512_maskz_mul_pd(live, dy, scale);
      const __m512d e2 = _mm512_add_pd(_mm512_mul_pd(ex, ex), _mm512_mul_pd(ey, ey));
      const __m512d rest = _mm512_sub_pd(one, e2);
      const __m512d room = _mm512_mul_pd(_mm512_mask_max_pd(rest, 0xFF, rest, zero), e2);  // (masked: see t)
      const __m512d t = _mm512_mask_sqrt_pd(room, 0xFF, room);  // (the unmasked form warns in GCC 12)
      const __m512d ax = _mm512_mul_pd(ex, e2), ay = _mm512_mul_pd(ey, e2);
      const __m512d bx = _mm512_mul_pd(ey, t), by = _mm512_mul_pd(ex, t);
      const __m512d x1 = _mm512_add_pd(ax, bx), y1 = _mm512_sub_pd(ay, by);
      const __m512d x2 = _mm512_sub_pd(ax, bx), y2 = _mm512_add_pd(ay, by);
      const __m512d s1 = _mm512_add_pd(_mm512_abs_pd(x1), _mm512_abs_pd(y1));
      const __m512d s2 = _mm512_add_pd(_mm512_abs_pd(x2), _mm512_abs_pd(y2));
      const __m512d inv = _mm512_div_pd(one, _mm512_mul_pd(s1, s2));
      const __m512d q1 = _mm512_mul_pd(_mm512_mul_pd(x1, s2), inv), q2 = _mm512_mul_pd(_mm512_mul_pd(x2, s1), inv);
      const __m512d u1 = _mm512_mask_min_pd(q1, 0xFF, q1, one), u2 = _mm512_mask_min_pd(q2, 0xFF, q2, one);
      __m512d lo = diamond_angle(u1, y1);
      __m512d len = _mm512_sub_pd(diamond_angle(u2, y2), lo);
      // lo -= 4 (lo >= 4), len += 4 (len < 0): the same exact subtraction and addition of 0 or 4.
      lo = _mm512_sub_pd(lo, _mm512_maskz_mov_pd(_mm512_cmp_pd_mask(lo, four, _CMP_GE_OQ), four));
      len = _mm512_add_pd(len, _mm512_maskz_mov_pd(_mm512_cmp_pd_mask(len, zero, _CMP_LT_OQ), four));
      len = _mm512_maskz_mov_pd(_mm512_cmp_pd_mask(len, three, _CMP_LE_OQ), len);  // len * (len <= 3)
      _mm512_storeu_pd(nb.lo + nb.blocked + i, lo);
      _mm512_storeu_pd(nb.len + nb.blocked + i, len);
    }
    nb.blocked += nb.count;
  }

  /// As ScalarNeighbours::clear_of_neighbours, eight neighbours per step
  /// (the same subtractions, products and comparison per neighbour; no
  /// early exit, whose trip count would be a mispredicted branch).
  PDS_AVX512 static bool clear_of_neighbours(const Neighbourhood& nb, const Point<2>& q, double r2, bool seam,
                                             const Domain<2>& domain) {
    if (seam) return ScalarNeighbours::clear_of_neighbours(nb, q, r2, seam, domain);
    const __m512d qx = _mm512_set1_pd(q[0]), qy = _mm512_set1_pd(q[1]), limit = _mm512_set1_pd(r2);
    __mmask8 close = 0;
    for (int step = 0, n = steps(nb.count); step < n; ++step) {
      const int i = 8 * step;
      const __mmask8 live = first_lanes(nb.count - i);
      const __m512d dx = _mm512_sub_pd(qx, _mm512_maskz_loadu_pd(live, nb.sx + i));
      const __m512d dy = _mm512_sub_pd(qy, _mm512_maskz_loadu_pd(live, nb.sy + i));
      const __m512d d2 = _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy));
      close |= _mm512_mask_cmp_pd_mask(live, d2, limit, _CMP_NGE_UQ);  // not (d2 >= r2), as the scalar test
    }
    return close == 0;
  }

  /// As ScalarNeighbours::complement (FreeArcs::assign_complement_unsorted),
  /// on up to 16 arcs held in two vectors: for each arc i, every arc k that
  /// starts after it takes max(covered_k, end_i); the gaps that stay open are
  /// compressed out in list order, then the one that ends at 4.
  PDS_AVX512 static void complement(const Neighbourhood& nb, detail::FreeArcs& arcs) {
    const int n = nb.blocked;
    if (n > kUsual) return ScalarNeighbours::complement(nb, arcs);
    const __mmask8 live[2] = {first_lanes(n), first_lanes(n - 8)};
    __m512d lo[2], end[2], covered[2];
    __m512d first = _mm512_setzero_pd(), last = _mm512_setzero_pd();
    for (int h = 0; h < 2; ++h) {
      lo[h] = _mm512_maskz_loadu_pd(live[h], nb.lo + 8 * h);
      end[h] = _mm512_add_pd(lo[h], _mm512_maskz_loadu_pd(live[h], nb.len + 8 * h));
      first = _mm512_mask_max_pd(first, live[h], first, _mm512_sub_pd(end[h], _mm512_set1_pd(4.0)));
      last = _mm512_mask_max_pd(last, live[h], last, end[h]);
    }
    // covered_k = max(from, the ends of the arcs listed before k): maxima are
    // exact in any order, so two chains over alternate arcs (shorter latency)
    // and `from` last give the scalar kernel's numbers.
    __m512d even[2] = {_mm512_setzero_pd(), _mm512_setzero_pd()}, odd[2] = {even[0], even[1]};
    const auto take = [&](int i, __m512d* acc) PDS_AVX512 {
      const __m512d lo_i = _mm512_set1_pd(nb.lo[i]), end_i = _mm512_set1_pd(nb.lo[i] + nb.len[i]);
      const unsigned listed_after = ~((2u << i) - 1);  // the arcs k > i, one bit each
      for (int h = 0; h < 2; ++h) {
        const auto later = static_cast<__mmask8>(listed_after >> (8 * h));
        const __mmask8 after = _mm512_mask_cmp_pd_mask(live[h], lo[h], lo_i, _CMP_GT_OQ) |
                               _mm512_mask_cmp_pd_mask(live[h] & later, lo[h], lo_i, _CMP_EQ_OQ);
        acc[h] = _mm512_mask_max_pd(acc[h], after, acc[h], end_i);
      }
    };
    int i = 0;
    for (; i + 1 < n; i += 2) take(i, even), take(i + 1, odd);
    if (i < n) take(i, even);
    const double from = max_lane(first);  // over the arcs and 0
    for (int h = 0; h < 2; ++h) {
      const __m512d both = _mm512_mask_max_pd(even[h], 0xFF, even[h], odd[h]);  // (masked: see block)
      covered[h] = _mm512_mask_max_pd(both, 0xFF, both, _mm512_set1_pd(from));
    }
    const double to = std::max(from, max_lane(last));
    detail::DiamondArc* out = arcs.begin_fill(3 * kUsual);
    auto* slots = reinterpret_cast<double*>(out);
    std::size_t kept = 0;
    const __m512i pairs_low = _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0);
    const __m512i pairs_high = _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4);
    const __m512d min_arc = _mm512_set1_pd(detail::FreeArcs::min_arc());
    for (int h = 0; h < 2; ++h) {
      const __m512d gap = _mm512_sub_pd(lo[h], covered[h]);
      const __mmask8 open = _mm512_mask_cmp_pd_mask(live[h], gap, min_arc, _CMP_GT_OQ);
      const __m512d starts = _mm512_maskz_compress_pd(open, covered[h]), lengths = _mm512_maskz_compress_pd(open, gap);
      _mm512_storeu_pd(slots + 2 * kept, _mm512_permutex2var_pd(starts, pairs_low, lengths));
      _mm512_storeu_pd(slots + 2 * kept + 8, _mm512_permutex2var_pd(starts, pairs_high, lengths));
      kept += static_cast<std::size_t>(__builtin_popcount(open));
    }
    out[kept] = {to, 4.0 - to};
    kept += 4.0 - to > detail::FreeArcs::min_arc();
    arcs.finish_fill(kept);
  }
};
#endif

/// Boundary sampling with a given neighbourhood kernel (inlined into each
/// entry point below, so that the AVX-512 one is compiled for that target).
template <class Kernel>
[[gnu::always_inline]] inline PointSet<2> boundary_sampling_with(const DunbarHumphreysParams& params,
                                                                 const Domain<2>& domain, std::uint64_t seed) {
  const double r = params.radius, r2 = r * r;
  // The circle radius: a hair above r, so that samples placed on it stay at
  // least r apart after rounding (see the file comment).
  const double rc = r * (1.0 + 1e-10);
  if (domain.periodic)
    for (int i = 0; i < 2; ++i)
      if (domain.extent(i) < 4.0 * rc)  // neighbours within 2 rc need one nearest image
        throw InvalidArgument(
            "dunbar-humphreys: on a torus every period must be more than 4 radius (the circles are 1e-10 larger than "
            "the radius); axis " +
            std::to_string(i) + " has " + detail::format_number(domain.extent(i)) + " for radius " +
            detail::format_number(r));

  CellGrid grid(domain, r / std::sqrt(2.0));
  const Reach reach = grid.reach(2.0 * rc);  // cells that may hold a sample within 2 rc
  PointSet<2> points;
  // Boundary sampling makes about 0.875 samples per r^2 (rho ~ 0.87); reserving
  // that avoids the doubling that would otherwise set the peak memory.
  points.reserve(static_cast<std::size_t>(0.9 * domain.volume() / r2) + 16);
  Rng rng(seed);
  append_sample(points, grid, uniform_point(rng, domain));

  const double reach2 = 4.0 * rc * rc, inv_reach = 1.0 / (2.0 * rc);
  const double sin60 = std::sqrt(3.0) / 2.0;
  detail::FreeArcs arcs;
  Neighbourhood nb;
  // Asking for the grid rows of the front sample four places ahead pays on
  // grids far larger than the caches (+8-9% at 10^7 samples, a 100 MB grid) and
  // costs on smaller ones (-2% at 10^6, 10 MB), as measured here.
  const bool prefetch = grid.bytes() > (std::size_t{32} << 20);
  // The front is every sample not yet processed, in insertion order (breadth
  // first), which keeps the grid rows and points being touched in cache.
  for (std::size_t head = 0; head < points.size(); ++head) {
    const Point<2> p = points[head];
    nb.blocked = 0;
    if (prefetch && head + 4 < points.size()) grid.prefetch_window(points[head + 4], reach);
    if (!domain.periodic) {
      // A wall at distance w < rc blocks the directions whose component
      // towards it exceeds w / rc: from (-w, h) to (-w, -h) for the low x wall, etc.
      const auto wall = [&](const detail::DiamondArc& a) {
        nb.lo[nb.blocked] = a.lo;
        nb.len[nb.blocked] = a.len;
        ++nb.blocked;
      };
      for (int axis = 0; axis < 2; ++axis) {
        const double to_lo = p[axis] - domain.lo[axis], to_hi = domain.hi[axis] - p[axis];
        if (to_lo < rc) {
          const double h = std::sqrt(rc * rc - to_lo * to_lo);
          wall(axis == 0 ? detail::diamond_arc(-to_lo, h, -to_lo, -h) : detail::diamond_arc(-h, -to_lo, h, -to_lo));
        }
        if (to_hi < rc) {
          const double h = std::sqrt(rc * rc - to_hi * to_hi);
          wall(axis == 0 ? detail::diamond_arc(to_hi, -h, to_hi, h) : detail::diamond_arc(h, to_hi, -h, to_hi));
        }
      }
    }
    bool seam = false;
    // (Gathered by scalar loads in both kernels: AVX-512 gathers of the
    // points, seven rows of them, measured slower here.)
    ScalarNeighbours::gather(grid, points, domain, p, reach, reach2, nb, seam);
    Kernel::block(inv_reach, p, seam, nb);
    if (nb.blocked > detail::FreeArcs::kMaxBlocked)
      throw std::logic_error("dunbar-humphreys: more blocked arcs than a circle can have");
    Kernel::complement(nb, arcs);

    // Away from a seam the plain distances decide exactly as the nearest
    // images would: q is within rc of p and a neighbour within 2 rc, so a
    // coordinate difference beyond half a period (> 2 rc) leaves both
    // distances above r.
    const auto far_enough = [&](const Point<2>& a, const Point<2>& b) {
      if (seam) return domain.distance2(a, b) >= r2;
      const double dx = a[0] - b[0], dy = a[1] - b[1];
      return dx * dx + dy * dy >= r2;
    };
    int rejected = 0;
    while (!arcs.empty()) {
      const double t = arcs.sample(rng);  // uniform in true angle over the free arcs
      const auto [vx, vy] = detail::diamond_direction(t);
      const double scale = rc / std::sqrt(vx * vx + vy * vy);
      // A plain window keeps p three cells (> rc) from every torus seam, so
      // only a seam window can put q across one.
      Point<2> q{{p[0] + vx * scale, p[1] + vy * scale}};
      if (seam) q = domain.wrap(q);
      const bool fits = domain.contains(q) && far_enough(p, q) && Kernel::clear_of_neighbours(nb, q, r2, seam, domain);
      if (!fits) {
        // Only rounding at an arc's end or at a wall gets here: drop a sliver
        // around t, twice as wide each time (6.7e-6 in all, at most 1.4e-5 rad; an arc of w rad
        // dropped leaves a hole of depth about w^2 r / 8). Bounded per front sample.
        if (++rejected > 24)
          throw Failure("dunbar-humphreys: 24 candidates rejected by rounding around one sample (radius " +
                        detail::format_number(r) +
                        "): the coordinates are too coarse for this radius (a domain far from the origin?)");
        const double sliver = 1e-13 * std::ldexp(1.0, rejected);
        arcs.remove({t - sliver < 0.0 ? t - sliver + 4.0 : t - sliver, 2.0 * sliver});
        continue;
      }
      // The new sample is a neighbour for the rest of p's circle.
      append_sample(points, grid, q);
      nb.sx[nb.count] = q[0];
      nb.sy[nb.count] = q[1];
      ++nb.count;
      // It blocks exactly +-60 degrees of the circle.
      arcs.remove(detail::diamond_arc(0.5 * vx + sin60 * vy, 0.5 * vy - sin60 * vx, 0.5 * vx - sin60 * vy,
                                      0.5 * vy + sin60 * vx));
    }
  }
  return points;
}

PointSet<2> boundary_sampling_scalar(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed) {
  return boundary_sampling_with<ScalarNeighbours>(params, domain, seed);
}

#if PDS_HAVE_AVX512_KERNEL
PDS_AVX512 PointSet<2> boundary_sampling_avx512(const DunbarHumphreysParams& params, const Domain<2>& domain,
                                                std::uint64_t seed) {
  return boundary_sampling_with<Avx512Neighbours>(params, domain, seed);
}
#endif

/// One front sample's free arcs from the given neighbours (offsets taken
/// plainly, no walls) by one kernel's block and complement: the test hook
/// that reaches the AVX-512 paths for more than 16 arcs, which real
/// neighbourhoods (13 at most in the runs measured) do not.
template <class Kernel>
[[gnu::always_inline]] inline std::vector<std::array<double, 2>> free_arcs_with(const Point<2>& p,
                                                                                const PointSet<2>& neighbours,
                                                                                double radius) {
  if (neighbours.size() > static_cast<std::size_t>(detail::FreeArcs::kMaxBlocked))
    throw InvalidArgument("dunbar-humphreys: more neighbours than a circle can have");
  Neighbourhood nb;
  // Arcs a kernel fails to write stay NaN and show in the result (stack
  // memory would otherwise hold the other kernel's numbers from the last call).
  std::fill(std::begin(nb.lo), std::end(nb.lo), std::numeric_limits<double>::quiet_NaN());
  std::fill(std::begin(nb.len), std::end(nb.len), std::numeric_limits<double>::quiet_NaN());
  for (const Point<2>& q : neighbours) {
    nb.sx[nb.count] = q[0];
    nb.sy[nb.count] = q[1];
    ++nb.count;
  }
  Kernel::block(1.0 / (2.0 * radius * (1.0 + 1e-10)), p, false, nb);
  detail::FreeArcs arcs;
  Kernel::complement(nb, arcs);
  std::vector<std::array<double, 2>> out;
  for (const detail::DiamondArc& a : arcs.arcs()) out.push_back({a.lo, a.len});
  return out;
}

std::vector<std::array<double, 2>> free_arcs_scalar(const Point<2>& p, const PointSet<2>& neighbours, double radius) {
  return free_arcs_with<ScalarNeighbours>(p, neighbours, radius);
}

#if PDS_HAVE_AVX512_KERNEL
PDS_AVX512 std::vector<std::array<double, 2>> free_arcs_avx512(const Point<2>& p, const PointSet<2>& neighbours,
                                                               double radius) {
  return free_arcs_with<Avx512Neighbours>(p, neighbours, radius);
}
#endif

// ---------------------------------------------------------------------------
// Variant 1: the paper's scalloped sectors (sampling the full annulus r..2r).
// ---------------------------------------------------------------------------

/// A boundary curve of a scalloped sector, in polar coordinates around the
/// front sample p: the ray at angle theta meets it at radius(theta). Either a
/// circle (centre c relative to p, radius rho; branch -1 is the near crossing
/// of the ray, +1 the far one; a circle centred at p has d = 0) or a wall, the
/// line {x : x . (cos psi, sin psi) = h}.
struct Curve {
  bool line = false;
  double cx = 0.0, cy = 0.0, rho = 0.0, branch = 1.0, d = 0.0, phi = 0.0;  // circle
  double h = 0.0, psi = 0.0;                                               // line

  static Curve circle(double cx, double cy, double rho, double branch) {
    Curve c;
    c.cx = cx;
    c.cy = cy;
    c.rho = rho;
    c.branch = branch;
    c.d = std::hypot(cx, cy);
    c.phi = c.d > 0.0 ? std::atan2(cy, cx) : 0.0;
    return c;
  }
  static Curve wall(double h, double psi) {
    Curve c;
    c.line = true;
    c.h = h;
    c.psi = psi;
    return c;
  }

  double radius(double theta) const {
    if (line) return h / std::cos(theta - psi);
    if (d == 0.0) return rho;
    const double u = theta - phi, s = d * std::sin(u);
    return d * std::cos(u) + branch * std::sqrt(std::max(0.0, rho * rho - s * s));
  }

  /// An antiderivative of radius(theta)^2 / 2 (the area swept by the ray),
  /// continuous over any angular range where the curve is defined.
  double primitive(double theta) const {
    if (line) return 0.5 * h * h * std::tan(wrap_angle(theta - psi));
    if (d == 0.0) return 0.5 * rho * rho * theta;
    // r^2 = rho^2 + d^2 cos 2u + 2 branch d cos u sqrt(rho^2 - d^2 sin^2 u);
    // with w = d sin u the last term integrates to w sqrt(rho^2 - w^2) + rho^2 asin(w / rho).
    const double u = wrap_angle(theta - phi), w = d * std::sin(u);
    const double root = std::sqrt(std::max(0.0, rho * rho - w * w));
    const double arc = std::asin(std::clamp(w / rho, -1.0, 1.0));
    return 0.5 * (rho * rho * u + 0.5 * d * d * std::sin(2.0 * u) + branch * (w * root + rho * rho * arc));
  }

  /// u in (-pi, pi]: neighbour circles and walls span less than pi around
  /// their direction, so the primitive is continuous inside a sector.
  static double wrap_angle(double u) {
    if (u > std::numbers::pi) return u - kTwoPi;
    if (u <= -std::numbers::pi) return u + kTwoPi;
    return u;
  }
};

/// Angles in [0, 2 pi) of the points where the geometric circles/lines of two
/// curves meet (both branches of a circle; extra angles are harmless).
void crossings(const Curve& a, const Curve& b, std::vector<double>& out) {
  auto push = [&](double x, double y) {
    double t = std::atan2(y, x);
    if (t < 0.0) t += kTwoPi;
    out.push_back(t);
  };
  if (a.line && b.line) {
    const double ax = std::cos(a.psi), ay = std::sin(a.psi), bx = std::cos(b.psi), by = std::sin(b.psi);
    const double det = ax * by - ay * bx;
    if (std::abs(det) < 1e-12) return;
    push((a.h * by - b.h * ay) / det, (ax * b.h - bx * a.h) / det);
    return;
  }
  if (a.line || b.line) {
    const Curve& l = a.line ? a : b;
    const Curve& c = a.line ? b : a;
    const double nx = std::cos(l.psi), ny = std::sin(l.psi);
    const double t = l.h - (nx * c.cx + ny * c.cy);
    if (std::abs(t) > c.rho) return;
    const double half = std::sqrt(c.rho * c.rho - t * t);
    const double fx = c.cx + t * nx, fy = c.cy + t * ny;
    push(fx - half * ny, fy + half * nx);
    push(fx + half * ny, fy - half * nx);
    return;
  }
  const double dx = b.cx - a.cx, dy = b.cy - a.cy, dd = std::hypot(dx, dy);
  if (dd == 0.0 || dd > a.rho + b.rho || dd < std::abs(a.rho - b.rho)) return;
  const double along = (a.rho * a.rho - b.rho * b.rho + dd * dd) / (2.0 * dd);
  const double half = std::sqrt(std::max(0.0, a.rho * a.rho - along * along));
  const double mx = a.cx + along * dx / dd, my = a.cy + along * dy / dd;
  push(mx - half * dy / dd, my + half * dx / dd);
  push(mx + half * dy / dd, my - half * dx / dd);
}

/// The available region of one front sample: the annulus r..2r around it
/// minus the disks of radius r around its neighbours and minus the outside of
/// the domain, as scalloped sectors {theta in [t0, t1], inner(theta) <= rho <=
/// outer(theta)} with their exact areas.
class ScallopedRegion {
 public:
  void reset(double r) {
    curves_.clear();
    sectors_.clear();
    curves_.push_back(Curve::circle(0.0, 0.0, r, 1.0));
    curves_.push_back(Curve::circle(0.0, 0.0, 2.0 * r, 1.0));
    add({0.0, kTwoPi, 0, 1}, sectors_);
  }
  bool empty() const { return sectors_.empty(); }
  double area() const {
    double total = 0.0;
    for (const Sector& s : sectors_) total += s.area;
    return total;
  }

  /// Removes the disk of radius r centred at (cx, cy) relative to the sample
  /// (at distance >= r from it; no effect beyond 3r).
  void remove_disk(double cx, double cy, double r) {
    const double d = std::hypot(cx, cy);
    if (d >= 3.0 * r) return;
    const int near = static_cast<int>(curves_.size());
    curves_.push_back(Curve::circle(cx, cy, r, -1.0));
    curves_.push_back(Curve::circle(cx, cy, r, 1.0));
    const double half = d > r ? std::asin(r / d) : 0.5 * std::numbers::pi;
    cut(near, near + 1, curves_[near].phi, half);
  }

  /// Removes the half-plane beyond the wall x . (cos psi, sin psi) = h, h > 0.
  void remove_beyond_wall(double h, double psi) {
    const int wall = static_cast<int>(curves_.size());
    curves_.push_back(Curve::wall(h, psi));
    cut(wall, -1, psi, 0.5 * std::numbers::pi);
  }

  /// A point (angle, radius) uniformly distributed over the region; requires !empty().
  std::pair<double, double> sample(Rng& rng) const {
    double u = rng.uniform() * area();
    const Sector* chosen = &sectors_.back();
    for (const Sector& s : sectors_) {
      if (u < s.area) {
        chosen = &s;
        break;
      }
      u -= s.area;
    }
    const Sector& s = *chosen;
    const Curve &a = curves_[s.inner], &b = curves_[s.outer];
    // Inverse CDF of the angle: the swept area from t0 is monotone; Newton
    // steps on it, kept inside a shrinking bracket (bisection otherwise).
    const double target = std::min(u, s.area), base = b.primitive(s.t0) - a.primitive(s.t0);
    double lo = s.t0, hi = s.t1, theta = s.t0 + (s.t1 - s.t0) * (target / s.area);
    for (int it = 0; it < 100 && hi - lo > 1e-15 * kTwoPi; ++it) {
      const double f = b.primitive(theta) - a.primitive(theta) - base - target;
      if (f > 0.0)
        hi = theta;
      else
        lo = theta;
      const double ra = a.radius(theta), rb = b.radius(theta), slope = 0.5 * (rb * rb - ra * ra);
      double next = slope > 0.0 ? theta - f / slope : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - theta) < 1e-16) break;
      theta = next;
    }
    const double ra = a.radius(theta), rb = b.radius(theta);
    const double rad = std::sqrt(ra * ra + rng.uniform() * std::max(0.0, rb * rb - ra * ra));
    return {theta, rad};
  }

 private:
  // Pieces narrower than this are dropped (a sliver under 1e-11 radius wide).
  static constexpr double kMinAngle = 1e-12;
  struct Sector {
    double t0, t1;
    int inner, outer;
    double area = 0.0;
  };

  void add(Sector s, std::vector<Sector>& to) const {
    if (s.t1 - s.t0 <= kMinAngle) return;
    if (!to.empty() && to.back().t1 == s.t0 && to.back().inner == s.inner && to.back().outer == s.outer) {
      to.back().t1 = s.t1;
      to.back().area = area(to.back());
      return;
    }
    s.area = area(s);
    if (s.area > 0.0) to.push_back(s);
  }

  double area(const Sector& s) const {
    const Curve &a = curves_[s.inner], &b = curves_[s.outer];
    return std::max(0.0, (b.primitive(s.t1) - b.primitive(s.t0)) - (a.primitive(s.t1) - a.primitive(s.t0)));
  }

  static bool within(double theta, double centre, double half) {
    return std::abs(Curve::wrap_angle(theta - centre)) < half;
  }

  /// Removes {near(theta) < rho < far(theta)} for theta within `half` of
  /// `centre` (far = -1: no far curve, everything beyond near).
  void cut(int near, int far, double centre, double half) {
    next_.clear();
    const Curve& n = curves_[near];
    for (const Sector& s : sectors_) {
      const double c = centre < 0.0 ? centre + kTwoPi : centre;
      const bool overlaps = within(s.t0, centre, half) || within(s.t1, centre, half) || (c >= s.t0 && c <= s.t1) ||
                            (c + kTwoPi <= s.t1) || (c - kTwoPi >= s.t0);
      if (!overlaps) {
        next_.push_back(s);
        continue;
      }
      breaks_.assign({s.t0, s.t1});
      for (double e : {centre - half, centre + half}) {
        e = e < 0.0 ? e + kTwoPi : (e >= kTwoPi ? e - kTwoPi : e);
        breaks_.push_back(e);
      }
      crossings(n, curves_[s.inner], breaks_);
      crossings(n, curves_[s.outer], breaks_);
      std::sort(breaks_.begin(), breaks_.end());
      for (std::size_t i = 0; i + 1 < breaks_.size(); ++i) {
        const double t0 = std::max(breaks_[i], s.t0), t1 = std::min(breaks_[i + 1], s.t1);
        if (t1 <= t0) continue;
        const double m = 0.5 * (t0 + t1);
        if (!within(m, centre, half)) {
          add({t0, t1, s.inner, s.outer}, next_);
          continue;
        }
        const double a = curves_[s.inner].radius(m), b = curves_[s.outer].radius(m);
        const double rn = n.radius(m), rf = far >= 0 ? curves_[far].radius(m) : INFINITY;
        if (rn > a) add({t0, t1, s.inner, rn < b ? near : s.outer}, next_);
        if (rf < b) add({t0, t1, rf > a ? far : s.inner, s.outer}, next_);
      }
    }
    sectors_.swap(next_);
  }

  std::vector<Curve> curves_;  // 0: circle r, 1: circle 2r, then walls and neighbours
  std::vector<Sector> sectors_, next_;
  std::vector<double> breaks_;
};

/// The point at polar offset (rad, theta) from p, wrapped into the domain, in
/// q; true when it lies inside and at least r (r2 = r^2) from p and from every
/// sample listed in `neighbours`.
bool polar_candidate(const Domain<2>& domain, const PointSet<2>& points, const std::vector<std::int32_t>& neighbours,
                     const Point<2>& p, double rad, double theta, double r2, Point<2>& q) {
  q = domain.wrap(Point<2>{{p[0] + rad * std::cos(theta), p[1] + rad * std::sin(theta)}});
  if (!domain.contains(q) || domain.distance2(p, q) < r2) return false;
  for (const std::int32_t j : neighbours)
    if (domain.distance2(q, points[static_cast<std::size_t>(j)]) < r2) return false;
  return true;
}

/// The available region of sample `pi` (walls first, then the samples
/// within 3r, nearest first: they remove the most, which leaves fewer sectors
/// for the rest to cut), and those samples in `neighbours`.
void build_region(const Domain<2>& domain, double r, CellGrid& grid, Reach reach, const PointSet<2>& points,
                  std::int32_t pi, ScallopedRegion& region, std::vector<std::int32_t>& neighbours,
                  std::vector<std::array<double, 3>>& offsets) {
  constexpr double kPi = std::numbers::pi;
  const Point<2> p = points[static_cast<std::size_t>(pi)];
  region.reset(r);
  if (!domain.periodic)
    for (int axis = 0; axis < 2; ++axis) {
      const double to_lo = p[axis] - domain.lo[axis], to_hi = domain.hi[axis] - p[axis];
      if (to_lo < 2.0 * r) region.remove_beyond_wall(to_lo, axis == 0 ? kPi : 1.5 * kPi);
      if (to_hi < 2.0 * r) region.remove_beyond_wall(to_hi, axis == 0 ? 0.0 : 0.5 * kPi);
    }
  neighbours.clear();
  offsets.clear();
  const double reach2 = 9.0 * r * r;
  grid.for_each_near(p, reach, [&](std::int32_t j) {
    if (j == pi) return;
    const Point<2>& s = points[static_cast<std::size_t>(j)];
    const double dx = domain.delta(p[0], s[0], 0), dy = domain.delta(p[1], s[1], 1);
    const double d2 = dx * dx + dy * dy;
    if (d2 >= reach2) return;
    neighbours.push_back(j);
    offsets.push_back({d2, dx, dy});
  });
  std::sort(offsets.begin(), offsets.end());
  for (const auto& [d2, dx, dy] : offsets) {
    if (region.empty()) break;
    region.remove_disk(dx, dy, r);
  }
}

/// Variant 2: uniform over the union of all front regions, which makes the
/// next sample uniform over the free area within 2r of the samples, as dart
/// throwing's would be there. A front sample is picked in proportion to its
/// stored area (an upper bound: areas only shrink), kept with probability
/// true area / stored area; a point x is drawn uniformly in its region and
/// kept with probability 1 / m(x), m = the samples within 2r of x (each of
/// whose regions contains x). One sample per pick; O(N log N).
PointSet<2> global_scalloped_sampling(const DunbarHumphreysParams& params, const Domain<2>& domain,
                                      std::uint64_t seed) {
  const double r = params.radius, r2 = r * r;
  CellGrid grid(domain, r / std::sqrt(2.0));
  const Reach reach = grid.reach(3.0 * r);
  const Reach reach_2r = grid.reach(2.0 * r);
  PointSet<2> points;
  points.reserve(static_cast<std::size_t>(0.72 * domain.volume() / r2) + 16);
  detail::SumTree areas;
  areas.set(points.capacity(), 0.0);  // size the tree once for the expected count
  const double annulus = 3.0 * std::numbers::pi * r2;
  Rng rng(seed);
  auto add = [&](const Point<2>& q) {
    const std::int32_t index = append_sample(points, grid, q);
    areas.set(static_cast<std::size_t>(index), annulus);
    return index;
  };
  add(uniform_point(rng, domain));

  ScallopedRegion region;
  std::vector<std::int32_t> neighbours;
  std::vector<std::array<double, 3>> offsets;
  std::uint64_t rejected = 0;
  while (areas.total() > 0.0) {
    const std::size_t pick = areas.find(rng.uniform() * areas.total());
    const double stored = areas.weight(pick);
    if (stored <= 0.0) continue;  // only if rounding in find() stepped onto an empty leaf
    const auto pi = static_cast<std::int32_t>(pick);
    build_region(domain, r, grid, reach, points, pi, region, neighbours, offsets);
    const double area = region.empty() ? 0.0 : region.area();
    areas.set(pick, area);
    if (area <= 0.0 || rng.uniform() * stored >= area) continue;
    const Point<2> p = points[pick];
    const auto [theta, rad] = region.sample(rng);
    Point<2> q;
    if (!polar_candidate(domain, points, neighbours, p, rad, theta, r2, q)) {
      // Only rounding on a sector's boundary can get here; bounded overall.
      if (++rejected > 1000 + points.size())
        throw Failure("dunbar-humphreys: too many candidates rejected by rounding (radius " + detail::format_number(r) +
                      ")");
      continue;
    }
    int m = 0;
    grid.for_each_near(q, reach_2r, [&](std::int32_t j) {
      m += domain.distance2(q, points[static_cast<std::size_t>(j)]) <= 4.0 * r2;
    });
    if (m > 1 && rng.uniform() * m >= 1.0) continue;
    add(q);
  }
  return points;
}

/// Variant 1: each front sample (picked at random from the front) is filled
/// completely: new samples are drawn uniformly over its scalloped region until
/// the region is empty; each new one removes its disk and joins the front.
PointSet<2> scalloped_sector_sampling(const DunbarHumphreysParams& params, const Domain<2>& domain,
                                      std::uint64_t seed) {
  const double r = params.radius, r2 = r * r;
  CellGrid grid(domain, r / std::sqrt(2.0));
  // Cells that may hold a sample within 3r (the reach of a disk into the annulus).
  const Reach reach = grid.reach(3.0 * r);
  PointSet<2> points;
  // Variant 1 makes about 0.735 samples per r^2 (rho ~ 0.80); reserving a little more
  // avoids the doubling that would otherwise set the peak memory.
  points.reserve(static_cast<std::size_t>(0.76 * domain.volume() / r2) + 16);
  std::vector<std::int32_t> front;
  Rng rng(seed);
  auto add = [&](const Point<2>& q) {
    const std::int32_t index = append_sample(points, grid, q);
    front.push_back(index);
    return index;
  };
  add(uniform_point(rng, domain));

  ScallopedRegion region;
  std::vector<std::int32_t> neighbours;        // samples within 3r of the front sample, and its new ones
  std::vector<std::array<double, 3>> offsets;  // (distance^2, dx, dy) of the neighbours found in the grid
  while (!front.empty()) {
    // A random front sample, removed from the front (swap with the last).
    const std::size_t pick = rng.below(front.size());
    const std::int32_t pi = front[pick];
    front[pick] = front.back();
    front.pop_back();
    const Point<2> p = points[static_cast<std::size_t>(pi)];

    build_region(domain, r, grid, reach, points, pi, region, neighbours, offsets);

    int rejected = 0;
    while (!region.empty()) {
      const auto [theta, rad] = region.sample(rng);
      Point<2> q;
      if (!polar_candidate(domain, points, neighbours, p, rad, theta, r2, q)) {
        // Only rounding on a sector's boundary can get here (the sectors are
        // exact): a new draw lands elsewhere. Bounded per front sample.
        if (++rejected > 1000)
          throw Failure("dunbar-humphreys: 1000 candidates rejected by rounding around one sample (radius " +
                        detail::format_number(r) + ")");
        continue;
      }
      neighbours.push_back(add(q));
      // Remove the new disk, from the offset as stored (after wrapping).
      region.remove_disk(domain.delta(p[0], q[0], 0), domain.delta(p[1], q[1], 1), r);
    }
  }
  return points;
}

}  // namespace

namespace detail {

bool dunbar_humphreys_has_vector_kernel() {
#if PDS_HAVE_AVX512_KERNEL
  // The kernel is compiled for the whole x86-64-v4 level (AVX-512 F, BW, CD,
  // DQ, VL with AVX2, BMI2, ...), so the processor must have all of it.
  static const bool has = __builtin_cpu_supports("x86-64-v4");
  return has;
#else
  return false;
#endif
}

namespace {
/// Throws InvalidArgument when the vector kernel is asked for where there is none.
void check_vector_kernel_request(bool vector_kernel) {
  if (!vector_kernel) return;
#if PDS_HAVE_AVX512_KERNEL
  if (!dunbar_humphreys_has_vector_kernel())
    throw InvalidArgument("dunbar-humphreys: the AVX-512 kernel was asked for on a processor without it");
#else
  throw InvalidArgument("dunbar-humphreys: this build has no vector kernel");
#endif
}
}  // namespace

PointSet<2> dunbar_humphreys_boundary(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed,
                                      bool vector_kernel) {
  domain.validate();
  require_radius_budget(domain, params.radius, params.max_points);
  check_vector_kernel_request(vector_kernel);
#if PDS_HAVE_AVX512_KERNEL
  if (vector_kernel) return boundary_sampling_avx512(params, domain, seed);
#endif
  return boundary_sampling_scalar(params, domain, seed);
}

std::vector<std::array<double, 2>> dunbar_humphreys_free_arcs(const Point<2>& p, const PointSet<2>& neighbours,
                                                              double radius, bool vector_kernel) {
  check_vector_kernel_request(vector_kernel);
#if PDS_HAVE_AVX512_KERNEL
  if (vector_kernel) return free_arcs_avx512(p, neighbours, radius);
#endif
  return free_arcs_scalar(p, neighbours, radius);
}

}  // namespace detail

PointSet<2> dunbar_humphreys(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed) {
  domain.validate();
  const double r = params.radius;
  require_radius_budget(domain, r, params.max_points);
  if (params.variant < 0 || params.variant > 2)
    throw InvalidArgument(
        "dunbar-humphreys: variant must be 0 (boundary), 1 (scalloped sectors) or 2 (global sectors), got " +
        std::to_string(params.variant));
  if (params.variant >= 1) {
    if (domain.periodic)
      for (int i = 0; i < 2; ++i)
        if (domain.extent(i) <= 6.0 * r)  // samples within 3r need one nearest image
          throw InvalidArgument(
              "dunbar-humphreys: variants 1 and 2 on a torus need every period above 6 radius; axis " +
              std::to_string(i) + " has " + detail::format_number(domain.extent(i)) + " for radius " +
              detail::format_number(r));
    return params.variant == 1 ? scalloped_sector_sampling(params, domain, seed)
                               : global_scalloped_sampling(params, domain, seed);
  }
  return detail::dunbar_humphreys_boundary(params, domain, seed, detail::dunbar_humphreys_has_vector_kernel());
}

}  // namespace pds
