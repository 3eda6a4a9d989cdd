// Tiling the image plane with a toroidal pattern.
//
// D. P. Mitchell, "Spectrally optimal sampling for distribution ray tracing",
// SIGGRAPH 1991: best-candidate patterns computed once on a torus and repeated
// over the image; M. Pharr and G. Humphreys, Physically Based Rendering (2004),
// section 7.5, used such a table with random per-copy offsets for the time and
// lens dimensions. Here the tile can come from any method run on the torus.
//
// Queries: the tile's points are sorted into a G x G grid of bins (G about
// sqrt(M), one point a bin on average), so a rectangle visits the copies it
// overlaps and, inside each, only the bins it covers: O(copies + bins +
// samples returned), independent of where on the plane the rectangle lies.
//
// The discrepancy sweep: for each run of points consecutive in x (an x-arc,
// M^2 of them), the largest excess of a closed rectangle (count - M*area) and
// the largest deficit of an open one (M*area - count) over all y-arcs are
// both maximum-sum windows over the run's sorted y values, found in O(run) with
// a monotone deque; runs grow one point at a time by sorted insertion.

#include "pds/detail/format.h"
#include "pds/tiling/tiled_pattern.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>
#include <string>

#include "pds/error.h"
#include "pds/rng.h"

namespace pds {

TiledPattern::TiledPattern(PointSet<2> tile, double spp, TiledPatternOptions options) : options_(options) {
  if (tile.empty()) throw InvalidArgument("tiled pattern: the tile has no points");
  if (!(spp > 0) || !std::isfinite(spp))
    throw InvalidArgument("tiled pattern: spp (samples per pixel) must be positive and finite, got " +
                          std::to_string(spp));
  if (options.extra_dims < 0 || options.extra_dims > kMaxExtraDims)
    throw InvalidArgument("tiled pattern: extra_dims must be in [0, " + std::to_string(kMaxExtraDims) + "], got " +
                          std::to_string(options.extra_dims));
  if (tile.size() > (std::size_t{1} << 31)) throw InvalidArgument("tiled pattern: the tile has more than 2^31 points");
  for (std::size_t i = 0; i < tile.size(); ++i)
    for (int k = 0; k < 2; ++k)
      if (!(tile[i][k] >= 0.0 && tile[i][k] < 1.0))
        throw InvalidArgument("tiled pattern: tile point " + std::to_string(i) + " has coordinate " +
                              detail::format_number(tile[i][k]) + " outside [0, 1) (the tile must lie on the unit torus)");
  const std::size_t m = tile.size();
  spp_ = spp;
  tile_size_ = std::sqrt(static_cast<double>(m) / spp);
  bins_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(m))), 1, 1024);

  // Extra dimensions: a shuffled Latin hypercube over the tile, per dimension.
  const int extra = options.extra_dims;
  std::vector<double> base(m * static_cast<std::size_t>(extra));
  for (int k = 0; k < extra; ++k) {
    Rng rng(options.seed, {0x7e11e57ab1e, static_cast<std::uint64_t>(k)});
    std::vector<std::uint32_t> perm(m);
    std::iota(perm.begin(), perm.end(), 0u);
    for (std::size_t i = m; i > 1; --i) std::swap(perm[i - 1], perm[rng.below(i)]);
    for (std::size_t i = 0; i < m; ++i) base[i * extra + k] = (perm[i] + rng.uniform()) / static_cast<double>(m);
  }

  // Counting sort of the points into bins, stable in the tile's order.
  auto bin_of = [&](const Point<2>& p) {
    const int bx = std::min(bins_ - 1, static_cast<int>(p[0] * bins_));
    const int by = std::min(bins_ - 1, static_cast<int>(p[1] * bins_));
    return static_cast<std::size_t>(by) * bins_ + bx;
  };
  bin_start_.assign(static_cast<std::size_t>(bins_) * bins_ + 1, 0);
  for (const auto& p : tile) ++bin_start_[bin_of(p) + 1];
  std::partial_sum(bin_start_.begin(), bin_start_.end(), bin_start_.begin());
  std::vector<std::uint32_t> next(bin_start_.begin(), bin_start_.end() - 1);
  tile_.resize(m);
  extra_base_.resize(base.size());
  for (std::size_t i = 0; i < m; ++i) {
    const std::uint32_t slot = next[bin_of(tile[i])]++;
    tile_[slot] = tile[i];
    for (int k = 0; k < extra; ++k) extra_base_[slot * extra + k] = base[i * extra + k];
  }
}

void TiledPattern::check(const PixelRect& r) const {
  const double limit = kMaxTileIndex * tile_size_;
  for (double v : {r.x0, r.y0, r.x1, r.y1})
    if (!std::isfinite(v) || std::abs(v) > limit)
      throw InvalidArgument("tiled pattern: rectangle coordinate " + detail::format_number(v) +
                            " is not finite or lies beyond " + detail::format_number(limit) + " pixels");
}

void TiledPattern::samples_in(const PixelRect& rect, std::vector<Point<2>>& positions,
                              std::vector<double>* extra) const {
  check(rect);
  if (!(rect.x1 > rect.x0) || !(rect.y1 > rect.y0)) return;
  const double s = tile_size_;
  const int dims = options_.extra_dims;
  double offset[kMaxExtraDims];
  const auto tx0 = static_cast<std::int64_t>(std::floor(rect.x0 / s));
  const auto tx1 = static_cast<std::int64_t>(std::floor(rect.x1 / s));
  const auto ty0 = static_cast<std::int64_t>(std::floor(rect.y0 / s));
  const auto ty1 = static_cast<std::int64_t>(std::floor(rect.y1 / s));
  // Bin range of [lo, hi) (tile units) within one copy; one bin wider on each
  // side than the exact range so rounding at bin edges never drops a point.
  auto bin_range = [&](double lo, double hi, int& b0, int& b1) {
    b0 = std::clamp(static_cast<int>(std::floor(lo * bins_)) - 1, 0, bins_ - 1);
    b1 = std::clamp(static_cast<int>(std::floor(hi * bins_)) + 1, 0, bins_ - 1);
  };
  for (std::int64_t ty = ty0; ty <= ty1; ++ty) {
    int by0, by1;
    bin_range(rect.y0 / s - static_cast<double>(ty), rect.y1 / s - static_cast<double>(ty), by0, by1);
    for (std::int64_t tx = tx0; tx <= tx1; ++tx) {
      int bx0, bx1;
      bin_range(rect.x0 / s - static_cast<double>(tx), rect.x1 / s - static_cast<double>(tx), bx0, bx1);
      if (dims > 0 && extra) {
        Rng rng(options_.seed, {0x0ff5e7, static_cast<std::uint64_t>(tx), static_cast<std::uint64_t>(ty)});
        for (int k = 0; k < dims; ++k) offset[k] = rng.uniform();
      }
      for (int by = by0; by <= by1; ++by) {
        const std::size_t row = static_cast<std::size_t>(by) * bins_;
        for (std::uint32_t i = bin_start_[row + bx0]; i < bin_start_[row + bx1 + 1]; ++i) {
          const Point<2>& p = tile_[i];
          const double x = (static_cast<double>(tx) + p[0]) * s;
          const double y = (static_cast<double>(ty) + p[1]) * s;
          if (!rect.contains(x, y)) continue;
          positions.push_back(Point<2>{{x, y}});
          if (dims > 0 && extra)
            for (int k = 0; k < dims; ++k) {
              const double v = extra_base_[static_cast<std::size_t>(i) * dims + k] + offset[k];
              extra->push_back(v < 1.0 ? v : v - 1.0);
            }
        }
      }
    }
  }
}

double TiledPattern::count_bound(const PixelRect& rect, double discrepancy) const {
  const double nx = std::floor((rect.x1 - rect.x0) / tile_size_);
  const double ny = std::floor((rect.y1 - rect.y0) / tile_size_);
  return (std::max(nx, 0.0) + std::max(ny, 0.0) + 1.0) * discrepancy;
}

namespace {

// Values of the sorted coordinates unrolled around the circle: v(j) for any j
// in [-n, 2n) is sorted[j mod n] plus the number of turns.
struct Unrolled {
  const std::vector<double>& sorted;
  double operator()(std::ptrdiff_t j) const {
    const auto n = static_cast<std::ptrdiff_t>(sorted.size());
    if (j < 0) return sorted[j + n] - 1.0;
    if (j >= n) return sorted[j - n] + 1.0;
    return sorted[j];
  }
};

// Over y-arcs of n sorted values, with c = M * (x-arc width):
//   excess:  max over closed arcs covering l consecutive values of l - c * height
//   deficit: max over open arcs holding l values of c * height - l (incl. the full circle)
struct ArcExtremes {
  double excess = 0, deficit = 0;
};

ArcExtremes arc_extremes(const std::vector<double>& ys, double c, bool want_excess, bool want_deficit) {
  const auto n = static_cast<std::ptrdiff_t>(ys.size());
  ArcExtremes out;
  out.deficit = c - static_cast<double>(n);  // the full circle
  if (n == 0) return out;
  const Unrolled y{ys};
  std::deque<std::ptrdiff_t> window;  // indices with decreasing key
  if (want_excess) {
    // 1 + max over s <= e <= s + n - 1, s in [0, n): (e - c y(e)) + (c y(s) - s).
    auto key = [&](std::ptrdiff_t s) { return c * y(s) - static_cast<double>(s); };
    double best = -1e300;
    for (std::ptrdiff_t e = 0; e <= 2 * n - 2; ++e) {
      if (e < n) {
        while (!window.empty() && key(window.back()) <= key(e)) window.pop_back();
        window.push_back(e);
      }
      while (window.front() < e - n + 1) window.pop_front();
      best = std::max(best, static_cast<double>(e) - c * y(e) + key(window.front()));
    }
    out.excess = best + 1.0;
    window.clear();
  }
  if (want_deficit) {
    // 1 + max over i < j <= i + n, i in [0, n): (c y(j) - j) + (i - c y(i)).
    auto key = [&](std::ptrdiff_t i) { return static_cast<double>(i) - c * y(i); };
    double best = -1e300;
    for (std::ptrdiff_t j = 1; j <= 2 * n - 1; ++j) {
      if (j - 1 < n) {
        while (!window.empty() && key(window.back()) <= key(j - 1)) window.pop_back();
        window.push_back(j - 1);
      }
      while (window.front() < j - n) window.pop_front();
      best = std::max(best, c * y(j) - static_cast<double>(j) + key(window.front()));
    }
    out.deficit = std::max(out.deficit, best + 1.0);
  }
  return out;
}

}  // namespace

double torus_rectangle_discrepancy(const PointSet<2>& points) {
  const std::size_t m = points.size();
  if (m > kMaxDiscrepancyPoints)
    throw InvalidArgument("torus discrepancy: " + std::to_string(m) + " points is more than the O(M^3) sweep takes (" +
                          std::to_string(kMaxDiscrepancyPoints) + ")");
  if (m == 0) return 0.0;
  const double md = static_cast<double>(m);
  PointSet<2> sorted = points;
  std::sort(sorted.begin(), sorted.end(), [](const Point<2>& a, const Point<2>& b) { return a[0] < b[0]; });
  std::vector<double> xs(m);
  for (std::size_t i = 0; i < m; ++i) xs[i] = sorted[i][0];
  const Unrolled x{xs};
  const auto n = static_cast<std::ptrdiff_t>(m);

  double worst = 0.0;
  std::vector<double> ys;
  ys.reserve(m);
  for (std::ptrdiff_t a = 0; a < n; ++a) {
    ys.clear();
    for (std::ptrdiff_t k = 0; k <= n; ++k) {
      // The run holds sorted points a .. a+k-1 (mod M).
      if (k > 0) {
        const double y = sorted[(a + k - 1) % n][1];
        ys.insert(std::upper_bound(ys.begin(), ys.end(), y), y);
      }
      const bool closed = k >= 1;    // closed x-arc from point a to point a+k-1
      const bool open = k <= n - 1;  // open x-arc between points a-1 and a+k
      const double closed_width = closed ? x(a + k - 1) - x(a) : 0.0;
      const double open_width = k == n - 1 ? 1.0 : (open ? x(a + k) - x(a - 1) : 1.0);
      if (closed) worst = std::max(worst, arc_extremes(ys, md * closed_width, true, false).excess);
      if (open) worst = std::max(worst, arc_extremes(ys, md * open_width, false, true).deficit);
    }
  }
  // The full x-circle holding every point (deficits only; its excess is
  // dominated by the closed arc over all points).
  worst = std::max(worst, arc_extremes(ys, md, false, true).deficit);
  return worst;
}

double torus_rectangle_discrepancy_brute_force(const PointSet<2>& points) {
  const std::size_t m = points.size();
  if (m == 0) return 0.0;
  const double md = static_cast<double>(m);
  // Arcs of one axis's circle from coordinate a forward to b. The extremes are
  // reached by closed arcs between two points' coordinates (largest excess of
  // points) and by open ones, or the whole circle (largest deficit); an open
  // arc from a point back to itself is the circle less that point.
  struct Arc {
    double a, b;
    bool closed, full;
  };
  auto forward = [](double from, double to) { return to >= from ? to - from : to - from + 1.0; };
  auto width = [&](const Arc& arc) {
    return arc.full || (!arc.closed && arc.a == arc.b) ? 1.0 : forward(arc.a, arc.b);
  };
  auto inside = [&](const Arc& arc, double t) {
    if (arc.full) return true;
    const double d = forward(arc.a, t), w = width(arc);
    return arc.closed ? d <= w : (d > 0 && d < w);
  };
  double worst = 0.0;
  for (bool closed : {true, false}) {
    std::vector<Arc> xa, ya;
    for (const auto& p : points)
      for (const auto& q : points) {
        xa.push_back({p[0], q[0], closed, false});
        ya.push_back({p[1], q[1], closed, false});
      }
    if (!closed) {
      xa.push_back({0, 0, false, true});
      ya.push_back({0, 0, false, true});
    }
    for (const Arc& ax : xa)
      for (const Arc& ay : ya) {
        std::size_t count = 0;
        for (const auto& p : points) count += inside(ax, p[0]) && inside(ay, p[1]);
        const double expected = md * width(ax) * width(ay);
        worst = std::max(worst, closed ? static_cast<double>(count) - expected : expected - static_cast<double>(count));
      }
  }
  return worst;
}

}  // namespace pds
