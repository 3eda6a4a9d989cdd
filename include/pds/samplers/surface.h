#pragma once
// Poisson disk samples on a triangle mesh by weighted sample elimination
// (C. Yuksel, Sample elimination for generating Poisson disk sample sets,
// Eurographics 2015, section 6: surfaces): dense candidates spread over the
// triangles in proportion to their area (times the density), then eliminated
// with distances measured in 3D, Euclidean (the straight line through space,
// not along the surface), as MeshLab's Poisson-disk sampling and Yuksel do.
// Reading meshes from files is pds::read_mesh (pds/io/mesh_file.h, the
// pds::mesh component); the sampler itself needs no third-party library.

#include <array>
#include <cstdint>
#include <vector>

#include "pds/point.h"
#include "pds/samplers/elimination.h"

namespace pds {

/// Vertices and triangles (three vertex indices each, counterclockwise seen
/// from the side the normal points to).
struct TriangleMesh {
  PointSet<3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

struct SurfaceParams {
  std::uint64_t count = 0;  // samples to keep, >= 1
  /// Candidates as a multiple of the count (at least 1; the paper uses 5).
  double candidates = 5.0;
  /// Order the output so that every prefix is well spread (halving rounds
  /// with d_max grown by sqrt 2: the surface is two-dimensional).
  bool progressive = false;
  EliminationWeights weights;
  /// Empty (uniform), or one density a vertex, positive and finite, at most
  /// 10^4 times apart: the density inside a triangle is the linear
  /// interpolation of its corners', and the local spacing goes as
  /// density^(-1/2). Only ratios matter.
  std::vector<double> vertex_density;
  /// Optional progress (candidates removed) and cancellation (pds/progress.h).
  Progress progress;
};

struct SurfaceSamples {
  PointSet<3> positions;
  /// The unit normal of the sample's triangle (cross(b - a, c - a) normalised:
  /// flat per face, oriented by the vertex order).
  PointSet<3> normals;
  /// The index of the sample's triangle in TriangleMesh::triangles.
  std::vector<std::uint32_t> faces;

  std::size_t size() const { return positions.size(); }
};

/// The surface's area (sum of the triangles' areas).
double surface_area(const TriangleMesh& mesh);

/// Throws InvalidArgument unless the mesh has a triangle, every index names a
/// vertex, every coordinate is finite and at most 1e149 in magnitude (the
/// bounding box stays a valid domain), the area is positive and finite, at most 2^31
/// vertices and triangles.
void validate_mesh(const TriangleMesh& mesh);

/// The count whose samples have, as elimination typically gives them
/// (relative radius 0.69, docs/surface.md), minimum distance `radius` on a
/// surface of the given area: area / (2 sqrt(3) (radius / 1.38)^2), at
/// least 1. Throws InvalidArgument for a radius not positive and finite or a
/// count beyond 2^31.
std::uint64_t surface_count_for_radius(double area, double radius);

/// Draws ceil(candidates * count) candidates on the mesh (each a point of
/// one triangle, barycentric coordinates uniform, triangles chosen in
/// proportion to area times mean corner density; inside a triangle with
/// varying density, by rejection against its largest corner density) and
/// keeps `count` by weighted elimination with d_max = 2 r_max,
/// r_max = sqrt(A' / (2 sqrt(3) N)) (A' the area weighted by density
/// relative to the largest; a pair of samples uses the larger of their two
/// spacings, density^(-1/2)).
/// Guarantees: exactly `count` samples, each on its triangle (a convex
/// combination of its corners, so within rounding of the surface); same
/// seed, same samples. No minimum distance is promised (docs/surface.md gives
/// the measured one). Invalid (InvalidArgument): an invalid mesh, count 0,
/// candidates below 1 or more than 2^31 of them, bad weights or densities.
SurfaceSamples sample_surface(const TriangleMesh& mesh, const SurfaceParams& params, std::uint64_t seed);

}  // namespace pds
