#include "pds/tiling/tiled_pattern.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pds/analysis/distance.h"
#include "pds/error.h"
#include "pds/registry.h"
#include "pds/rng.h"

namespace pds {
namespace {

PointSet<2> uniform_points(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  PointSet<2> points(n);
  for (auto& p : points) p = Point<2>{{rng.uniform(), rng.uniform()}};
  return points;
}

PointSet<2> torus_pattern(const std::string& method, std::uint64_t count, std::uint64_t seed) {
  GenerateRequest request;
  request.torus = true;
  request.count = count;
  request.seed = seed;
  return generate(method, request).as<2>();
}

// Every sample of the copies overlapping the rectangle, by direct enumeration.
std::size_t count_by_enumeration(const PointSet<2>& tile, double s, const PixelRect& r) {
  std::size_t n = 0;
  for (auto ty = static_cast<long>(std::floor(r.y0 / s)) - 1; ty <= static_cast<long>(std::floor(r.y1 / s)) + 1; ++ty)
    for (auto tx = static_cast<long>(std::floor(r.x0 / s)) - 1; tx <= static_cast<long>(std::floor(r.x1 / s)) + 1; ++tx)
      for (const auto& p : tile) n += r.contains((tx + p[0]) * s, (ty + p[1]) * s);
  return n;
}

TEST(TorusDiscrepancy, SweepMatchesBruteForce) {
  for (std::size_t n : {1, 2, 3, 5, 8})
    for (std::uint64_t seed = 0; seed < 6; ++seed) {
      const PointSet<2> points = uniform_points(n, seed);
      EXPECT_NEAR(torus_rectangle_discrepancy(points), torus_rectangle_discrepancy_brute_force(points), 1e-9)
          << "n " << n << " seed " << seed;
    }
  const PointSet<2> jittered = torus_pattern("jittered", 9, 3);
  EXPECT_NEAR(torus_rectangle_discrepancy(jittered), torus_rectangle_discrepancy_brute_force(jittered), 1e-9);
}

TEST(TorusDiscrepancy, WithinTheStrataBoundForJitter) {
  // A torus rectangle's four edges (each at most 1 long) cross at most k + 1
  // strata each of a k x k jittered set; the strata they miss are wholly in or
  // out (exact count), the others are off by less than one point each.
  const int k = 16;
  const double e = torus_rectangle_discrepancy(torus_pattern("jittered", k * k, 11));
  EXPECT_GE(e, 1.0);  // a vanishing rectangle around one point
  EXPECT_LE(e, 4.0 * (k + 1));
}

TEST(TorusDiscrepancy, RejectsSetsTooLargeForTheSweep) {
  EXPECT_THROW(torus_rectangle_discrepancy(uniform_points(kMaxDiscrepancyPoints + 1, 1)), InvalidArgument);
}

TEST(TiledPattern, QueriesReturnExactlyTheSamplesInside) {
  const PointSet<2> tile = uniform_points(100, 5);
  const TiledPattern pattern(tile, 3.0);  // S = sqrt(100 / 3), not a whole number of pixels
  Rng rng(9);
  for (int trial = 0; trial < 300; ++trial) {
    const double x0 = rng.uniform(-60, 60), y0 = rng.uniform(-60, 60);
    const PixelRect r{x0, y0, x0 + rng.uniform(0, 25), y0 + rng.uniform(0, 25)};
    std::vector<Point<2>> found;
    pattern.samples_in(r, found);
    for (const auto& p : found) ASSERT_TRUE(r.contains(p[0], p[1]));
    ASSERT_EQ(found.size(), count_by_enumeration(tile, pattern.tile_size(), r));
  }
}

TEST(TiledPattern, CountsStayWithinTheStatedBound) {
  for (const char* method : {"random", "jittered", "best-candidate"}) {
    const PointSet<2> tile = torus_pattern(method, 256, 2);
    const double e = torus_rectangle_discrepancy(tile);
    for (double spp : {1.0, 3.0, 4.0}) {
      const TiledPattern pattern(tile, spp);
      const double s = pattern.tile_size();
      Rng rng(17);
      for (int trial = 0; trial < 400; ++trial) {
        // From sub-pixel rectangles to several copies across, anywhere on the plane.
        const double w = s * std::exp(rng.uniform(std::log(0.02), std::log(5.0)));
        const double h = s * std::exp(rng.uniform(std::log(0.02), std::log(5.0)));
        const double x0 = rng.uniform(-1000, 1000), y0 = rng.uniform(-1000, 1000);
        const PixelRect r{x0, y0, x0 + w, y0 + h};
        std::vector<Point<2>> found;
        pattern.samples_in(r, found);
        ASSERT_LE(std::abs(static_cast<double>(found.size()) - spp * r.area()), pattern.count_bound(r, e) + 1e-6)
            << method << " spp " << spp << " rect " << w << " x " << h;
      }
      // An S x S square anywhere holds exactly one copy's worth: spp per pixel on average.
      for (int trial = 0; trial < 50; ++trial) {
        const double x0 = rng.uniform(-500, 500), y0 = rng.uniform(-500, 500);
        std::vector<Point<2>> found;
        pattern.samples_in({x0, y0, x0 + s, y0 + s}, found);
        ASSERT_EQ(found.size(), pattern.tile_count());
      }
    }
  }
}

TEST(TiledPattern, SeamsKeepTheTileMinimumDistance) {
  // Every 2D method of the registry, run on the torus: the tiled plane's
  // closest pair is the tile's toroidal closest pair, scaled by S.
  for (const Method& m : methods()) {
    if (!m.dims.contains(2)) continue;
    GenerateRequest request;
    request.torus = true;
    request.seed = 4;
    // Radius-driven where possible, so the radius itself can be checked too.
    if (m.takes_radius)
      request.radius = 0.06;
    else
      request.count = 200;
    const PointSet<2> tile = generate(m.name, request).as<2>();
    if (tile.size() < 2) continue;
    const TiledPattern pattern(tile, 2.0);
    const double s = pattern.tile_size();
    const double inside = min_distance(tile, Domain<2>::unit(true)).distance * s;
    // Three by three copies and parts of their neighbours, off the tile grid.
    std::vector<Point<2>> plane;
    const PixelRect window{-0.7 * s, -1.3 * s, 2.4 * s, 1.9 * s};
    pattern.samples_in(window, plane);
    const Domain<2> box = Domain<2>::box(Point<2>{{window.x0, window.y0}}, Point<2>{{window.x1, window.y1}});
    const double across = min_distance_brute_force(PointSet<2>(plane.begin(), plane.end()), box).distance;
    EXPECT_NEAR(across, inside, 1e-9 * s) << m.name;
    if (request.radius) {
      EXPECT_GE(across, *request.radius * s * (1 - 1e-12)) << m.name;
    }
  }
}

TEST(TiledPattern, SameQuerySameSamplesAnyDecomposition) {
  const TiledPattern a(uniform_points(64, 1), 4.0, {2, 99}), b(uniform_points(64, 1), 4.0, {2, 99});
  const PixelRect whole{-7.5, -3.25, 20.5, 11.0};
  std::vector<Point<2>> pa, pb;
  std::vector<double> ea, eb;
  a.samples_in(whole, pa, &ea);
  b.samples_in(whole, pb, &eb);
  EXPECT_EQ(pa, pb);
  EXPECT_EQ(ea, eb);
  // Four quadrants give the same samples with the same extra values.
  std::vector<std::pair<Point<2>, std::pair<double, double>>> joined, parts;
  for (std::size_t i = 0; i < pa.size(); ++i) joined.push_back({pa[i], {ea[2 * i], ea[2 * i + 1]}});
  const double mx = 3.3, my = 4.4;
  for (const PixelRect& q : {PixelRect{whole.x0, whole.y0, mx, my}, PixelRect{mx, whole.y0, whole.x1, my},
                             PixelRect{whole.x0, my, mx, whole.y1}, PixelRect{mx, my, whole.x1, whole.y1}}) {
    std::vector<Point<2>> p;
    std::vector<double> e;
    a.samples_in(q, p, &e);
    for (std::size_t i = 0; i < p.size(); ++i) parts.push_back({p[i], {e[2 * i], e[2 * i + 1]}});
  }
  std::sort(joined.begin(), joined.end());
  std::sort(parts.begin(), parts.end());
  EXPECT_EQ(joined, parts);
}

TEST(TiledPattern, ExtraDimensionsAreRotatedLatinHypercubesPerCopy) {
  const std::size_t m = 128;
  const TiledPattern pattern(uniform_points(m, 8), 1.0, {3, 5});
  const double s = pattern.tile_size();
  std::vector<double> first_copy;
  for (int copy = 0; copy < 4; ++copy) {
    std::vector<Point<2>> p;
    std::vector<double> e;
    pattern.samples_in({copy * s, 0, (copy + 1) * s, s}, p, &e);
    ASSERT_EQ(p.size(), m);
    for (int k = 0; k < 3; ++k) {
      std::vector<double> v;
      for (std::size_t i = 0; i < m; ++i) v.push_back(e[i * 3 + k]);
      for (double x : v) ASSERT_TRUE(x >= 0.0 && x < 1.0);
      // One value per stratum of 1/M, rotated: circular gaps below 2/M.
      std::sort(v.begin(), v.end());
      for (std::size_t i = 0; i < m; ++i) {
        const double gap = i + 1 < m ? v[i + 1] - v[i] : v[0] + 1.0 - v[i];
        ASSERT_LT(gap, 2.0 / m);
      }
    }
    if (copy == 0)
      first_copy = e;
    else
      EXPECT_NE(e, first_copy);  // each copy has its own offsets
  }
}

TEST(TiledPattern, RejectsBadInput) {
  EXPECT_THROW(TiledPattern({}, 1.0), InvalidArgument);
  EXPECT_THROW(TiledPattern(uniform_points(4, 1), 0.0), InvalidArgument);
  EXPECT_THROW(TiledPattern(uniform_points(4, 1), std::nan("")), InvalidArgument);
  EXPECT_THROW(TiledPattern(PointSet<2>{Point<2>{{0.5, 1.0}}}, 1.0), InvalidArgument);
  EXPECT_THROW(TiledPattern(uniform_points(4, 1), 1.0, {TiledPattern::kMaxExtraDims + 1, 0}), InvalidArgument);
  const TiledPattern pattern(uniform_points(4, 1), 1.0);
  std::vector<Point<2>> out;
  EXPECT_THROW(pattern.samples_in({0, 0, std::nan(""), 1}, out), InvalidArgument);
  EXPECT_THROW(pattern.samples_in({0, 0, 1e300, 1}, out), InvalidArgument);
  pattern.samples_in({5, 5, 4, 6}, out);  // empty rectangle: nothing
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace pds
