// Poisson disk samples on a triangle mesh (docs/benchmarks.md, section
// "Surfaces"): weighted sample elimination of 5N area-weighted candidates,
// distances in 3D, one thread. The mesh is a torus of 2 x A x T triangles
// built here (the case: 10^5 triangles, 10^6 samples).
//
//   build/bench/pds_bench --benchmark_filter=Surface
//
// Arguments: samples, triangles / 1000, candidates factor x 10.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "pds/analysis/distance.h"
#include "pds/samplers/surface.h"

namespace {

pds::TriangleMesh torus(int around, int tube) {
  pds::TriangleMesh mesh;
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      const double u = 2 * std::numbers::pi * i / around, v = 2 * std::numbers::pi * j / tube;
      mesh.vertices.push_back(
          {{(1 + 0.3 * std::cos(v)) * std::cos(u), (1 + 0.3 * std::cos(v)) * std::sin(u), 0.3 * std::sin(v)}});
    }
  const auto at = [&](int i, int j) { return static_cast<std::uint32_t>((i % around) * tube + j % tube); };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

void BM_SurfaceElimination(benchmark::State& state) {
  const auto n = static_cast<std::uint64_t>(state.range(0));
  const int triangles = static_cast<int>(state.range(1)) * 1000;
  // around : tube = 2.5 : 1, so the triangles are near-equilateral-ish.
  const int tube = static_cast<int>(std::lround(std::sqrt(triangles / 2 / 2.5)));
  const int around = triangles / 2 / tube;
  const pds::TriangleMesh mesh = torus(around, tube);
  pds::SurfaceParams params{.count = n, .candidates = static_cast<double>(state.range(2)) / 10.0};
  pds::SurfaceSamples s;
  for (auto _ : state) {
    s = pds::sample_surface(mesh, params, 1);
    benchmark::DoNotOptimize(s.positions.data());
  }
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
  // The relative radius on the surface, (d_min / 2) / sqrt(A / (2 sqrt(3) N)),
  // d_min in 3D (the torus fits in [-1.3, 1.3]^2 x [-0.3, 0.3]).
  const auto box = pds::Domain<3>::box({{-1.4, -1.4, -0.4}}, {{1.4, 1.4, 0.4}});
  const double r_max = std::sqrt(pds::surface_area(mesh) / (2 * std::sqrt(3.0) * static_cast<double>(n)));
  state.counters["rho"] = pds::min_distance(s.positions, box).distance / 2 / r_max;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_SurfaceElimination)
    ->Args({100000, 100, 50})
    ->Args({1000000, 100, 50})
    ->Args({1000000, 100, 30})
    ->Args({1000000, 100, 20})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
