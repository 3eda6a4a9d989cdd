// Variable-density Bridson against the uniform one at the same count
// (docs/benchmarks.md, section "Variable density"). Items/s is samples
// produced per second on one thread.
//
//   build/bench/pds_bench --benchmark_filter='Density'
//
// BM_DensityBridson/N/RATIO: the constrained Bridson (samplers/constrained.h)
// on the unit torus with a smooth field r(x) = s (1 + (RATIO - 1) w(x)),
// w = (1 + sin(2 pi x) sin(2 pi y)) / 2 (dense and sparse patches, radius
// ratio RATIO), s chosen so that about N samples come out. The field is read
// from a 512 x 512 table with the nearest entry, as an image would be
// (pds generate --density), so the time is the sampler's, not sin's.
// BM_DensityUniformFast/N: pds::bridson (the specialised uniform code) at the
// radius for N; BM_DensityUniformGeneric/N: the constrained code with a
// constant radius (a mask that is everywhere true), which isolates the cost
// of the general index from that of the field.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "pds/samplers/constrained.h"
#include "pds/samplers/sizing.h"

namespace {

constexpr double kRho = 0.73;  // relative radius of a finished Bridson set in 2D

double weight(const pds::Point<2>& x) { return 0.5 * (1.0 + std::sin(2 * M_PI * x[0]) * std::sin(2 * M_PI * x[1])); }

// A set of relative radius rho holds 2 rho^2 / (sqrt(3) r^2) samples per unit
// area; the scale s that makes the integral over the torus N.
double field_scale(double n, double ratio) {
  const int m = 512;
  double integral = 0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const double r = 1 + (ratio - 1) * weight({{(i + 0.5) / m, (j + 0.5) / m}});
      integral += 1.0 / (r * r) / (m * m);
    }
  return std::sqrt(2 * kRho * kRho / std::sqrt(3.0) * integral / n);
}

void report(benchmark::State& state, std::size_t n) {
  state.counters["samples"] = static_cast<double>(n);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

void BM_DensityBridson(benchmark::State& state) {
  const double ratio = static_cast<double>(state.range(1));
  const double s = field_scale(static_cast<double>(state.range(0)), ratio);
  constexpr int m = 512;
  auto table = std::make_shared<std::vector<double>>(m * m);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) (*table)[j * m + i] = s * (1 + (ratio - 1) * weight({{(i + 0.5) / m, (j + 0.5) / m}}));
  pds::SamplingConstraints<2> c;
  c.rmin = s;
  c.rmax = s * ratio;
  c.radius = [table](const pds::Point<2>& x) {
    const int i = std::min(m - 1, static_cast<int>(x[0] * m)), j = std::min(m - 1, static_cast<int>(x[1] * m));
    return (*table)[j * m + i];
  };
  const auto domain = pds::Domain<2>::unit(true);
  std::size_t n = 0;
  for (auto _ : state) {
    const auto points = pds::bridson(pds::BridsonParams{}, c, domain, 1);
    n = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  report(state, n);
}
BENCHMARK(BM_DensityBridson)
    ->Args({100'000, 4})
    ->Args({100'000, 16})
    ->Args({1'000'000, 4})
    ->Unit(benchmark::kMillisecond);

void BM_DensityUniformFast(benchmark::State& state) {
  const auto domain = pds::Domain<2>::unit(true);
  pds::BridsonParams params;
  params.radius = pds::radius_for_count(static_cast<std::uint64_t>(state.range(0)), domain, kRho);
  std::size_t n = 0;
  for (auto _ : state) {
    const auto points = pds::bridson(params, domain, 1);
    n = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  report(state, n);
}
BENCHMARK(BM_DensityUniformFast)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void BM_DensityUniformGeneric(benchmark::State& state) {
  const auto domain = pds::Domain<2>::unit(true);
  pds::BridsonParams params;
  params.radius = pds::radius_for_count(static_cast<std::uint64_t>(state.range(0)), domain, kRho);
  pds::SamplingConstraints<2> c;
  c.inside = [](const pds::Point<2>&) { return true; };
  std::size_t n = 0;
  for (auto _ : state) {
    const auto points = pds::bridson(params, c, domain, 1);
    n = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  report(state, n);
}
BENCHMARK(BM_DensityUniformGeneric)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

}  // namespace
