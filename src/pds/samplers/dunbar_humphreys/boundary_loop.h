#pragma once
// Boundary sampling (D. Dunbar and G. Humphreys, "A spatial data structure for
// fast Poisson-disk sample generation", ACM SIGGRAPH 2006; its boundary sampling): the
// loop over the front and the scalar neighbourhood kernel, written once as
// templates over the kernel and instantiated by each kernel's translation unit
// (boundary_scalar.cpp, boundary_avx512.cpp). Private to those two files.
//
// A sample's "available boundary" is the part of the circle of radius r
// around it that lies outside the disks of radius r of all other samples (and
// inside the domain): the paper's scalloped region restricted to the circle,
// a set of angular intervals, which is what we store. Front samples are taken
// in insertion order (breadth first, which keeps memory access local; the
// guarantees do not depend on the order), from one seed in a box and 16 on a
// torus (see the seeds below: one seed's front meets itself along two
// axis-parallel lines of the torus). A front sample's available arcs
// are computed from the samples within 2r (a sample at distance d blocks the
// directions within acos(d / 2r) of its own); then points are drawn uniformly
// in angle on the remaining arcs, each new sample blocking +-60 degrees
// around itself, until no arc remains. The new samples join the front; the
// sample leaves it. Directions are handled without trigonometry
// (pds/detail/diamond_arcs.h): an arc's ends are the neighbour's direction
// rotated by -+acos(d / 2r), which needs one square root, and they are
// ordered by their "diamond angle", which needs one division for both ends; a
// uniform true angle is drawn by rejection (tested there). The free arcs come
// from the blocked ones without sorting (FreeArcs::assign_complement_unsorted).
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

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "cell_grid.h"
#include "pds/detail/diamond_arcs.h"
#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/rng.h"
#include "pds/samplers/dunbar_humphreys.h"
#include "pds/samplers/random.h"
#include "sample_progress.h"

namespace pds::detail::dh {

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
/// order; no fused multiply-adds: these files are built with
/// -ffp-contract=off): ScalarNeighbours, and on x86-64 with AVX-512
/// Avx512Neighbours (boundary_avx512.cpp), which blocks and complements eight
/// neighbours or arcs at a time (its gather and exact checks are the scalar
/// ones). Same seed, same bytes either way (tested).
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

/// Seeds of the front on a torus, and the tries to place them (below).
inline constexpr std::size_t kTorusSeeds = 16;
inline constexpr int kTorusSeedAttempts = 256;

/// The order in which front samples are processed. From one seed: insertion
/// order (breadth first; the front is the unprocessed tail of the output).
/// From several: each seed's cluster keeps its own breadth-first queue, and
/// the clusters take turns, each advancing by kGenerations generations a
/// turn, so that all grow at the same rate (their fronts meet on the edges
/// of the seeds' Voronoi cells, give or take a few generations) while the
/// memory a turn touches is one cluster's front, not all of them: processed
/// one generation at a time, the 16 fronts of a torus, together 4 times as
/// long as one seed's, cost 15% of the speed at 10^6 samples.
class FrontOrder {
 public:
  static constexpr int kGenerations = 8;

  /// The first `seeds` samples of the output are the seeds.
  explicit FrontOrder(std::size_t seeds) : seen_(seeds) {
    if (seeds < 2) return;
    clusters_.resize(seeds);
    for (std::size_t k = 0; k < seeds; ++k) clusters_[k].items.push_back(static_cast<std::int32_t>(k));
    clusters_[0].end = 1;
  }

  /// The next front sample to process, given that the output now holds
  /// `size` samples (those added since the last call are the last front
  /// sample's children), and one a few places later (for prefetching; any
  /// index, possibly past the output). False when the front is empty.
  bool next(std::size_t size, std::size_t& head, std::size_t& ahead) {
    if (clusters_.empty()) {
      head = next_++;
      ahead = head + 4;
      return head < size;
    }
    for (std::size_t j = seen_; j < size; ++j) clusters_[current_].items.push_back(static_cast<std::int32_t>(j));
    seen_ = size;
    // Each pass either returns, starts a generation of the current cluster,
    // or moves to the next cluster; a full round of clusters with nothing
    // left ends the front.
    for (std::size_t idle = 0; idle <= clusters_.size();) {
      Cluster& c = clusters_[current_];
      if (c.head < c.end) {
        head = static_cast<std::size_t>(c.items[c.head++]);
        ahead = c.head + 3 < c.items.size() ? static_cast<std::size_t>(c.items[c.head + 3]) : SIZE_MAX;
        return true;
      }
      // The first turn processes the seeds alone, before any cluster can grow
      // over another seed's circle (they are 4 rc apart): every seed gets a
      // child at exactly rc.
      if (c.head < c.items.size() && ++generation_ < (turns_ < clusters_.size() ? 1 : kGenerations)) {
        c.end = c.items.size();
        continue;
      }
      // The turn is over: drop the cluster's processed entries once they
      // are the larger part, and pass to the next cluster.
      if (c.head > 1024 && 2 * c.head > c.items.size()) {
        c.items.erase(c.items.begin(), c.items.begin() + static_cast<std::ptrdiff_t>(c.head));
        c.head = 0;
      }
      generation_ = 0;
      ++turns_;
      current_ = current_ + 1 == clusters_.size() ? 0 : current_ + 1;
      Cluster& d = clusters_[current_];
      d.end = d.items.size();
      idle = d.head == d.end ? idle + 1 : 0;
    }
    return false;
  }

 private:
  struct Cluster {
    std::vector<std::int32_t> items;  // its samples in insertion order, from items[head] on unprocessed
    std::size_t head = 0, end = 0;    // end: where the generation being processed stops
  };
  std::vector<Cluster> clusters_;
  std::size_t seen_ = 0, next_ = 0, current_ = 0, turns_ = 0;
  int generation_ = 0;
};

/// Boundary sampling with a given neighbourhood kernel (inlined into each
/// kernel's entry point, so that the AVX-512 one is compiled for its target).
template <class Kernel>
[[gnu::always_inline]] inline PointSet<2> boundary_sampling_with(const DunbarHumphreysParams& params,
                                                                 const Domain<2>& domain, std::uint64_t seed) {
  const double r = params.radius, r2 = r * r;
  // The circle radius: a hair above r, so that samples placed on it stay at
  // least r apart after rounding (see the comment at the top).
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
  advise_huge_pages(points);
  Rng rng(seed);
  append_sample(points, grid, uniform_point(rng, domain));
  if (domain.periodic) {
    // On a torus one seed's front meets itself halfway to the seed's periodic
    // images, on the lines x = x0 + Lx/2 and y = y0 + Ly/2: a seam of packing
    // defects parallel to the axes, a cross along the axes in the averaged
    // periodogram (twice the power of the other low frequencies). The fronts
    // of several seeds at random places meet on the edges of their Voronoi
    // cells instead, which point every way. With 4 seeds a cell often spans
    // a whole period and is bounded by its own image (axis-parallel again:
    // the axes kept 1.13 times the power); 16 leave 1.07, while every seed
    // adds seams, power at low frequencies (64 seeds: the cross is gone
    // entirely but that power doubles). A box needs none (one front never
    // meets itself there). Seeds are kept 4 rc apart, so that each one's
    // circle is free when it is processed (its first child is at exactly
    // rc); a torus too small for all of them keeps fewer. Measured in
    // docs/dunbar-humphreys.md.
    for (int attempt = 0; attempt < kTorusSeedAttempts && points.size() < kTorusSeeds; ++attempt) {
      const Point<2> q = uniform_point(rng, domain);
      bool apart = true;
      for (const Point<2>& s : points) apart &= domain.distance2(q, s) >= 16.0 * rc * rc;
      if (apart) append_sample(points, grid, q);
    }
  }

  const double reach2 = 4.0 * rc * rc, inv_reach = 1.0 / (2.0 * rc);
  const double sin60 = std::sqrt(3.0) / 2.0;
  detail::FreeArcs arcs;
  Neighbourhood nb;
  // Asking for the grid rows of the front sample four places ahead pays on
  // grids far larger than the caches (+8-9% at 10^7 samples, a 100 MB grid) and
  // costs on smaller ones (-2% at 10^6, 10 MB), as measured here.
  const bool prefetch = grid.bytes() > (std::size_t{32} << 20);
  // The front is every sample not yet processed, breadth first from each seed
  // (FrontOrder), which keeps the grid rows and points being touched in cache.
  FrontOrder order(points.size());
  std::size_t head = 0, ahead = 0;
  ProgressReporter progress = sample_progress(params, domain);
  while (order.next(points.size(), head, ahead)) {
    if ((head & (kReportEvery - 1)) == 0) progress.update(static_cast<double>(points.size()));
    const Point<2> p = points[head];
    nb.blocked = 0;
    if (prefetch && ahead < points.size()) grid.prefetch_window(points[ahead], reach);
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
  progress.finish();
  return points;
}

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

}  // namespace pds::detail::dh
