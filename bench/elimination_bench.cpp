// Benchmarks of weighted sample elimination (docs/benchmarks.md, section
// "Sample elimination"). Items/s is output samples per second on one thread;
// the counter `rho` is the relative radius of the output.
//
//   build/bench/pds_bench --benchmark_filter=Elimination
//
// The peer measured in the same run is the paper author's own implementation,
// cySampleElim.h of cyCodeBase (C. Yuksel; k-d tree neighbour search, binary
// heap), on the same white-noise candidates. It is not part of pds: configure
// with -DPDS_BENCH_CYCODEBASE=/path/to/cyCodeBase (a checkout of
// github.com/cemyuksel/cyCodeBase) to build BM_EliminationCyCodeBase.
#include <benchmark/benchmark.h>

#include <vector>

#include "pds/analysis/distance.h"
#include "pds/analysis/relative_radius.h"
#include "pds/samplers/elimination.h"
#include "pds/samplers/random.h"

#ifdef PDS_BENCH_CYCODEBASE
#include "cySampleElim.h"
#include "cyVector.h"
#endif

namespace {

template <int D>
double rho_of(const pds::PointSet<D>& points, const pds::Domain<D>& domain) {
  return pds::relative_radius(pds::min_distance(points, domain).distance, domain.volume(), points.size(), D);
}

// Candidates drawn outside the timing, as for the peer.
template <int D, bool Torus>
void BM_Elimination(benchmark::State& state) {
  const auto domain = pds::Domain<D>::unit(Torus);
  const auto n = static_cast<std::uint64_t>(state.range(0));
  const bool progressive = state.range(1) != 0;
  const pds::PointSet<D> candidates = pds::white_noise<D>({.count = 5 * n}, domain, 1);
  pds::PointSet<D> out;
  for (auto _ : state) {
    out = pds::eliminate(candidates, n, domain, {}, progressive);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["rho"] = rho_of(out, domain);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_Elimination<2, true>)->ArgsProduct({{10'000, 100'000, 1'000'000}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Elimination<2, false>)->Args({1'000'000, 0})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Elimination<3, true>)->Args({100'000, 0})->Unit(benchmark::kMillisecond);

// elimination() as `pds generate elimination` runs it: 5N white-noise
// candidates drawn inside the timing, the progressive order, then min_rho's
// moves of the closest pairs (second argument: min_rho x 100; 0 is the
// paper's set, a subset of the candidates; third: 1 builds the order in
// levels, EliminationParams::levels). Counters: rho of the set and of its
// first 1%, 10% and 50%.
template <int D>
void BM_EliminationMinRho(benchmark::State& state) {
  const auto domain = pds::Domain<D>::unit(true);
  const auto n = static_cast<std::uint64_t>(state.range(0));
  const double min_rho = static_cast<double>(state.range(1)) / 100.0;
  const bool levels = state.range(2) != 0;
  pds::PointSet<D> out;
  for (auto _ : state) {
    out = pds::elimination<D>({.count = n, .min_rho = min_rho, .levels = levels}, domain, 1);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["rho"] = rho_of(out, domain);
  for (const auto& [name, percent] :
       {std::pair{"rho_1pct", 1}, std::pair{"rho_10pct", 10}, std::pair{"rho_50pct", 50}}) {
    const pds::PointSet<D> prefix(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n * percent / 100));
    state.counters[name] = rho_of(prefix, domain);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_EliminationMinRho<2>)
    ->ArgsProduct({{100'000, 1'000'000}, {0, 72}, {0}})
    ->Args({100'000, 72, 1})
    ->Args({1'000'000, 72, 1})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EliminationMinRho<3>)
    ->ArgsProduct({{100'000}, {0, 72}, {0}})
    ->Args({100'000, 72, 1})
    ->Unit(benchmark::kMillisecond);

#ifdef PDS_BENCH_CYCODEBASE
// cySampleElim with its defaults (alpha 8, beta 0.65, gamma 1.5, weight
// limiting on), tiling on (the torus), on the same candidates.
void BM_EliminationCyCodeBase(benchmark::State& state) {
  const auto domain = pds::Domain<2>::unit(true);
  const auto n = static_cast<std::size_t>(state.range(0));
  const bool progressive = state.range(1) != 0;
  const pds::PointSet<2> candidates = pds::white_noise<2>({.count = 5 * n}, domain, 1);
  std::vector<cy::Vec2d> in(candidates.size()), out(n);
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = cy::Vec2d(candidates[i][0], candidates[i][1]);
  cy::WeightedSampleElimination<cy::Vec2d, double, 2, std::size_t> wse;
  wse.SetTiling(true);
  for (auto _ : state) {
    wse.Eliminate(in.data(), in.size(), out.data(), out.size(), progressive);
    benchmark::DoNotOptimize(out.data());
  }
  pds::PointSet<2> result(n);
  for (std::size_t i = 0; i < n; ++i) result[i] = {out[i].x, out[i].y};
  state.counters["rho"] = rho_of(result, domain);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_EliminationCyCodeBase)->ArgsProduct({{10'000, 100'000, 1'000'000}, {0, 1}})->Unit(benchmark::kMillisecond);
#endif

}  // namespace
