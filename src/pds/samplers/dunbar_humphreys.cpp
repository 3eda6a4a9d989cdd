// D. Dunbar and G. Humphreys, "A spatial data structure for fast Poisson-disk
// sample generation", ACM SIGGRAPH 2006 (ACM TOG 25(3), 503-508).
//
// Method (the paper's boundary sampling). A sample's "available boundary" is
// the part of the circle of radius r around it that lies outside the disks of
// radius r of all other samples (and inside the domain). The paper keeps the
// available neighbourhood of a sample as scalloped sectors; restricted to the
// circle, that region is a set of angular intervals, which is what we store.
// Front samples are taken in insertion order (breadth first, which keeps
// memory access local; the guarantees do not depend on the order). A front
// sample's available arcs are computed from the samples within 2r (a sample at
// distance d blocks the arc of half-angle acos(d / 2r) around its direction);
// then points are drawn uniformly on the remaining arcs, each new sample blocking +-60 degrees around itself, until no
// arc remains. The new samples join the front; the sample leaves it.
//
// Guarantees. Every new sample is at distance >= r from every other (checked
// on the stored coordinates before it is accepted). Maximal: if some region
// were uncovered, its boundary would contain an arc of some sample's circle
// that no disk covers, and that sample would still be on the front. The
// circle radius is r(1 + 1e-10) so that rounding can never put two samples
// closer than r; hence every point is within r(1 + 1e-10) of a sample.
//
// Complexity. Each sample is processed once with a constant number of
// neighbours: O(N) time. Memory: the output, one int32 per grid cell (about
// 2.4 per sample) and each sample's parent and angle (12 bytes); the front is
// the unprocessed tail of the output. The arcs blocked by a sample's parent
// and siblings follow from their angles on the parent's circle, which saves
// the atan2 and acos for those neighbours.
//
// Limits. 2D only (the paper is 2D). Boundary sampling is not the unbiased
// process: samples sit exactly at distance r from their parent, so the set is
// denser and more regular than dart throwing (measured in
// docs/dunbar-humphreys.md). The paper's scalloped-sector variant, which
// samples the full annulus r..2r, is not implemented.
#include "pds/samplers/dunbar_humphreys.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "pds/error.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// The free part of a circle: disjoint angular intervals in [0, 2 pi).
class Arcs {
 public:
  void reset() {
    arcs_.clear();
    arcs_.push_back({0.0, kTwoPi});
  }
  bool empty() const { return arcs_.empty(); }

  /// Removes the open interval (lo, hi), hi - lo < 2 pi, lo in [-2 pi, 2 pi).
  void remove(double lo, double hi) {
    if (hi <= 0.0) {
      lo += kTwoPi;
      hi += kTwoPi;
    } else if (lo >= kTwoPi) {
      lo -= kTwoPi;
      hi -= kTwoPi;
    }
    if (lo < 0.0) {
      remove_normalized(lo + kTwoPi, kTwoPi);
      remove_normalized(0.0, hi);
    } else if (hi > kTwoPi) {
      remove_normalized(lo, kTwoPi);
      remove_normalized(0.0, hi - kTwoPi);
    } else {
      remove_normalized(lo, hi);
    }
  }

  /// An angle uniformly distributed over the free arcs; requires !empty().
  double sample(Rng& rng) const {
    double total = 0.0;
    for (const Arc& a : arcs_) total += a.hi - a.lo;
    double u = rng.uniform() * total;
    for (const Arc& a : arcs_) {
      const double len = a.hi - a.lo;
      if (u < len) return a.lo + u;
      u -= len;
    }
    return arcs_.back().hi - 0.5 * (arcs_.back().hi - arcs_.back().lo);
  }

 private:
  // Arcs shorter than this are dropped: the gap they leave between disks is
  // narrower than 1e-13 radius.
  static constexpr double kMinArc = 1e-13;
  struct Arc {
    double lo, hi;
  };

  void remove_normalized(double lo, double hi) {
    std::size_t out = 0;
    const std::size_t n = arcs_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Arc a = arcs_[i];
      if (hi <= a.lo || lo >= a.hi) {
        arcs_[out++] = a;
        continue;
      }
      const bool left = lo - a.lo > kMinArc, right = a.hi - hi > kMinArc;
      if (left && right) {
        // Split: the right piece goes to the end (order does not matter for
        // sampling, only the multiset of arcs, which is deterministic).
        arcs_[out++] = {a.lo, lo};
        arcs_.push_back({hi, a.hi});
      } else if (left) {
        arcs_[out++] = {a.lo, lo};
      } else if (right) {
        arcs_[out++] = {hi, a.hi};
      }
    }
    // Arcs appended by splits sit after n; move them down.
    for (std::size_t i = n; i < arcs_.size(); ++i) arcs_[out++] = arcs_[i];
    arcs_.resize(out);
  }

  std::vector<Arc> arcs_;
};

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
  int coord(double x, int axis) const {
    const int c = static_cast<int>((x - domain_.lo[axis]) * inv_edge_[axis]);
    return std::clamp(c, 0, n_[axis] - 1);
  }
  std::int32_t& at(int cx, int cy) { return cells_[static_cast<std::size_t>(cy) * n_[0] + cx]; }
  std::int32_t& at(const Point<2>& p) { return at(coord(p[0], 0), coord(p[1], 1)); }

  /// Calls f(index) for every stored sample in the cells within `reach`
  /// cells of p's cell (each cell once, wrapping on a torus).
  template <class F>
  void for_each_near(const Point<2>& p, int reach, F&& f) {
    int first[2], last[2];
    for (int i = 0; i < 2; ++i) {
      const int c = coord(p[i], i);
      first[i] = c - reach;
      last[i] = c + reach;
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
    for (int y = first[1]; y <= last[1]; ++y) {
      const int cy = y < 0 ? y + n_[1] : (y >= n_[1] ? y - n_[1] : y);
      const std::int32_t* row = cells_.data() + static_cast<std::size_t>(cy) * n_[0];
      for (int x = first[0]; x <= last[0]; ++x) {
        const int cx = x < 0 ? x + n_[0] : (x >= n_[0] ? x - n_[0] : x);
        if (row[cx] >= 0) f(row[cx]);
      }
    }
  }

 private:
  Domain<2> domain_;
  int n_[2];
  double inv_edge_[2];
  std::vector<std::int32_t> cells_;
};

}  // namespace

PointSet<2> dunbar_humphreys(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed) {
  domain.validate();
  const double r = params.radius;
  require_radius_budget(domain, r, params.max_points);
  // The circle radius: a hair above r, so that samples placed on it stay at
  // least r apart after rounding (see the file comment).
  const double rc = r * (1.0 + 1e-10);
  if (domain.periodic)
    for (int i = 0; i < 2; ++i)
      if (domain.extent(i) < 4.0 * rc)  // neighbours within 2 rc need one nearest image
        throw InvalidArgument(
            "dunbar-humphreys: on a torus every period must be more than 4 radius (the circles are 1e-10 larger than "
            "the radius); axis " +
            std::to_string(i) + " has " + std::to_string(domain.extent(i)) + " for radius " + std::to_string(r));
  const double r2 = r * r;

  CellGrid grid(domain, r / std::sqrt(2.0));
  // Cells that may hold a sample within 2 rc.
  const int reach =
      static_cast<int>(std::ceil(2.0 * rc * std::max(grid.n(0) / domain.extent(0), grid.n(1) / domain.extent(1))));
  PointSet<2> points;
  // Boundary sampling makes about 0.875 samples per r^2 (rho ~ 0.87); reserving
  // that avoids the doubling that would otherwise set the peak memory.
  points.reserve(static_cast<std::size_t>(0.9 * domain.volume() / r2) + 16);
  // For each sample, the sample it was placed around and the angle it sits at
  // on that sample's circle: the arcs a parent and siblings block then follow
  // from the angles alone, without atan2/acos (measured: 1.2 of the 7.6 neighbours within 2r).
  std::vector<std::int32_t> parent;
  std::vector<double> angle;
  parent.reserve(points.capacity());
  angle.reserve(points.capacity());
  Rng rng(seed);

  auto add = [&](const Point<2>& q, std::int32_t from, double theta) {
    if (points.size() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
      throw InvalidArgument("dunbar-humphreys: more than 2^31 - 1 samples");
    const auto index = static_cast<std::int32_t>(points.size());
    points.push_back(q);
    parent.push_back(from);
    angle.push_back(theta);
    grid.at(q) = index;
    return index;
  };
  add(uniform_point(rng, domain), -1, 0.0);

  Arcs arcs;
  std::vector<std::int32_t> neighbours;  // samples within 2 rc of the front sample, and its new ones
  const double reach2 = 4.0 * rc * rc;
  constexpr double kPi = std::numbers::pi;
  // The front is every sample not yet processed; taking it in insertion order
  // (breadth first) keeps the grid rows and points being touched in cache.
  for (std::size_t head = 0; head < points.size(); ++head) {
    const auto pi = static_cast<std::int32_t>(head);
    const Point<2> p = points[head];
    const std::int32_t pp = parent[head];

    arcs.reset();
    if (!domain.periodic) {
      // A wall at distance w < rc blocks the arc of half-angle acos(w / rc)
      // facing it, as a sample at distance 2w would.
      for (int axis = 0; axis < 2; ++axis) {
        const double facing_lo = axis == 0 ? kPi : 1.5 * kPi;
        const double to_lo = p[axis] - domain.lo[axis], to_hi = domain.hi[axis] - p[axis];
        if (to_lo < rc) {
          const double h = std::acos(to_lo / rc);
          arcs.remove(facing_lo - h, facing_lo + h);
        }
        if (to_hi < rc) {
          const double h = std::acos(to_hi / rc);
          const double facing_hi = facing_lo - kPi;
          arcs.remove(facing_hi - h, facing_hi + h);
        }
      }
    }
    neighbours.clear();
    grid.for_each_near(p, reach, [&](std::int32_t j) {
      if (j == pi) return;
      const Point<2>& s = points[static_cast<std::size_t>(j)];
      const double dx = domain.delta(p[0], s[0], 0), dy = domain.delta(p[1], s[1], 1);
      const double d2 = dx * dx + dy * dy;
      if (d2 >= reach2) return;
      neighbours.push_back(j);
      const auto js = static_cast<std::size_t>(j);
      double c, h;
      if (j == pp) {
        // The parent is at distance rc, opposite the angle p sits at.
        c = angle[head] + kPi;
        h = kPi / 3.0;
      } else if (pp >= 0 && parent[js] == pp) {
        // A sibling: both on the parent's circle, at angles a and b. The chord
        // b - a has length 2 rc |sin(delta/2)| and points at (a + b)/2 + 90
        // degrees (flipped when delta < 0); acos(|sin(delta/2)|) is the half-angle.
        const double delta = angle[js] - angle[head];
        c = 0.5 * (angle[js] + angle[head]) + 0.5 * kPi + (delta < 0.0 ? kPi : 0.0);
        h = std::abs(0.5 * kPi - 0.5 * std::abs(delta));
      } else {
        h = std::acos(std::sqrt(d2) / (2.0 * rc));
        c = std::atan2(dy, dx);
      }
      if (c >= kTwoPi) c -= kTwoPi;
      if (c < 0.0) c += kTwoPi;
      arcs.remove(c - h, c + h);
    });

    int rejected = 0;
    while (!arcs.empty()) {
      const double theta = arcs.sample(rng);
      const double dx = rc * std::cos(theta), dy = rc * std::sin(theta);
      const Point<2> q = domain.wrap(Point<2>{{p[0] + dx, p[1] + dy}});
      bool ok = domain.contains(q) && domain.distance2(p, q) >= r2;
      for (const std::int32_t j : neighbours) {
        if (!ok) break;
        ok = domain.distance2(q, points[static_cast<std::size_t>(j)]) >= r2;
      }
      if (!ok) {
        // Only rounding at an arc's end or at a wall can get here: drop a
        // sliver of the circle around theta. Bounded per front sample.
        if (++rejected > 64)
          throw Failure("dunbar-humphreys: 64 candidates rejected by rounding around one sample (radius " +
                        std::to_string(r) + ")");
        arcs.remove(theta - 1e-12, theta + 1e-12);
        continue;
      }
      const std::int32_t qi = add(q, pi, theta);
      neighbours.push_back(qi);
      // A sample on the circle blocks exactly +-60 degrees of it.
      arcs.remove(theta - kPi / 3.0, theta + kPi / 3.0);
    }
  }
  return points;
}

const Method& dunbar_humphreys_method() {
  static const Method method{
      .name = "dunbar-humphreys",
      .summary = "boundary sampling (Dunbar & Humphreys): maximal Poisson disk set in O(N), 2D, --radius",
      .citation =
          "D. Dunbar, G. Humphreys, A spatial data structure for fast Poisson-disk sample generation, "
          "ACM SIGGRAPH 2006",
      .takes_radius = true,
      .maximal = true,
      .dims = {2},
      .run =
          [](const GenerateRequest& r) {
            const DunbarHumphreysParams params{*r.radius, r.max_points};
            return PointCloud::from<2>(dunbar_humphreys(params, r.domain<2>(), r.seed));
          },
  };
  return method;
}

}  // namespace pds
