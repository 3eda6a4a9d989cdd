// Poisson disk samples on triangle meshes: C. Yuksel, Sample elimination for
// generating Poisson disk sample sets, Computer Graphics Forum 34(2)
// (Eurographics 2015), section 6 (sampling surfaces).
//
// Method: ceil(c N) candidates are spread over the triangles, each triangle
// chosen with probability proportional to its area times its mean corner
// density (a binary search in the cumulative weights), the point inside it
// uniform in barycentric coordinates (the unit square folded onto the
// triangle), kept against the triangle's largest corner density when the
// density varies (rejection, at most 64 tries, each accepted with
// probability at least 1/3). The candidates are then eliminated in 3D
// (elimination_detail.h) inside the mesh's bounding box, with d_max =
// 2 r_max for the hexagonal packing of N disks on the surface's
// (density-weighted) area: the surface is two-dimensional, so its packing is
// the plane's, and the progressive rounds grow d_max by sqrt 2.
//
// Distances are 3D Euclidean: two samples on either side of a thin wall are
// close even though the path along the surface is long, as in MeshLab and in
// the paper.
//
// Guarantees: exactly N samples, each a convex combination of its
// triangle's corners; same seed, same samples (one thread). No minimum
// distance is promised.
//
// Complexity: O(c N log T) to draw the candidates (T triangles) and the
// elimination's O(c N k log(c N)); memory about 60 bytes a candidate.

#include "pds/samplers/surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "elimination_detail.h"
#include "pds/analysis/relative_radius.h"
#include "pds/detail/format.h"
#include "pds/domain.h"
#include "pds/error.h"
#include "pds/rng.h"

namespace pds {
namespace {

constexpr std::size_t kMaxCandidates = std::size_t{1} << 31;
// Elimination's typical relative radius in 2D from 5N candidates
// (docs/elimination.md); --radius sizes the count by it.
constexpr double kTypicalRho = 0.69;
constexpr double kMaxDensityRatio = 1e4;
constexpr int kMaxDensityTries = 64;

Point<3> minus(const Point<3>& a, const Point<3>& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }

Point<3> cross(const Point<3>& a, const Point<3>& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

double norm(const Point<3>& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

double triangle_area(const TriangleMesh& mesh, const std::array<std::uint32_t, 3>& t) {
  const Point<3>& a = mesh.vertices[t[0]];
  return 0.5 * norm(cross(minus(mesh.vertices[t[1]], a), minus(mesh.vertices[t[2]], a)));
}

}  // namespace

double surface_area(const TriangleMesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles) area += triangle_area(mesh, t);
  return area;
}

void validate_mesh(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) throw InvalidArgument("mesh: no triangles");
  if (mesh.vertices.size() > kMaxCandidates || mesh.triangles.size() > kMaxCandidates)
    throw InvalidArgument("mesh: more than 2^31 vertices or triangles");
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    for (double x : mesh.vertices[v])
      if (!std::isfinite(x) || std::abs(x) > 1e149)
        throw InvalidArgument("mesh: vertex " + std::to_string(v) +
                              " has a coordinate that is not finite or beyond 1e149 in magnitude");
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
    for (std::uint32_t v : mesh.triangles[k])
      if (v >= mesh.vertices.size())
        throw InvalidArgument("mesh: triangle " + std::to_string(k) + " names vertex " + std::to_string(v) +
                              ", but there are " + std::to_string(mesh.vertices.size()) + " vertices");
  const double area = surface_area(mesh);
  if (!(area > 0.0) || !std::isfinite(area))
    throw InvalidArgument("mesh: the surface has area " + detail::format_number(area) +
                          "; it must be positive and finite");
}

std::uint64_t surface_count_for_radius(double area, double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw InvalidArgument("surface: radius must be positive and finite, got " + detail::format_number(radius));
  const double count = std::max(1.0, std::round(area / packing_volume_per_point(radius / (2.0 * kTypicalRho), 2)));
  if (!(count <= static_cast<double>(kMaxCandidates)))
    throw InvalidArgument("surface: radius " + detail::format_number(radius) + " asks for " +
                          detail::format_number(count) + " samples, more than 2^31");
  return static_cast<std::uint64_t>(count);
}

SurfaceSamples sample_surface(const TriangleMesh& mesh, const SurfaceParams& params, std::uint64_t seed) {
  validate_mesh(mesh);
  detail::validate_elimination_weights(params.weights);
  if (params.count == 0) throw InvalidArgument("surface: count must be at least 1, got 0");
  if (!(params.candidates >= 1.0) || !std::isfinite(params.candidates))
    throw InvalidArgument("surface: candidates must be a factor of at least 1, got " +
                          detail::format_number(params.candidates));
  const double m_real = std::ceil(params.candidates * static_cast<double>(params.count));
  if (m_real > static_cast<double>(kMaxCandidates))
    throw InvalidArgument("surface: " + detail::format_number(m_real) + " candidates, more than 2^31");
  const std::size_t m = static_cast<std::size_t>(m_real);
  const std::vector<double>& density = params.vertex_density;
  const bool varying = !density.empty();
  double top = 1.0;
  if (varying) {
    if (density.size() != mesh.vertices.size())
      throw InvalidArgument("surface: " + std::to_string(density.size()) + " vertex densities for " +
                            std::to_string(mesh.vertices.size()) + " vertices");
    double low = std::numeric_limits<double>::infinity();
    top = 0.0;
    for (std::size_t v = 0; v < density.size(); ++v) {
      if (!(density[v] > 0.0) || !std::isfinite(density[v]))
        throw InvalidArgument("surface: the density of vertex " + std::to_string(v) + " is " +
                              detail::format_number(density[v]) + "; densities must be positive and finite");
      low = std::min(low, density[v]);
      top = std::max(top, density[v]);
    }
    if (top > kMaxDensityRatio * low)
      throw InvalidArgument("surface: the vertex densities span " + detail::format_number(top / low) + " (from " +
                            detail::format_number(low) + " to " + detail::format_number(top) +
                            "); at most 1e4 is taken");
  }
  // Relative density of a vertex, in (0, 1].
  auto relative = [&](std::uint32_t v) { return varying ? density[v] / top : 1.0; };

  // Cumulative triangle weights: area times mean relative corner density.
  const std::size_t triangles = mesh.triangles.size();
  std::vector<double> cumulative(triangles);
  double total = 0.0;
  for (std::size_t k = 0; k < triangles; ++k) {
    const auto& t = mesh.triangles[k];
    total += triangle_area(mesh, t) * (relative(t[0]) + relative(t[1]) + relative(t[2])) / 3.0;
    cumulative[k] = total;
  }

  Rng rng(seed);
  PointSet<3> candidates(m);
  std::vector<std::uint32_t> face(m);
  std::vector<double> scale(varying ? m : 0);
  Point<3> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < m; ++i) {
    const double pick = rng.uniform() * total;
    const std::size_t k = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()),
        triangles - 1);
    const auto& t = mesh.triangles[k];
    const Point<3>& a = mesh.vertices[t[0]];
    const Point<3>& b = mesh.vertices[t[1]];
    const Point<3>& c = mesh.vertices[t[2]];
    double u = 0.0, v = 0.0, here = 1.0;
    const double corner_max = std::max({relative(t[0]), relative(t[1]), relative(t[2])});
    for (int attempt = 0; attempt < kMaxDensityTries; ++attempt) {
      u = rng.uniform();
      v = rng.uniform();
      if (u + v > 1.0) {
        u = 1.0 - u;
        v = 1.0 - v;
      }
      if (!varying) break;
      here = (1.0 - u - v) * relative(t[0]) + u * relative(t[1]) + v * relative(t[2]);
      if (rng.uniform() * corner_max < here) break;
    }
    Point<3>& p = candidates[i];
    for (int axis = 0; axis < 3; ++axis) {
      p[axis] = (1.0 - u - v) * a[axis] + u * b[axis] + v * c[axis];
      lo[axis] = std::min(lo[axis], p[axis]);
      hi[axis] = std::max(hi[axis], p[axis]);
    }
    face[i] = static_cast<std::uint32_t>(k);
    if (varying) scale[i] = 1.0 / std::sqrt(here);
  }
  // The candidates' bounding box, grown so that every candidate lies inside
  // [lo, hi) and a flat mesh still has thickness.
  double diagonal = 0.0;
  for (int axis = 0; axis < 3; ++axis) diagonal = std::max(diagonal, hi[axis] - lo[axis]);
  const double margin = std::max(1e-6 * diagonal, 1e-140);
  for (int axis = 0; axis < 3; ++axis) {
    lo[axis] -= margin;
    hi[axis] += margin;
  }
  const Domain<3> box = Domain<3>::box(lo, hi);
  const std::size_t n = static_cast<std::size_t>(params.count);
  if (n > m) throw InvalidArgument("surface: count is more than the candidates");
  const double d_max = 2.0 * std::sqrt(total / (2.0 * std::sqrt(3.0) * static_cast<double>(n)));
  const std::vector<std::uint32_t> kept = detail::eliminate_indices<3>(
      candidates, scale, n, box, d_max, params.weights, params.progressive, /*growth_dim=*/2, params.progress);

  SurfaceSamples out;
  out.positions.resize(n);
  out.normals.resize(n);
  out.faces.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.positions[i] = candidates[kept[i]];
    const std::uint32_t k = face[kept[i]];
    out.faces[i] = k;
    const auto& t = mesh.triangles[k];
    const Point<3>& a = mesh.vertices[t[0]];
    const Point<3> normal = cross(minus(mesh.vertices[t[1]], a), minus(mesh.vertices[t[2]], a));
    const double length = norm(normal);
    for (int axis = 0; axis < 3; ++axis) out.normals[i][axis] = normal[axis] / length;
  }
  return out;
}

}  // namespace pds
