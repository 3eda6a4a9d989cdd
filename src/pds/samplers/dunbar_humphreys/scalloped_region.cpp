// Scalloped regions (D. Dunbar and G. Humphreys, "A spatial data structure for
// fast Poisson-disk sample generation", ACM SIGGRAPH 2006; its scalloped sectors): exact
// areas and sampling by inverse CDF; the declarations say what each does.
//
// A sector's area is the integral of rho(t)^2 / 2 between its two curves,
// in closed form for every curve (Curve::primitive). Removing a disk splits
// each sector at the angles where the disk's circle crosses the sector's
// curves and at the disk's tangent directions, and keeps, between those
// angles, the part below and the part above the disk (the order of the four
// radii is fixed between split angles, so it is read at the middle angle).
#include "scalloped_region.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pds::detail::dh {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Pieces narrower than this are dropped (a sliver under 1e-11 radius wide).
constexpr double kMinAngle = 1e-12;

bool within(double theta, double centre, double half) { return std::abs(Curve::wrap_angle(theta - centre)) < half; }

}  // namespace

Curve Curve::circle(double cx, double cy, double rho, double branch) {
  Curve c;
  c.cx = cx;
  c.cy = cy;
  c.rho = rho;
  c.branch = branch;
  c.d = std::hypot(cx, cy);
  c.phi = c.d > 0.0 ? std::atan2(cy, cx) : 0.0;
  return c;
}

Curve Curve::wall(double h, double psi) {
  Curve c;
  c.line = true;
  c.h = h;
  c.psi = psi;
  return c;
}

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

void ScallopedRegion::reset(double r) {
  curves_.clear();
  sectors_.clear();
  curves_.push_back(Curve::circle(0.0, 0.0, r, 1.0));
  curves_.push_back(Curve::circle(0.0, 0.0, 2.0 * r, 1.0));
  add({0.0, kTwoPi, 0, 1}, sectors_);
}

double ScallopedRegion::area() const {
  double total = 0.0;
  for (const Sector& s : sectors_) total += s.area;
  return total;
}

void ScallopedRegion::remove_disk(double cx, double cy, double r) {
  const double d = std::hypot(cx, cy);
  if (d >= 3.0 * r) return;
  const int near = static_cast<int>(curves_.size());
  curves_.push_back(Curve::circle(cx, cy, r, -1.0));
  curves_.push_back(Curve::circle(cx, cy, r, 1.0));
  const double half = d > r ? std::asin(r / d) : 0.5 * std::numbers::pi;
  cut(near, near + 1, curves_[near].phi, half);
}

void ScallopedRegion::remove_beyond_wall(double h, double psi) {
  const int wall = static_cast<int>(curves_.size());
  curves_.push_back(Curve::wall(h, psi));
  cut(wall, -1, psi, 0.5 * std::numbers::pi);
}

std::pair<double, double> ScallopedRegion::sample(Rng& rng) const {
  const double u = rng.uniform();
  const double v = rng.uniform();
  return position(u, v);
}

std::pair<double, double> ScallopedRegion::position(double u_fraction, double v) const {
  double u = u_fraction * area();
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
  const double rad = std::sqrt(ra * ra + v * std::max(0.0, rb * rb - ra * ra));
  return {theta, rad};
}

std::optional<std::pair<double, double>> ScallopedRegion::cdf(double theta, double radius) const {
  double before = 0.0;
  for (const Sector& s : sectors_) {
    if (theta >= s.t0 && theta <= s.t1) {
      const Curve &a = curves_[s.inner], &b = curves_[s.outer];
      const double ra = a.radius(theta), rb = b.radius(theta);
      if (radius >= ra && radius <= rb) {
        const double swept = (b.primitive(theta) - a.primitive(theta)) - (b.primitive(s.t0) - a.primitive(s.t0));
        const double v = rb * rb > ra * ra ? (radius * radius - ra * ra) / (rb * rb - ra * ra) : 0.0;
        return std::pair{(before + swept) / area(), v};
      }
    }
    before += s.area;
  }
  return std::nullopt;
}

void ScallopedRegion::add(Sector s, std::vector<Sector>& to) const {
  if (s.t1 - s.t0 <= kMinAngle) return;
  if (!to.empty() && to.back().t1 == s.t0 && to.back().inner == s.inner && to.back().outer == s.outer) {
    to.back().t1 = s.t1;
    to.back().area = area(to.back());
    return;
  }
  s.area = area(s);
  if (s.area > 0.0) to.push_back(s);
}

double ScallopedRegion::area(const Sector& s) const {
  const Curve &a = curves_[s.inner], &b = curves_[s.outer];
  return std::max(0.0, (b.primitive(s.t1) - b.primitive(s.t0)) - (a.primitive(s.t1) - a.primitive(s.t0)));
}

/// Removes {near(theta) < rho < far(theta)} for theta within `half` of
/// `centre` (far = -1: no far curve, everything beyond near).
void ScallopedRegion::cut(int near, int far, double centre, double half) {
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

}  // namespace pds::detail::dh
