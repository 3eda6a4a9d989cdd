// T. Schlömer, D. Heck, O. Deussen, Farthest-point optimized point sets with
// maximized minimum distance, High Performance Graphics 2011, 135-142.
//
// Method (the paper's local variant, section 4): the points live in a
// Delaunay triangulation of the torus. A sweep takes each point x in turn
// (along a Hilbert curve through the start), removes it, and looks at the
// faces incident to its former Delaunay neighbours: they include the faces
// that re-triangulate the hole, whose circumcentres are the Voronoi vertices
// of the remaining points around x's old place. The centre of the largest of
// these empty circumcircles is the farthest point from the others found near
// x; x goes there if that is farther from its nearest neighbour than its old
// place was, else it goes back. Sweeps repeat until one grows neither the
// minimum nor the mean nearest-neighbour distance by a tolerance (the stop
// rule) or the sweep budget is spent. The paper reports relative radius ~0.93
// and an isotropic spectrum with a pronounced peak.
//
// Our realisation: on a torus CGAL's Periodic_2_Delaunay_triangulation_2
// (exact predicates, inexact constructions; square tori only), each point
// stored once, its index in the vertex's info; circumcentres are computed
// relative to one vertex of the face, from the faces' periodic offsets (as in
// samplers/jones.cpp), then wrapped into the domain. In a box (the paper
// works on the torus) CGAL's Delaunay_triangulation_2: the farthest point of
// a box lies at a Voronoi vertex inside it, where a Voronoi edge meets a
// side, or at a corner, so the local search around the former neighbours
// takes all three (BoxOptimizer). The acceptance test and
// every reported distance use Domain::distance2 on the stored coordinates:
// a move is kept only when the moved point's nearest Delaunay neighbour (its
// nearest point) is strictly farther than before, which is what makes the
// minimum distance non-decreasing in the arithmetic that pds analyze uses
// (every new pair is at least the moved point's new nearest distance, above
// its old one, which was at least the old minimum).
//
// Complexity: a move is a removal and an insertion (expected O(1) each on
// well-spread points) and a scan of ~40 faces; a sweep is O(N). Memory: the
// triangulation, about 200 bytes a point.
// Limits: 2D; tori with equal periods.

#include "pds/samplers/fpo.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/Hilbert_sort_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Periodic_2_Delaunay_triangulation_traits_2<Kernel>;
using PeriodicVertexBase =
    CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Traits, CGAL::Periodic_2_triangulation_vertex_base_2<Traits>>;
using PeriodicTds =
    CGAL::Triangulation_data_structure_2<PeriodicVertexBase, CGAL::Periodic_2_triangulation_face_base_2<Traits>>;
using PeriodicDelaunay = CGAL::Periodic_2_Delaunay_triangulation_2<Traits, PeriodicTds>;
using BoxTds = CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>>;
using BoxDelaunay = CGAL::Delaunay_triangulation_2<Kernel, BoxTds>;

// The circumcentre of a triangle relative to its first vertex, from the
// other two vertices' offsets (e0, e1) from it; false for a flat triangle.
bool circumcentre_offset(double e0x, double e0y, double e1x, double e1y, double& x, double& y) {
  const double a2 = e0x * e0x + e0y * e0y, b2 = e1x * e1x + e1y * e1y;
  const double den = 2.0 * (e0x * e1y - e0y * e1x);
  if (den == 0.0) return false;
  x = (e1y * a2 - e0y * b2) / den;
  y = (e0x * b2 - e1x * a2) / den;
  return true;
}

// The points, their vertices and the sweeps, for either triangulation:
// Derived (the torus or the box) supplies neighbours_of(), which lists a
// vertex's Delaunay neighbours, and best_centre(), which finds the farthest
// point near a removed point's former neighbours.
template <class Derived, class Triangulation>
class Optimizer {
 public:
  using Vertex = typename Triangulation::Vertex_handle;
  using Face = typename Triangulation::Face_handle;

  /// One sweep: every point once, along a Hilbert curve of the start.
  /// Returns how many moved.
  /// Reports `done` plus the points visited so far in this sweep.
  std::size_t sweep(ProgressReporter& progress, double done) {
    std::size_t moved = 0;
    std::vector<std::uint32_t> neighbours;
    const auto n = static_cast<std::uint32_t>(points_.size());
    for (std::uint32_t k = 0; k < n; ++k) {
      progress.update(done + static_cast<double>(k));
      moved += move(k, neighbours);
    }
    return moved;
  }

  /// Minimum and mean nearest-neighbour distance of the current set.
  FpoSweep measure() {
    FpoSweep s;
    double min2 = std::numeric_limits<double>::infinity(), sum = 0.0;
    std::vector<std::uint32_t> neighbours;
    for (std::uint32_t i = 0; i < points_.size(); ++i) {
      const double nn2 = nearest2(i, neighbours);
      min2 = std::min(min2, nn2);
      sum += std::sqrt(nn2);
    }
    s.min_distance = std::sqrt(min2);
    s.mean_nn_distance = sum / static_cast<double>(points_.size());
    return s;
  }

  std::size_t size() const { return points_.size(); }

  /// The points in the caller's order.
  PointSet<2> points() const {
    PointSet<2> out(points_.size());
    for (std::size_t k = 0; k < points_.size(); ++k) out[caller_index_[k]] = points_[k];
    return out;
  }

 protected:
  /// Where a removed point may go: `centre` (in the domain), its squared
  /// distance to the points that define it (`near`, up to three), and a face
  /// to start the insertion from.
  struct Centre {
    Point<2> centre{};
    double r2 = -1;
    std::array<std::uint32_t, 3> near{};
    int near_count = 0;
    Face hint;
  };

  Optimizer(const PointSet<2>& start, const Domain<2>& domain, Triangulation dt)
      : domain_(domain), points_(start), dt_(std::move(dt)) {
    handles_.resize(points_.size());
    // Inserted in CGAL's spatial order (a fixed shuffle, then Hilbert curves
    // over growing prefixes), each location starts next to the last
    // insertion. In index order (random places) every location would walk
    // across the triangulation, O(sqrt N) faces each; along one Hilbert
    // curve the periodic triangulation would stay in its 9-sheeted cover
    // until the last points spread over the torus.
    //
    // Sweeps visit the points along one Hilbert curve of the start: points
    // move little, so a point's triangulation is mostly still in cache from
    // its predecessor's move. With the insertion order (the triangulation's
    // records then lie in memory roughly in the order of space), a sweep at
    // 10^5 points went from 0.9 to 0.2 s. The points are renumbered along
    // that curve, so that a neighbour's coordinates are near in memory too.
    //
    // Both sorts split at medians down to single points (threshold 1), by a
    // strict order (IndexOrder): so the orders do not depend on how the
    // standard library's nth_element arranges ties or small groups.
    const IndexOrder by_location{&points_};
    caller_index_.resize(points_.size());
    std::iota(caller_index_.begin(), caller_index_.end(), 0u);
    std::vector<std::uint32_t> order = caller_index_;
    CGAL::spatial_sort(order.begin(), order.end(), by_location, CGAL::Hilbert_sort_median_policy(),
                       /*threshold_hilbert=*/1);
    const CGAL::Hilbert_sort_2<IndexOrder, CGAL::Hilbert_sort_median_policy> along_one_curve(by_location, 1);
    along_one_curve(caller_index_.begin(), caller_index_.end());
    std::vector<std::uint32_t> own_index(points_.size());
    for (std::uint32_t k = 0; k < caller_index_.size(); ++k) {
      own_index[caller_index_[k]] = k;
      points_[k] = start[caller_index_[k]];
    }
    Face hint;
    for (std::uint32_t i : order) hint = insert(own_index[i], hint)->face();
  }

  // The traits CGAL's spatial sorts ask for, on point indices: a coordinate,
  // then the index, so that no two points compare equal.
  struct IndexOrder {
    using Point_2 = std::uint32_t;
    struct Less {
      const PointSet<2>* points;
      int axis;
      bool operator()(std::uint32_t a, std::uint32_t b) const {
        const double pa = (*points)[a][axis], pb = (*points)[b][axis];
        return pa < pb || (pa == pb && a < b);
      }
    };
    using Less_x_2 = Less;
    using Less_y_2 = Less;
    Less less_x_2_object() const { return {points, 0}; }
    Less less_y_2_object() const { return {points, 1}; }
    const PointSet<2>* points;
  };

  static typename Triangulation::Point to_cgal(const Point<2>& p) { return {p[0], p[1]}; }

  // Squared distance from point i to its nearest other point: the nearest
  // point is a Delaunay neighbour.
  double nearest2(std::uint32_t i, std::vector<std::uint32_t>& neighbours) const {
    self().neighbours_of(i, neighbours);
    double best = std::numeric_limits<double>::infinity();
    for (std::uint32_t j : neighbours)
      if (j != i) best = std::min(best, domain_.distance2(points_[i], points_[j]));
    return best;
  }

  Vertex insert(std::uint32_t i, Face hint) {
    const Vertex v = hint == Face() ? dt_.insert(to_cgal(points_[i])) : dt_.insert(to_cgal(points_[i]), hint);
    v->info() = i;
    handles_[i] = v;
    return v;
  }

  bool move(std::uint32_t i, std::vector<std::uint32_t>& neighbours) {
    const double old2 = nearest2(i, neighbours);
    const Point<2> old = points_[i];
    dt_.remove(handles_[i]);
    const Centre best = self().best_centre(i, neighbours);
    if (best.r2 > old2 && domain_.contains(best.centre)) {
      // Nearest of the defining points from the centre, in the arithmetic of
      // the acceptance test.
      double near2 = std::numeric_limits<double>::infinity();
      for (int k = 0; k < best.near_count; ++k)
        near2 = std::min(near2, domain_.distance2(best.centre, points_[best.near[k]]));
      if (near2 > old2) {
        points_[i] = best.centre;
        insert(i, best.hint);
        // Rounding in the centre can put another point a hair nearer than
        // the defining ones: keep the move only if it really gained.
        if (nearest2(i, neighbours) > old2) return true;
        dt_.remove(handles_[i]);
        points_[i] = old;
        insert(i, Face());
        return false;
      }
    }
    insert(i, best.hint);
    return false;
  }

  const Derived& self() const { return static_cast<const Derived&>(*this); }
  Derived& self() { return static_cast<Derived&>(*this); }

  Domain<2> domain_;
  PointSet<2> points_;
  Triangulation dt_;
  std::vector<Vertex> handles_;
  // caller_index_[k]: the caller's index of our point k (points are
  // numbered along the sweep's Hilbert curve).
  std::vector<std::uint32_t> caller_index_;
};

// The square torus: CGAL's periodic triangulation, each point stored once.
class TorusOptimizer : public Optimizer<TorusOptimizer, PeriodicDelaunay> {
  using Base = Optimizer<TorusOptimizer, PeriodicDelaunay>;
  friend Base;

 public:
  TorusOptimizer(const PointSet<2>& start, const Domain<2>& domain)
      : Base(start, domain,
             PeriodicDelaunay(PeriodicDelaunay::Iso_rectangle(domain.lo[0], domain.lo[1], domain.hi[0], domain.hi[1]))),
        period_(domain.extent(0)) {}

 private:
  void neighbours_of(std::uint32_t i, std::vector<std::uint32_t>& out) const {
    out.clear();
    auto n = dt_.adjacent_vertices(handles_[i]), done = n;
    do out.push_back(dt_.get_original_vertex(n)->info());
    while (++n != done);
  }

  // The faces already looked at in one search: a face of the hole is a face
  // of three neighbours, one of the ring of two, so a third of the faces and
  // more came twice or three times (the same arithmetic each time: skipping
  // them changes no result). A small open-addressed set of face addresses,
  // made for each search; past kMostFaces faces (a point of very high degree)
  // it stops recording and faces are looked at again, as before.
  class SeenFaces {
   public:
    /// False the first time f is offered, true after (while recording).
    bool seen(Face f) {
      const auto key = reinterpret_cast<std::uintptr_t>(&*f);
      std::size_t slot = (key >> 6) & (kSlots - 1);
      for (; slots_[slot] != 0; slot = (slot + 1) & (kSlots - 1))
        if (slots_[slot] == key) return true;
      if (used_ < kMostFaces) {
        slots_[slot] = key;
        ++used_;
      }
      return false;
    }

   private:
    static constexpr std::size_t kSlots = 128, kMostFaces = kSlots / 2;  // a hole's faces are about 20
    std::array<std::uintptr_t, kSlots> slots_{};
    std::size_t used_ = 0;
  };

  // The largest circumcircle among the faces around the former neighbours,
  // its centre computed relative to the face's vertex 0 from the faces'
  // periodic offsets, then wrapped into the domain.
  Centre best_centre(std::uint32_t i, const std::vector<std::uint32_t>& neighbours) const {
    Centre best;
    SeenFaces faces;
    for (std::uint32_t j : neighbours) {
      if (j == i) continue;  // a periodic copy of x itself, on a sparse torus
      auto f = dt_.incident_faces(handles_[j]), done = f;
      do {
        if (faces.seen(f)) continue;
        const auto [p0, o0] = dt_.periodic_point(f, 0);
        double e[2][2];
        for (int s = 1; s <= 2; ++s) {
          const auto [q, o] = dt_.periodic_point(f, s);
          const auto d = o - o0;
          e[s - 1][0] = q.x() + d.x() * period_ - p0.x();
          e[s - 1][1] = q.y() + d.y() * period_ - p0.y();
        }
        double x, y;
        if (circumcentre_offset(e[0][0], e[0][1], e[1][0], e[1][1], x, y)) {
          if (x * x + y * y > best.r2) {
            best.r2 = x * x + y * y;
            best.centre = {p0.x() + x, p0.y() + y};
            best.hint = f;
            for (int k = 0; k < 3; ++k) best.near[k] = dt_.get_original_vertex(f->vertex(k))->info();
            best.near_count = 3;
          }
        }
      } while (++f != done);
    }
    if (best.r2 >= 0) best.centre = domain_.wrap(best.centre);
    return best;
  }

  double period_;
};

// A box: CGAL's Delaunay triangulation of the plane, whose Voronoi cells the
// box clips. The farthest point of the box from a set is a Voronoi vertex
// inside it, a point where a Voronoi edge meets a side, or a corner; the
// local search takes all three around the former neighbours. A side or
// corner point x belongs to the Voronoi cell of neighbour j when no Delaunay
// neighbour of j is nearer to x than j (a cell is bounded by its Delaunay
// neighbours' bisectors).
class BoxOptimizer : public Optimizer<BoxOptimizer, BoxDelaunay> {
  using Base = Optimizer<BoxOptimizer, BoxDelaunay>;
  friend Base;

 public:
  BoxOptimizer(const PointSet<2>& start, const Domain<2>& domain) : Base(start, domain, BoxDelaunay()) {}

 private:
  void neighbours_of(std::uint32_t i, std::vector<std::uint32_t>& out) const {
    out.clear();
    if (dt_.dimension() < 1) return;  // the only point
    // In dimension 1 (every point on one line) the circulator visits the
    // point's neighbours along the line.
    auto n = dt_.incident_vertices(handles_[i]), done = n;
    do
      if (!dt_.is_infinite(n)) out.push_back(n->info());
    while (++n != done);
  }

  // Squared distance from x to point j if x lies in j's Voronoi cell (no
  // point of `around`, j's Delaunay neighbours, is nearer, up to rounding:
  // x may lie on the bisector of j and one of them), else -1.
  double in_cell2(const Point<2>& x, std::uint32_t j, const std::vector<std::uint32_t>& around) const {
    const double own = domain_.distance2(x, points_[j]);
    for (std::uint32_t m : around)
      if (domain_.distance2(x, points_[m]) < own * (1.0 - 1e-12)) return -1;
    return own;
  }

  void consider(Centre& best, const Point<2>& x, double r2, std::uint32_t j, int k, Face hint) const {
    if (!(r2 > best.r2)) return;
    best.r2 = r2;
    best.centre = x;
    // A side of the box at hi is outside [lo, hi): the largest double below it.
    for (int a = 0; a < 2; ++a)
      if (best.centre[a] >= domain_.hi[a]) best.centre[a] = std::nextafter(domain_.hi[a], domain_.lo[a]);
    best.near = {j, static_cast<std::uint32_t>(k < 0 ? j : k), j};
    best.near_count = k < 0 ? 1 : 2;
    best.hint = hint;
  }

  Centre best_centre(std::uint32_t i, const std::vector<std::uint32_t>& neighbours) {
    Centre best;
    const Point<2> corners[4] = {{domain_.lo[0], domain_.lo[1]},
                                 {domain_.hi[0], domain_.lo[1]},
                                 {domain_.lo[0], domain_.hi[1]},
                                 {domain_.hi[0], domain_.hi[1]}};
    if (dt_.dimension() < 2) {
      // The rest lie on one line (a start on a line, or two points): the
      // farthest corner from all of them, found by a scan.
      for (const Point<2>& c : corners) {
        double near2 = std::numeric_limits<double>::infinity();
        for (std::uint32_t j = 0; j < points_.size(); ++j)
          if (j != i) near2 = std::min(near2, domain_.distance2(c, points_[j]));
        if (near2 > best.r2) {
          consider(best, c, near2, i, -1, Face());
          best.near_count = 0;  // the scan above was the check
        }
      }
      return best;
    }
    std::vector<std::uint32_t> around;
    for (std::uint32_t j : neighbours) {
      const Vertex v = handles_[j];
      // Voronoi vertices: circumcentres of the finite faces, inside the box
      // (a face's circumcircle is empty, so its radius is the distance).
      // A bounded cell (no infinite face around j) whose vertices all lie in
      // the box lies in the box (it is convex): no side or corner can be
      // farther from j than its farthest vertex, so the scan of the sides
      // below is skipped. Most cells are such.
      bool cell_in_box = true;
      auto f = dt_.incident_faces(v), done = f;
      do {
        if (dt_.is_infinite(f)) {
          cell_in_box = false;
          continue;
        }
        const Point<2> p0 = points_[f->vertex(0)->info()];
        const Point<2> q1 = points_[f->vertex(1)->info()], q2 = points_[f->vertex(2)->info()];
        double x, y;
        if (!circumcentre_offset(q1[0] - p0[0], q1[1] - p0[1], q2[0] - p0[0], q2[1] - p0[1], x, y)) {
          cell_in_box = false;
          continue;
        }
        const Point<2> c{p0[0] + x, p0[1] + y};
        const bool inside =
            c[0] >= domain_.lo[0] && c[0] <= domain_.hi[0] && c[1] >= domain_.lo[1] && c[1] <= domain_.hi[1];
        cell_in_box = cell_in_box && inside;
        if (x * x + y * y > best.r2 && inside) {
          consider(best, c, x * x + y * y, f->vertex(0)->info(), static_cast<int>(f->vertex(1)->info()), f);
          best.near[2] = f->vertex(2)->info();
          best.near_count = 3;
        }
      } while (++f != done);
      if (cell_in_box) continue;
      // Voronoi edges meeting a side: the point of the side equidistant from
      // j and a neighbour k, if it lies in j's cell; and the corners in j's cell.
      neighbours_of(j, around);
      const Point<2>& pj = points_[j];
      for (std::uint32_t k : around) {
        const Point<2>& pk = points_[k];
        const double mid[2] = {0.5 * (pj[0] + pk[0]), 0.5 * (pj[1] + pk[1])};
        const double d[2] = {pk[0] - pj[0], pk[1] - pj[1]};
        for (int a = 0; a < 2; ++a) {
          const int b = 1 - a;
          if (d[b] == 0.0) continue;  // the bisector runs along this side
          for (const double side : {domain_.lo[a], domain_.hi[a]}) {
            Point<2> x;
            x[a] = side;
            x[b] = mid[b] - d[a] * (side - mid[a]) / d[b];
            if (!(x[b] >= domain_.lo[b] && x[b] <= domain_.hi[b])) continue;
            if (domain_.distance2(x, pj) <= best.r2) continue;
            const double r2 = in_cell2(x, j, around);
            if (r2 > best.r2) consider(best, x, r2, j, static_cast<int>(k), v->face());
          }
        }
      }
      for (const Point<2>& c : corners) {
        if (domain_.distance2(c, pj) <= best.r2) continue;
        const double r2 = in_cell2(c, j, around);
        if (r2 > best.r2) consider(best, c, r2, j, -1, v->face());
      }
    }
    return best;
  }
};

void validate(const PointSet<2>& start, const Domain<2>& domain, const FpoParams& params) {
  domain.validate();
  if (domain.periodic && domain.extent(0) != domain.extent(1))
    throw InvalidArgument("fpo: the torus must be square (CGAL's periodic triangulation), got periods " +
                          detail::format_number(domain.extent(0)) + " and " + detail::format_number(domain.extent(1)));
  if (params.sweeps < 1) throw InvalidArgument("fpo: sweeps must be at least 1, got " + std::to_string(params.sweeps));
  if (!(params.tolerance >= 0.0) || !std::isfinite(params.tolerance))
    throw InvalidArgument("fpo: tolerance must be non-negative and finite, got " +
                          detail::format_number(params.tolerance));
  if (start.size() < 2) throw InvalidArgument("fpo: needs at least 2 points, got " + std::to_string(start.size()));
  if (start.size() > std::numeric_limits<std::uint32_t>::max() / 2)
    throw InvalidArgument("fpo: too many points (" + std::to_string(start.size()) + ")");
  for (const Point<2>& p : start)
    if (!domain.contains(p)) {
      std::ostringstream os;
      os << "fpo: point " << p << " lies outside " << domain;
      throw InvalidArgument(os.str());
    }
  PointSet<2> sorted = start;
  std::sort(sorted.begin(), sorted.end());
  const auto same = std::adjacent_find(sorted.begin(), sorted.end());
  if (same != sorted.end()) {
    std::ostringstream os;
    os << "fpo: the point " << *same << " appears twice";
    throw InvalidArgument(os.str());
  }
}

// The sweeps and the stop rule, on either optimizer (by reference: the
// vertex handles point into its triangulation).
template <class Sweeper>
FpoResult optimize(Sweeper& optimizer, const FpoParams& params) {
  FpoResult result;
  result.sweeps.push_back(optimizer.measure());
  // Point visits out of the sweep budget: a run that converges early ends
  // with a jump to the total.
  const auto n = static_cast<double>(optimizer.size());
  ProgressReporter progress(params.progress, n * params.sweeps);
  for (int s = 0; s < params.sweeps; ++s) {
    const std::size_t moved = optimizer.sweep(progress, n * s);
    FpoSweep now = optimizer.measure();
    now.moved = moved;
    const FpoSweep before = result.sweeps.back();
    result.sweeps.push_back(now);
    // A stall is a sweep that grows neither the minimum nor the mean: the
    // minimum alone can stand still for a sweep long before the end (a start
    // of boundary sampling thinned by elimination kept its closest pair
    // through the first sweep while the mean grew, then gained 0.04 in rho).
    const double grow = 1.0 + params.tolerance;
    if (moved == 0 || !(now.min_distance > before.min_distance * grow ||
                        now.mean_nn_distance > before.mean_nn_distance * grow))
      break;
  }
  progress.finish();
  result.points = optimizer.points();
  return result;
}

}  // namespace

FpoResult fpo_optimize(const PointSet<2>& start, const Domain<2>& domain, const FpoParams& params) {
  validate(start, domain, params);
  if (domain.periodic) {
    TorusOptimizer torus(start, domain);
    return optimize(torus, params);
  }
  BoxOptimizer box(start, domain);
  return optimize(box, params);
}

FpoResult fpo(std::uint64_t count, const Domain<2>& domain, const FpoParams& params, std::uint64_t seed) {
  domain.validate();
  if (count < 2) throw InvalidArgument("fpo: needs at least 2 points, got " + std::to_string(count));
  Rng rng(seed);
  PointSet<2> start(count);
  for (Point<2>& p : start) p = uniform_point(rng, domain);
  return fpo_optimize(start, domain, params);
}

}  // namespace pds
