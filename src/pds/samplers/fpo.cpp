// T. Schlömer, D. Heck, O. Deussen, Farthest-point optimized point sets with
// maximized minimum distance, High Performance Graphics 2011, 135-142.
//
// Method (the paper's local variant, section 4): the points live in a
// Delaunay triangulation of the torus. A sweep takes each point x in index
// order, removes it, and looks at the faces incident to its former Delaunay
// neighbours: they include the faces that re-triangulate the hole, whose
// circumcentres are the Voronoi vertices of the remaining points around x's
// old place. The centre of the largest of these empty circumcircles is the
// farthest point from the others found near x; x goes there if that is
// farther from its nearest neighbour than its old place was, else it goes
// back. Sweeps repeat until one grows the minimum distance by less than a
// tolerance (the stop rule) or the sweep budget is spent. The paper reports
// relative radius ~0.93 and an isotropic spectrum with a pronounced peak.
//
// Our realisation: CGAL's Periodic_2_Delaunay_triangulation_2 (exact
// predicates, inexact constructions; square tori only), each point stored
// once, its index in the vertex's info. Circumcentres are computed relative
// to one vertex of the face, from the faces' periodic offsets (as in
// samplers/jones.cpp), then wrapped into the domain. The acceptance test and
// every reported distance use Domain::distance2 on the stored coordinates:
// a move is kept only when the moved point's nearest Delaunay neighbour (its
// nearest point) is strictly farther than before, which is what makes the
// minimum distance non-decreasing in the arithmetic that pds analyze uses
// (every new pair is at least the moved point's new nearest distance, above
// its old one, which was at least the old minimum).
//
// Complexity: a move is a removal and an insertion (expected O(1) each on
// well-spread points) and a scan of ~40 faces; a sweep is O(N). Memory: the
// triangulation, about 150 bytes a point.
// Limits: 2D, square tori.

#include "pds/samplers/fpo.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Periodic_2_Delaunay_triangulation_traits_2<Kernel>;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Traits,
                                                               CGAL::Periodic_2_triangulation_vertex_base_2<Traits>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, CGAL::Periodic_2_triangulation_face_base_2<Traits>>;
using Delaunay = CGAL::Periodic_2_Delaunay_triangulation_2<Traits, Tds>;
using Vertex = Delaunay::Vertex_handle;
using Face = Delaunay::Face_handle;

class Optimizer {
 public:
  Optimizer(const PointSet<2>& start, const Domain<2>& domain)
      : domain_(domain),
        period_(domain.extent(0)),
        points_(start),
        dt_(Delaunay::Iso_rectangle(domain.lo[0], domain.lo[1], domain.hi[0], domain.hi[1])) {
    handles_.resize(points_.size());
    Face hint;
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const Vertex v = hint == Face() ? dt_.insert(to_cgal(points_[i])) : dt_.insert(to_cgal(points_[i]), hint);
      v->info() = static_cast<std::uint32_t>(i);
      handles_[i] = v;
      hint = v->face();
    }
  }

  /// One sweep: every point once, in index order. Returns how many moved.
  /// Reports `done` plus the points visited so far in this sweep.
  std::size_t sweep(ProgressReporter& progress, double done) {
    std::size_t moved = 0;
    std::vector<std::uint32_t> neighbours;
    for (std::uint32_t i = 0; i < points_.size(); ++i) {
      progress.update(done + i);
      moved += move(i, neighbours);
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

  const PointSet<2>& points() const { return points_; }

 private:
  static Delaunay::Point to_cgal(const Point<2>& p) { return {p[0], p[1]}; }

  void neighbours_of(std::uint32_t i, std::vector<std::uint32_t>& out) const {
    out.clear();
    auto n = dt_.adjacent_vertices(handles_[i]), done = n;
    do out.push_back(dt_.get_original_vertex(n)->info());
    while (++n != done);
  }

  // Squared distance from point i to its nearest other point: the nearest
  // point is a Delaunay neighbour.
  double nearest2(std::uint32_t i, std::vector<std::uint32_t>& neighbours) const {
    neighbours_of(i, neighbours);
    double best = std::numeric_limits<double>::infinity();
    for (std::uint32_t j : neighbours)
      if (j != i) best = std::min(best, domain_.distance2(points_[i], points_[j]));
    return best;
  }

  Vertex insert(std::uint32_t i, Face hint) {
    const Vertex v = dt_.insert(to_cgal(points_[i]), hint);
    v->info() = i;
    handles_[i] = v;
    return v;
  }

  // The circumcentre of a face relative to its vertex 0, and that vertex.
  struct Circle {
    double x = 0, y = 0, r2 = -1;
    std::uint32_t anchor = 0;
  };
  Circle circumcircle(Face f) const {
    const auto [p0, o0] = dt_.periodic_point(f, 0);
    double e[2][2];
    for (int s = 1; s <= 2; ++s) {
      const auto [q, o] = dt_.periodic_point(f, s);
      const auto d = o - o0;
      e[s - 1][0] = q.x() + d.x() * period_ - p0.x();
      e[s - 1][1] = q.y() + d.y() * period_ - p0.y();
    }
    const double a2 = e[0][0] * e[0][0] + e[0][1] * e[0][1], b2 = e[1][0] * e[1][0] + e[1][1] * e[1][1];
    const double den = 2.0 * (e[0][0] * e[1][1] - e[0][1] * e[1][0]);
    Circle c;
    if (!(den != 0.0)) return c;
    c.x = (e[1][1] * a2 - e[0][1] * b2) / den;
    c.y = (e[0][0] * b2 - e[1][0] * a2) / den;
    c.r2 = c.x * c.x + c.y * c.y;
    c.anchor = dt_.get_original_vertex(f->vertex(0))->info();
    return c;
  }

  bool move(std::uint32_t i, std::vector<std::uint32_t>& neighbours) {
    const double old2 = nearest2(i, neighbours);
    const Point<2> old = points_[i];
    dt_.remove(handles_[i]);
    // The largest circumcircle among the faces around the former neighbours.
    Circle best;
    Face best_face;
    for (std::uint32_t j : neighbours) {
      if (j == i) continue;  // a periodic copy of x itself, on a sparse torus
      auto f = dt_.incident_faces(handles_[j]), done = f;
      do {
        const Circle c = circumcircle(f);
        if (c.r2 > best.r2) {
          best = c;
          best_face = f;
        }
      } while (++f != done);
    }
    if (best.r2 > old2) {
      const Point<2>& a = points_[best.anchor];
      const Point<2> centre = domain_.wrap(Point<2>{a[0] + best.x, a[1] + best.y});
      // Nearest of the face's vertices from the wrapped centre, in the
      // arithmetic of the acceptance test.
      double near2 = std::numeric_limits<double>::infinity();
      for (int k = 0; k < 3; ++k)
        near2 =
            std::min(near2, domain_.distance2(centre, points_[dt_.get_original_vertex(best_face->vertex(k))->info()]));
      if (near2 > old2 && domain_.contains(centre)) {
        points_[i] = centre;
        insert(i, best_face);
        // Rounding in the centre can put another point a hair nearer than
        // the face's vertices: keep the move only if it really gained.
        std::vector<std::uint32_t> around;
        if (nearest2(i, around) > old2) return true;
        dt_.remove(handles_[i]);
        points_[i] = old;
        insert(i, Face());
        return false;
      }
    }
    insert(i, best_face == Face() ? Face() : best_face);
    return false;
  }

  Domain<2> domain_;
  double period_;
  PointSet<2> points_;
  Delaunay dt_;
  std::vector<Vertex> handles_;
};

void validate(const PointSet<2>& start, const Domain<2>& domain, const FpoParams& params) {
  domain.validate();
  if (!domain.periodic)
    throw InvalidArgument("fpo: needs a torus (--torus): the optimization runs on a periodic Delaunay triangulation");
  if (domain.extent(0) != domain.extent(1))
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

}  // namespace

FpoResult fpo_optimize(const PointSet<2>& start, const Domain<2>& domain, const FpoParams& params) {
  validate(start, domain, params);
  Optimizer optimizer(start, domain);
  FpoResult result;
  result.sweeps.push_back(optimizer.measure());
  // Point visits out of the sweep budget: a run that converges early ends
  // with a jump to the total.
  const auto n = static_cast<double>(start.size());
  ProgressReporter progress(params.progress, n * params.sweeps);
  for (int s = 0; s < params.sweeps; ++s) {
    const std::size_t moved = optimizer.sweep(progress, n * s);
    FpoSweep now = optimizer.measure();
    now.moved = moved;
    const double before = result.sweeps.back().min_distance;
    result.sweeps.push_back(now);
    if (moved == 0 || !(now.min_distance > before * (1.0 + params.tolerance))) break;
  }
  progress.finish();
  result.points = optimizer.points();
  return result;
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
