#include "pds/samplers/surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pds/error.h"

namespace pds {
namespace {

// A latitude-longitude sphere of radius `radius`.
TriangleMesh sphere(int rings, int segments, double radius = 1.0) {
  TriangleMesh mesh;
  mesh.vertices.push_back({{0, 0, radius}});
  for (int i = 1; i < rings; ++i) {
    const double theta = std::numbers::pi * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * std::numbers::pi * j / segments;
      mesh.vertices.push_back({{radius * std::sin(theta) * std::cos(phi), radius * std::sin(theta) * std::sin(phi),
                                radius * std::cos(theta)}});
    }
  }
  mesh.vertices.push_back({{0, 0, -radius}});
  const auto at = [&](int ring, int j) { return static_cast<std::uint32_t>(1 + (ring - 1) * segments + j % segments); };
  const auto south = static_cast<std::uint32_t>(mesh.vertices.size() - 1);
  for (int j = 0; j < segments; ++j) {
    mesh.triangles.push_back({0, at(1, j), at(1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
    mesh.triangles.push_back({at(rings - 1, j), south, at(rings - 1, j + 1)});
  }
  return mesh;
}

// A torus of radii R (tube centre) and r (tube).
TriangleMesh torus(int around, int tube, double big = 1.0, double small = 0.3) {
  TriangleMesh mesh;
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      const double u = 2 * std::numbers::pi * i / around, v = 2 * std::numbers::pi * j / tube;
      mesh.vertices.push_back({{(big + small * std::cos(v)) * std::cos(u), (big + small * std::cos(v)) * std::sin(u),
                                small * std::sin(v)}});
    }
  const auto at = [&](int i, int j) { return static_cast<std::uint32_t>((i % around) * tube + j % tube); };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

// A long thin strip: 10 by 0.001, two triangles, tilted out of every axis
// plane.
TriangleMesh sliver() {
  TriangleMesh mesh;
  mesh.vertices = {{{0, 0, 0}}, {{10, 3, 1}}, {{10, 3, 1.001}}, {{0, 0, 0.001}}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

Point<3> sub(const Point<3>& a, const Point<3>& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
double dot(const Point<3>& a, const Point<3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Distance from p to triangle abc, in long double: the distance to the
// plane where p projects inside the triangle (all three edge tests, signs of
// cross products with the normal, agree), else the distance to the nearest
// edge. Both forms stay accurate on slivers, where the barycentric
// closed forms lose digits to cancellation.
using Vec = std::array<long double, 3>;
Vec lsub(const Point<3>& a, const Point<3>& b) {
  return {(long double)a[0] - b[0], (long double)a[1] - b[1], (long double)a[2] - b[2]};
}
long double ldot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec lcross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

long double distance_to_segment(const Point<3>& p, const Point<3>& a, const Point<3>& b) {
  const Vec ab = lsub(b, a), ap = lsub(p, a);
  const long double t = std::clamp(ldot(ap, ab) / ldot(ab, ab), 0.0L, 1.0L);
  const Vec d{ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]};
  return std::sqrt(ldot(d, d));
}

double distance_to_triangle(const Point<3>& p, const Point<3>& a, const Point<3>& b, const Point<3>& c) {
  const Vec n = lcross(lsub(b, a), lsub(c, a));
  const bool inside = ldot(lcross(lsub(b, a), lsub(p, a)), n) >= 0 && ldot(lcross(lsub(c, b), lsub(p, b)), n) >= 0 &&
                      ldot(lcross(lsub(a, c), lsub(p, c)), n) >= 0;
  if (inside) return static_cast<double>(std::abs(ldot(lsub(p, a), n)) / std::sqrt(ldot(n, n)));
  return static_cast<double>(
      std::min({distance_to_segment(p, a, b), distance_to_segment(p, b, c), distance_to_segment(p, c, a)}));
}

double diagonal(const TriangleMesh& mesh) {
  Point<3> lo = mesh.vertices[0], hi = mesh.vertices[0];
  for (const auto& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], v[k]);
      hi[k] = std::max(hi[k], v[k]);
    }
  return std::sqrt(dot(sub(hi, lo), sub(hi, lo)));
}

// All pairs: the smallest 3D distance.
double min_distance(const PointSet<3>& points) {
  double best = INFINITY;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      best = std::min(best, dot(sub(points[i], points[j]), sub(points[i], points[j])));
  return std::sqrt(best);
}

// (d_min / 2) / r_max with r_max the hexagonal packing radius on the area.
double relative_radius_on(double area, const PointSet<3>& points) {
  const double r_max = std::sqrt(area / (2 * std::sqrt(3.0) * static_cast<double>(points.size())));
  return min_distance(points) / 2 / r_max;
}

void expect_on_surface(const TriangleMesh& mesh, const SurfaceSamples& s) {
  const double tolerance = 1e-12 * diagonal(mesh);
  for (std::size_t i = 0; i < s.size(); ++i) {
    ASSERT_LT(s.faces[i], mesh.triangles.size());
    const auto& t = mesh.triangles[s.faces[i]];
    // Its own triangle, and so the nearest of all triangles too.
    ASSERT_LE(distance_to_triangle(s.positions[i], mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]),
              tolerance)
        << "sample " << i;
    const Point<3> e1 = sub(mesh.vertices[t[1]], mesh.vertices[t[0]]),
                   e2 = sub(mesh.vertices[t[2]], mesh.vertices[t[0]]);
    ASSERT_NEAR(dot(s.normals[i], s.normals[i]), 1.0, 1e-12);
    ASSERT_NEAR(dot(s.normals[i], e1), 0.0, 1e-12 * std::sqrt(dot(e1, e1)));
    ASSERT_NEAR(dot(s.normals[i], e2), 0.0, 1e-12 * std::sqrt(dot(e2, e2)));
  }
}

TEST(Surface, SphereSamplesAreOnTheSurfaceExactCountAndSpread) {
  const TriangleMesh mesh = sphere(24, 48);
  const SurfaceSamples s = sample_surface(mesh, {.count = 1500}, 1);
  ASSERT_EQ(s.size(), 1500u);
  expect_on_surface(mesh, s);
  // The relative radius on the surface: elimination reaches ~0.69 in the
  // plane from 5N candidates; white noise would give ~0.02.
  const double rho = relative_radius_on(surface_area(mesh), s.positions);
  EXPECT_GT(rho, 0.6) << rho;
  // Outward normals: the sphere's triangles are counterclockwise seen from
  // outside.
  for (std::size_t i = 0; i < s.size(); ++i) ASSERT_GT(dot(s.normals[i], s.positions[i]), 0.9);
}

// Progress counts the candidates removed (all rounds), monotone up to the
// total; it changes no byte, and a callback that says stop cancels the run.
TEST(Surface, ReportsProgressAndCanBeCancelled) {
  const TriangleMesh t = torus(48, 16);
  SurfaceParams params{.count = 1000, .progressive = true};
  const SurfaceSamples quiet = sample_surface(t, params, 3);
  std::vector<std::pair<double, double>> reports;
  params.progress.report = [&](double done, double total) {
    reports.emplace_back(done, total);
    return true;
  };
  const SurfaceSamples heard = sample_surface(t, params, 3);
  EXPECT_EQ(heard.positions, quiet.positions);
  ASSERT_GE(reports.size(), 10u);
  // 4,000 removed in the first round, then 500 + 250 + ... + 1 in the halvings.
  EXPECT_EQ(reports.front().second, 4000.0 + 999.0);
  for (std::size_t i = 1; i < reports.size(); ++i) EXPECT_GE(reports[i].first, reports[i - 1].first);
  EXPECT_EQ(reports.back().first, reports.back().second);
  int calls = 0;
  params.progress.report = [&](double, double) { return ++calls < 3; };
  EXPECT_THROW(sample_surface(t, params, 3), Cancelled);
}

TEST(Surface, TorusAndSliver) {
  const TriangleMesh t = torus(48, 16);
  const SurfaceSamples s = sample_surface(t, {.count = 1000, .progressive = true}, 3);
  ASSERT_EQ(s.size(), 1000u);
  expect_on_surface(t, s);
  EXPECT_GT(relative_radius_on(surface_area(t), s.positions), 0.55);
  // Every prefix is spread when progressive.
  const PointSet<3> half(s.positions.begin(), s.positions.begin() + 250);
  EXPECT_GT(relative_radius_on(surface_area(t), half), 0.5);

  const TriangleMesh thin = sliver();
  const SurfaceSamples line = sample_surface(thin, {.count = 300}, 4);
  ASSERT_EQ(line.size(), 300u);
  expect_on_surface(thin, line);
  // 0.001 wide and 10.5 long, narrower than the spacing the area asks for
  // (d_max = 2 sqrt(0.0104 / (2 sqrt 3 300)) = 0.0062): the samples keep
  // about that spacing along it; white noise would have pairs 50 times
  // closer (about 10.5 / 300^2).
  EXPECT_GT(min_distance(line.positions), 0.5 * 0.0062);
}

TEST(Surface, SeedReproducesAndAreaWeights) {
  // Two squares, one 3 times the area of the other (sides 1 and sqrt 3): the
  // counts on each follow the areas.
  TriangleMesh mesh;
  const double s3 = std::sqrt(3.0);
  mesh.vertices = {{{0, 0, 0}}, {{1, 0, 0}},  {{1, 1, 0}},   {{0, 1, 0}},
                   {{5, 0, 0}}, {{5, 0, s3}}, {{5, s3, s3}}, {{5, s3, 0}}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
  const SurfaceSamples a = sample_surface(mesh, {.count = 800}, 9);
  const SurfaceSamples b = sample_surface(mesh, {.count = 800}, 9);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_NE(sample_surface(mesh, {.count = 800}, 10).positions, a.positions);
  const auto big = std::count_if(a.faces.begin(), a.faces.end(), [](std::uint32_t f) { return f >= 2; });
  // 600 expected; elimination evens the spread, so the error is well below
  // the binomial sd of 12.
  EXPECT_NEAR(static_cast<double>(big), 600.0, 30.0);
}

TEST(Surface, VertexDensityFollows) {
  // The sphere, density rising from 1 at the south pole to 9 at the north
  // (linear in z). Counts in the two hemispheres follow the integral of the
  // density: on a sphere, area is uniform in z, so the northern half holds
  // the integral of 5 + 4z over [0, 1] (7) against 3 over [-1, 0].
  const TriangleMesh mesh = sphere(24, 48);
  SurfaceParams params{.count = 2000};
  for (const auto& v : mesh.vertices) params.vertex_density.push_back(5.0 + 4.0 * v[2]);
  const SurfaceSamples s = sample_surface(mesh, params, 5);
  ASSERT_EQ(s.size(), 2000u);
  expect_on_surface(mesh, s);
  const auto north = std::count_if(s.positions.begin(), s.positions.end(), [](const Point<3>& p) { return p[2] > 0; });
  EXPECT_NEAR(static_cast<double>(north) / 2000.0, 0.7, 0.03);
  // The larger-of-two spacing: the closest pair in the sparse south is
  // farther apart than in the dense north.
  PointSet<3> south_cap, north_cap;
  for (const auto& p : s.positions) {
    if (p[2] < -0.6) south_cap.push_back(p);
    if (p[2] > 0.6) north_cap.push_back(p);
  }
  EXPECT_GT(min_distance(south_cap), 1.5 * min_distance(north_cap));
}

TEST(Surface, BadInput) {
  const TriangleMesh good = sphere(4, 6);
  EXPECT_THROW(sample_surface(good, {.count = 0}, 1), InvalidArgument);
  EXPECT_THROW(sample_surface(good, {.count = 10, .candidates = 0.5}, 1), InvalidArgument);
  TriangleMesh out_of_range = good;
  out_of_range.triangles[3][1] = 1000;
  EXPECT_THROW(sample_surface(out_of_range, {.count = 10}, 1), InvalidArgument);
  TriangleMesh flat;
  flat.vertices = {{{0, 0, 0}}, {{1, 1, 1}}, {{2, 2, 2}}};
  flat.triangles = {{0, 1, 2}};
  EXPECT_THROW(sample_surface(flat, {.count = 10}, 1), InvalidArgument);
  TriangleMesh nan = good;
  nan.vertices[2][0] = NAN;
  EXPECT_THROW(sample_surface(nan, {.count = 10}, 1), InvalidArgument);
  EXPECT_THROW(sample_surface(TriangleMesh{}, {.count = 10}, 1), InvalidArgument);
  SurfaceParams wrong_size{.count = 10};
  wrong_size.vertex_density = {1.0, 2.0};
  EXPECT_THROW(sample_surface(good, wrong_size, 1), InvalidArgument);
  SurfaceParams negative{.count = 10};
  negative.vertex_density.assign(good.vertices.size(), 1.0);
  negative.vertex_density[1] = -1.0;
  EXPECT_THROW(sample_surface(good, negative, 1), InvalidArgument);
  negative.vertex_density[1] = 1e-5;
  EXPECT_THROW(sample_surface(good, negative, 1), InvalidArgument);  // a ratio of 1e5
  EXPECT_THROW(surface_count_for_radius(1.0, 0.0), InvalidArgument);
  EXPECT_THROW(surface_count_for_radius(1.0, 1e-10), InvalidArgument);
  // The radius that sizes a count is the typical spacing: a unit square at
  // 0.05 takes about 1 / (2 sqrt 3 (0.05 / 1.38)^2) = 220 samples.
  EXPECT_EQ(surface_count_for_radius(1.0, 0.05), 220u);
}

}  // namespace
}  // namespace pds
