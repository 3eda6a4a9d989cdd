// Benchmarks of the foundation: generation of the elementary patterns and the
// exact minimum-distance and maximality checks.
#include <benchmark/benchmark.h>

#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"
#include "pds/grid.h"
#include "pds/samplers/jittered.h"
#include "pds/samplers/random.h"
#include "pds/samplers/regular.h"

namespace {

void BM_WhiteNoise2D(benchmark::State& state) {
  const auto n = static_cast<std::uint64_t>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(pds::white_noise<2>({n}, pds::Domain<2>::unit(), 1));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_WhiteNoise2D)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

void BM_Jittered2D(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(pds::jittered<2>({{side, side, 1}}, pds::Domain<2>::unit(), 1));
  state.SetItemsProcessed(state.iterations() * side * side);
}
BENCHMARK(BM_Jittered2D)->Arg(1024)->Unit(benchmark::kMillisecond);

void BM_MinDistance2D(benchmark::State& state) {
  const auto n = static_cast<std::uint64_t>(state.range(0));
  const auto domain = pds::Domain<2>::unit(true);
  const auto points = pds::white_noise<2>({n}, domain, 1);
  for (auto _ : state) benchmark::DoNotOptimize(pds::min_distance(points, domain));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_MinDistance2D)->Arg(1 << 14)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

void BM_MaximalityRegular2D(benchmark::State& state) {
  // A regular grid is maximal at radius = half its diagonal spacing, with every
  // Voronoi vertex exactly on a circle: the hardest case for the check.
  const int side = static_cast<int>(state.range(0));
  const auto domain = pds::Domain<2>::unit(true);
  const auto points = pds::regular<2>({{side, side, 1}}, domain);
  const double radius = std::sqrt(0.5) / side * 1.0001;
  for (auto _ : state) benchmark::DoNotOptimize(pds::check_maximality(points, domain, radius));
  state.SetItemsProcessed(state.iterations() * side * side);
}
BENCHMARK(BM_MaximalityRegular2D)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
