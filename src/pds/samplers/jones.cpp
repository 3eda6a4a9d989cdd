// T. R. Jones, "Efficient generation of Poisson-disk sampling patterns",
// journal of graphics tools 11(2), 27-36, 2006.
//
// Method, as in the paper: keep the Voronoi diagram of the samples. The part
// of a sample's Voronoi cell outside its disk of radius r is exactly the area
// of that cell where a new sample may go (every point of the cell is nearest
// to its site). Choose a cell with probability proportional to that available
// area (a binary sum tree over the cells, O(log N)), draw a point uniformly in
// the available part of the cell, insert it, and update the cells of its
// Delaunay neighbours; stop when no area is left. Each sample is therefore
// uniform over the whole uncovered area: the process is maximal dart
// throwing, with no wasted darts in covered regions.
//
// Our realisation. A CGAL Delaunay triangulation (exact predicates) holds the
// samples; a cell's polygon is the circumcentres of its incident faces in
// order. Box: a Delaunay_triangulation_2 with four far frame points that keep
// every cell bounded, and cells are clipped to the box. Square torus:
// Periodic_2_Delaunay_triangulation_2, each sample stored once, the cell
// built in the frame of its site from the faces' periodic offsets. Torus with
// unequal periods (CGAL's periodic triangulation takes squares only): each
// sample goes into the plane triangulation with its 8 periodic copies (3x3
// tiles), and the cell of the central copy is the cell on the torus. The
// available part of a convex cell is split at the chords where its boundary
// crosses the circle: each outside run of the boundary with its chord bounds
// a convex piece (the available area plus a circular segment), or, with no
// crossing, the whole cell. The sum tree holds the area of these pieces; a
// point drawn uniformly in them is kept when it lies outside the disk (and,
// checked on the stored coordinates, at least r from every sample), which is
// uniform over the available area. A cell counts as covered when all its
// vertices are within r (1 + 1e-10) of its site, so the set is maximal up to
// 1e-10 r.
//
// Complexity: O(log N) per sample for the tree plus expected O(1) for the
// Delaunay insertion (located from the chosen cell's site) and the updates:
// O(N log N). Memory: the triangulation (about 150 bytes a sample; 9 copies per
// sample on an oblong torus).
// Limits: 2D only.
#include "pds/detail/format.h"
#include "pds/samplers/jones.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pds/detail/sum_tree.h"
#include "pds/error.h"
#include "pds/grid.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

struct V2 {
  double x, y;
};
V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.y - b.y}; }
double dot(V2 a, V2 b) { return a.x * b.x + a.y * b.y; }
double cross(V2 a, V2 b) { return a.x * b.y - a.y * b.x; }

/// As a fan from the first vertex: exact enough for slivers far smaller than
/// their distance from the origin.
double area(const std::vector<V2>& poly) {
  double s = 0.0;
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) s += cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
  return 0.5 * s;
}

/// Circumcentre of the triangle (0, a, b), as CGAL's circumcenter_translateC2.
V2 circumcentre(V2 a, V2 b) {
  const double a2 = dot(a, a), b2 = dot(b, b), den = 2.0 * cross(a, b);
  return {(b.y * a2 - a.y * b2) / den, (a.x * b2 - b.x * a2) / den};
}

/// Box, or a torus with unequal periods (CGAL's periodic triangulation needs a
/// square): a plane Delaunay triangulation. On the torus every sample goes in
/// with its 8 periodic copies (3 x 3 tiles) and the cell of the central copy is
/// the cell on the torus.
class PlaneCells {
  using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::int32_t, Kernel>;  // sample, -1: frame
  using Tds = CGAL::Triangulation_data_structure_2<VertexBase, CGAL::Triangulation_face_base_2<Kernel>>;
  using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
  using Vertex = Delaunay::Vertex_handle;

 public:
  static constexpr int kMaxCopies = 9;

  explicit PlaneCells(const Domain<2>& domain) : domain_(domain), copies_(domain.periodic ? 9 : 1) {
    if (!domain_.periodic) {
      // Far frame points: every sample is inside their hull, so its cell is
      // bounded; cells are clipped to the box anyway.
      const double e = 4.0 * std::max(domain_.extent(0), domain_.extent(1));
      for (double x : {domain_.lo[0] - e, domain_.hi[0] + e})
        for (double y : {domain_.lo[1] - e, domain_.hi[1] + e}) dt_.insert(Delaunay::Point(x, y))->info() = -1;
    }
  }

  /// Inserts sample k at q (drawn in the cell of sample `from`, or -1).
  void insert(const Point<2>& q, std::int32_t k, std::int32_t from) {
    for (int c = 0; c < copies_; ++c) {
      double x = q[0], y = q[1];
      if (copies_ > 1) {
        x += (c / 3 - 1) * domain_.extent(0);
        y += (c % 3 - 1) * domain_.extent(1);
      }
      // Located from the same copy of the cell the dart came from: O(1) walk.
      const Vertex hint = from >= 0 ? handles_[static_cast<std::size_t>(from) * copies_ + c] : Vertex();
      const Vertex v =
          hint != Vertex() ? dt_.insert(Delaunay::Point(x, y), hint->face()) : dt_.insert(Delaunay::Point(x, y));
      v->info() = k;
      handles_.push_back(v);
    }
  }

  /// Calls f(j) for every Delaunay neighbour j of sample k (of every copy).
  /// Only once all copies are in: the first sample's copies are collinear (a
  /// 1-dimensional triangulation) until the last ones arrive.
  template <class F>
  void for_each_neighbour(std::int32_t k, F&& f) const {
    for (int c = 0; c < copies_; ++c) {
      const Vertex v = handles_[static_cast<std::size_t>(k) * copies_ + c];
      auto n = dt_.incident_vertices(v), done = n;
      do {
        if (!dt_.is_infinite(n) && n->info() >= 0) f(n->info());
      } while (++n != done);
    }
  }

  /// The Voronoi cell of sample k (unclipped) relative to its site,
  /// counter-clockwise.
  void cell(std::size_t k, std::vector<V2>& poly) const {
    const Vertex v = handles_[k * copies_ + copies_ / 2];
    const auto& p = v->point();
    auto face = dt_.incident_faces(v), done = face;
    do {
      const int i = face->index(v);
      const auto& a = face->vertex((i + 1) % 3)->point();
      const auto& b = face->vertex((i + 2) % 3)->point();
      poly.push_back(circumcentre({a.x() - p.x(), a.y() - p.y()}, {b.x() - p.x(), b.y() - p.y()}));
    } while (++face != done);
  }

  void clear() {
    dt_.clear();
    handles_ = {};
  }

 private:
  const Domain<2>& domain_;
  int copies_;
  Delaunay dt_;
  std::vector<Vertex> handles_;  // copies_ per sample; the central copy in the middle
};

/// Square torus: CGAL's periodic Delaunay triangulation, each sample stored
/// once. While the set is sparse CGAL keeps a 9-sheeted covering itself
/// (virtual copies of every vertex) and turns it into the 1-sheeted one once
/// every edge is shorter than 0.407 periods.
class TorusCells {
  using Traits = CGAL::Periodic_2_Delaunay_triangulation_traits_2<Kernel>;
  using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::int32_t, Traits,
                                                                 CGAL::Periodic_2_triangulation_vertex_base_2<Traits>>;
  using Tds = CGAL::Triangulation_data_structure_2<VertexBase, CGAL::Periodic_2_triangulation_face_base_2<Traits>>;
  using Delaunay = CGAL::Periodic_2_Delaunay_triangulation_2<Traits, Tds>;
  using Vertex = Delaunay::Vertex_handle;

 public:
  static constexpr int kMaxCopies = 1;

  explicit TorusCells(const Domain<2>& domain)
      : period_(domain.extent(0)),
        dt_(Delaunay::Iso_rectangle(domain.lo[0], domain.lo[1], domain.hi[0], domain.hi[1])) {}

  void insert(const Point<2>& q, std::int32_t k, std::int32_t from) {
    // Located from the cell the dart came from: O(1) walk.
    const Delaunay::Point p(q[0], q[1]);
    const Vertex v = from >= 0 ? dt_.insert(p, handles_[static_cast<std::size_t>(from)]->face()) : dt_.insert(p);
    v->info() = k;
    handles_.push_back(v);
  }

  template <class F>
  void for_each_neighbour(std::int32_t k, F&& f) const {
    const Vertex v = handles_[static_cast<std::size_t>(k)];
    // Virtual copies carry no info: map them to their original.
    auto visit = [&](Vertex u) {
      auto n = dt_.adjacent_vertices(u), done = n;
      do f(dt_.get_original_vertex(n)->info());
      while (++n != done);
    };
    visit(v);
    // On the 9-sheeted covering the copies' stars may break ties differently.
    if (!dt_.is_1_cover())
      for (const Vertex c : dt_.periodic_copies(v)) visit(c);
  }

  /// The Voronoi cell of sample k relative to its site: the circumcentres of
  /// its faces, each face's vertices shifted by their offsets relative to the
  /// site's.
  void cell(std::size_t k, std::vector<V2>& poly) const {
    const Vertex v = handles_[k];
    const auto& p = v->point();
    auto face = dt_.incident_faces(v), done = face;
    do {
      const int i = face->index(v);
      const auto o = dt_.periodic_point(face, i).second;  // (the documented form of get_offset)
      V2 e[2];
      for (int s = 1; s <= 2; ++s) {
        const auto [q, offset] = dt_.periodic_point(face, (i + s) % 3);
        const auto d = offset - o;
        e[s - 1] = {q.x() + d.x() * period_ - p.x(), q.y() + d.y() * period_ - p.y()};
      }
      poly.push_back(circumcentre(e[0], e[1]));
    } while (++face != done);
  }

  void clear() {
    dt_.clear();
    handles_ = {};
  }

 private:
  double period_;
  Delaunay dt_;
  std::vector<Vertex> handles_;  // per sample
};

template <class Cells>
class JonesSampler {
 public:
  JonesSampler(const JonesParams& params, const Domain<2>& domain, std::uint64_t seed)
      : domain_(domain),
        r2_(params.radius * params.radius),
        cover2_(r2_ * (1.0 + 2e-10)),
        cells_(domain),
        grid_(Grid<2>::for_radius(domain, params.radius)),
        rng_(seed),
        radius_(params.radius),
        progress_(params.progress) {}

  PointSet<2> run() {
    insert(uniform_point(rng_, domain_), -1);
    // A miss is a dart in the circular segment of a piece or, rarely, one that
    // rounding puts too close to a sample. Pieces are cut where a vertex is at
    // least 1e-10 r outside the disk, so about half of the darts hit; a cell
    // missing this often in a row means the geometry broke down numerically.
    constexpr int kMaxMisses = 10000;
    int empty_picks = 0;
    // Samples against typical_count early on, the share of
    // the area covered late (it reaches all of it as the set completes).
    const double expected = typical_count(domain_.volume(), radius_, 2);
    const double area = tree_.total();
    ProgressReporter progress(progress_, expected);
    while (tree_.total() > 0.0) {
      progress.update(expected * std::max(static_cast<double>(grid_.size()) / expected, 1.0 - tree_.total() / area));
      const std::size_t k = tree_.find(rng_.uniform() * tree_.total());
      if (!(tree_.weight(k) > 0.0)) {
        // Only rounding at a leaf's boundary picks an empty leaf.
        if (++empty_picks > kMaxMisses) throw Failure("jones: the area tree keeps picking empty cells");
        continue;
      }
      empty_picks = 0;
      const auto dart = draw(k);
      if (!dart) {
        if (++misses_[k] > kMaxMisses)
          throw Failure("jones: " + std::to_string(kMaxMisses) + " darts in a row missed the free area of cell " +
                        std::to_string(k) + " (radius " + detail::format_number(radius_) + ")");
        continue;
      }
      insert(*dart, static_cast<std::int32_t>(k));
    }
    progress.finish();
    // The grid holds the only copy of the points; free the triangulation first.
    cells_.clear();
    return std::move(grid_).take_points();
  }

 private:
  V2 site(std::size_t k) const {
    const Point<2>& p = grid_.points()[k];
    return {p[0], p[1]};
  }

  /// The Voronoi cell of sample k (clipped to the box) relative to its site,
  /// counter-clockwise. Relative coordinates keep the precision of small
  /// pieces however far the domain lies from the origin.
  std::vector<V2> cell(std::size_t k) const {
    std::vector<V2> poly;
    cells_.cell(k, poly);
    if (!domain_.periodic) {
      const V2 p = site(k);
      clip(poly, 0, domain_.lo[0] - p.x, +1.0);
      clip(poly, 0, domain_.hi[0] - p.x, -1.0);
      clip(poly, 1, domain_.lo[1] - p.y, +1.0);
      clip(poly, 1, domain_.hi[1] - p.y, -1.0);
    }
    return poly;
  }
  /// Keeps the part of a convex polygon with sign * (coord - bound) >= 0.
  static void clip(std::vector<V2>& poly, int axis, double bound, double sign) {
    std::vector<V2> out;
    const std::size_t n = poly.size();
    auto value = [&](const V2& p) { return sign * ((axis == 0 ? p.x : p.y) - bound); };
    for (std::size_t i = 0; i < n; ++i) {
      const V2 a = poly[i], b = poly[(i + 1) % n];
      const double va = value(a), vb = value(b);
      if (va >= 0.0) out.push_back(a);
      if ((va >= 0.0) != (vb >= 0.0)) {
        const double t = va / (va - vb);
        V2 c{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        // The crossing lies on the bound exactly.
        (axis == 0 ? c.x : c.y) = bound;
        out.push_back(c);
      }
    }
    poly = std::move(out);
  }

  /// Convex pieces that together contain the part of the cell outside the
  /// disk of sample k (see the file comment), relative to its site.
  std::vector<std::vector<V2>> pieces(std::size_t k) const {
    const std::vector<V2> poly = cell(k);
    std::vector<std::vector<V2>> result;
    const std::size_t n = poly.size();
    if (n < 3) return result;
    bool all_covered = true;
    for (const V2& v : poly) all_covered = all_covered && dot(v, v) <= cover2_;
    if (all_covered) return result;

    // The boundary as a ring of vertices and circle crossings.
    enum Kind { kOutside, kInside, kEnter, kExit };
    struct Event {
      V2 at;
      Kind kind;
    };
    std::vector<Event> ring;
    bool any_crossing = false;
    for (std::size_t i = 0; i < n; ++i) {
      const V2 a = poly[i], b = poly[(i + 1) % n];
      const V2 ab = b - a;
      const double A = dot(ab, ab), B = dot(a, ab), C = dot(a, a) - r2_;
      const bool a_in = C <= 0.0, b_in = dot(b, b) - r2_ <= 0.0;
      ring.push_back({a, a_in ? kInside : kOutside});
      if (!(A > 0.0)) continue;
      const double disc = std::max(0.0, B * B - A * C);
      const double t1 = std::clamp((-B - std::sqrt(disc)) / A, 0.0, 1.0);
      const double t2 = std::clamp((-B + std::sqrt(disc)) / A, 0.0, 1.0);
      auto at = [&](double t) { return V2{a.x + t * ab.x, a.y + t * ab.y}; };
      if (a_in && !b_in) {
        ring.push_back({at(t2), kExit});
      } else if (!a_in && b_in) {
        ring.push_back({at(t1), kEnter});
      } else if (!a_in && !b_in && B * B - A * C > 0.0 && t1 > 0.0 && t2 < 1.0) {
        ring.push_back({at(t1), kEnter});
        ring.push_back({at(t2), kExit});
      } else {
        continue;
      }
      any_crossing = true;
    }
    if (!any_crossing) {
      // The disk lies inside the cell (or the whole cell inside the disk).
      if (ring.front().kind == kOutside) result.push_back(poly);
      return result;
    }
    // Each run of the boundary from an exit to the next entry, closed by its
    // chord, is a convex piece.
    const std::size_t m = ring.size();
    for (std::size_t i = 0; i < m; ++i) {
      if (ring[i].kind != kExit) continue;
      std::vector<V2> piece{ring[i].at};
      for (std::size_t j = (i + 1) % m; j != i; j = (j + 1) % m) {
        piece.push_back(ring[j].at);
        if (ring[j].kind == kEnter) break;
      }
      if (piece.size() >= 3 && area(piece) > 0.0) result.push_back(std::move(piece));
    }
    return result;
  }

  double weight(std::size_t k) const {
    double w = 0.0;
    for (const auto& piece : pieces(k)) w += area(piece);
    return w;
  }

  /// One dart in the pieces of cell k; the sample if it is available.
  std::optional<Point<2>> draw(std::size_t k) {
    const auto parts = pieces(k);
    if (parts.empty()) return std::nullopt;
    double total = 0.0;
    for (const auto& piece : parts) total += area(piece);
    double u = rng_.uniform() * total;
    const std::vector<V2>* chosen = &parts.back();
    for (const auto& piece : parts) {
      const double a = area(piece);
      if (u < a) {
        chosen = &piece;
        break;
      }
      u -= a;
    }
    // A triangle of the piece's fan by area, then a uniform point in it.
    const auto& poly = *chosen;
    double fan = 0.0;
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) fan += 0.5 * cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
    double v = rng_.uniform() * fan;
    std::size_t t = poly.size() - 2;
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
      const double a = 0.5 * cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
      if (v < a) {
        t = i;
        break;
      }
      v -= a;
    }
    double s = rng_.uniform(), w = rng_.uniform();
    if (s + w > 1.0) s = 1.0 - s, w = 1.0 - w;
    const V2 e1 = poly[t] - poly[0], e2 = poly[t + 1] - poly[0];
    const V2 x{poly[0].x + s * e1.x + w * e2.x, poly[0].y + s * e1.y + w * e2.y};
    if (dot(x, x) < r2_) return std::nullopt;
    const V2 p = site(k);
    const Point<2> q = domain_.wrap(Point<2>{{p.x + x.x, p.y + x.y}});
    if (!domain_.contains(q) || grid_.any_closer_than(q, radius_)) return std::nullopt;
    return q;
  }

  /// Adds sample q (drawn in the cell of sample `from`, or -1) and updates the
  /// available areas of every cell it changed.
  void insert(const Point<2>& q, std::int32_t from) {
    const auto k = static_cast<std::int32_t>(grid_.size());
    if (grid_.size() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() / Cells::kMaxCopies))
      throw InvalidArgument("jones: too many samples");
    grid_.insert(q);
    misses_.push_back(0);
    cells_.insert(q, k, from);
    changed_.clear();
    changed_.push_back(k);
    cells_.for_each_neighbour(k, [&](std::int32_t j) { changed_.push_back(j); });
    std::sort(changed_.begin(), changed_.end());
    changed_.erase(std::unique(changed_.begin(), changed_.end()), changed_.end());
    for (const std::int32_t j : changed_) {
      const auto js = static_cast<std::size_t>(j);
      tree_.set(js, weight(js));
      misses_[js] = 0;
    }
  }

  const Domain<2>& domain_;
  double r2_, cover2_;
  Cells cells_;
  Grid<2> grid_;  // the points; exact distance check on the stored coordinates
  Rng rng_;
  double radius_;
  Progress progress_;
  detail::SumTree tree_;
  std::vector<std::uint16_t> misses_;
  std::vector<std::int32_t> changed_;
};

}  // namespace

PointSet<2> jones(const JonesParams& params, const Domain<2>& domain, std::uint64_t seed) {
  domain.validate();
  require_radius_budget(domain, params.radius, params.max_points);
  if (domain.periodic)
    for (int i = 0; i < 2; ++i)
      if (domain.extent(i) < 4.0 * params.radius)
        throw InvalidArgument("jones: on a torus every period must be at least 4 radius; axis " + std::to_string(i) +
                              " has " + detail::format_number(domain.extent(i)) + " for radius " +
                              detail::format_number(params.radius));
  if (domain.periodic && domain.extent(0) == domain.extent(1))
    return JonesSampler<TorusCells>(params, domain, seed).run();
  return JonesSampler<PlaneCells>(params, domain, seed).run();
}

}  // namespace pds
