// Benchmarks of the fast Poisson disk methods (docs/benchmarks.md): Dunbar & Humphreys
// boundary sampling and scalloped sectors, Wei's parallel sampler and Jones's Voronoi sampler, on the
// 2D unit torus. The argument is the target sample count N; the radius is set
// from each method's measured density so that it makes about N samples, and
// the counters report the real count, rho and the peak memory.
//
// Peak memory: run one benchmark per process (--benchmark_filter) and read
// peak_rss_MB, the growth of the process's high-water resident set over the
// run, against output_MB, the size of the returned points.
#include <benchmark/benchmark.h>

#include <cmath>

#include "pds/analysis/distance.h"
#include "pds/analysis/relative_radius.h"
#include "pds/samplers/dart_throwing.h"
#include "pds/samplers/dunbar_humphreys.h"
#include "pds/samplers/ebeida.h"
#include "pds/samplers/jones.h"
#include "pds/samplers/maximal_darts.h"
#include "pds/samplers/wei.h"
#include "peak_rss.h"

namespace {

using pds_bench::peak_rss_mb;

/// Runs `make(radius)` and reports samples/s, rho and memory. `density` is the
/// method's N r^2 on the unit square (measured), so radius = sqrt(density / N).
template <class Make>
void run(benchmark::State& state, double density, Make make) {
  const double radius = std::sqrt(density / static_cast<double>(state.range(0)));
  const double rss_before = peak_rss_mb();
  std::size_t count = 0;
  for (auto _ : state) {
    auto points = make(radius);
    count = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  // Read before the analysis below, which allocates its own grid.
  const double peak = peak_rss_mb() - rss_before;
  const auto points = make(radius);
  const auto domain = pds::Domain<2>::unit(true);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * count));
  state.counters["N"] = static_cast<double>(count);
  state.counters["rho"] =
      pds::relative_radius(pds::min_distance(points, domain).distance, domain.volume(), points.size(), 2);
  state.counters["output_MB"] = static_cast<double>(points.size() * sizeof(points[0])) / (1024.0 * 1024.0);
  state.counters["peak_rss_MB"] = peak;
}

void BM_DunbarHumphreys(benchmark::State& state) {
  run(state, 0.875, [](double r) { return pds::dunbar_humphreys({r}, pds::Domain<2>::unit(true), 1); });
}
BENCHMARK(BM_DunbarHumphreys)->RangeMultiplier(10)->Range(10'000, 10'000'000)->Unit(benchmark::kMillisecond);

/// The same boundary sampling on its scalar kernel (what a processor without
/// AVX-512 runs; the same bytes).
void BM_DunbarHumphreysScalar(benchmark::State& state) {
  run(state, 0.875,
      [](double r) { return pds::detail::dunbar_humphreys_boundary({r}, pds::Domain<2>::unit(true), 1, false); });
}
BENCHMARK(BM_DunbarHumphreysScalar)->Arg(10'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

/// The paper's scalloped sectors (variant 1): new samples uniform over the free annulus r..2r.
void BM_DunbarHumphreysSectors(benchmark::State& state) {
  run(state, 0.735, [](double r) {
    pds::DunbarHumphreysParams params{r};
    params.variant = 1;
    return pds::dunbar_humphreys(params, pds::Domain<2>::unit(true), 1);
  });
}
// Up to 10^6: 10^7 takes about 5 minutes at this rate.
BENCHMARK(BM_DunbarHumphreysSectors)->RangeMultiplier(10)->Range(10'000, 1'000'000)->Unit(benchmark::kMillisecond);

/// Variant 2: scalloped sectors, the next sample uniform over all front regions.
void BM_DunbarHumphreysGlobalSectors(benchmark::State& state) {
  run(state, 0.694, [](double r) {
    pds::DunbarHumphreysParams params{r};
    params.variant = 2;
    return pds::dunbar_humphreys(params, pds::Domain<2>::unit(true), 1);
  });
}
// Up to 10^6: about 5.5 minutes at that size on this machine (run() builds the set twice).
BENCHMARK(BM_DunbarHumphreysGlobalSectors)
    ->RangeMultiplier(10)
    ->Range(10'000, 1'000'000)
    ->Unit(benchmark::kMillisecond);

/// Wei with state.range(1) threads.
void BM_Wei(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(1));
  run(state, 0.70, [&](double r) {
    pds::WeiParams params;
    params.radius = r;
    params.threads = threads;
    return pds::wei<2>(params, pds::Domain<2>::unit(true), 1);
  });
}
BENCHMARK(BM_Wei)
    ->ArgsProduct({{10'000, 100'000, 1'000'000, 10'000'000}, {1}})
    ->ArgsProduct({{1'000'000}, {2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_Jones(benchmark::State& state) {
  run(state, 0.684, [](double r) { return pds::jones({r}, pds::Domain<2>::unit(true), 1); });
}
// Up to 10^6: 10^7 takes about 3 minutes a run here (2.2 GB), and run() makes
// the set twice.
BENCHMARK(BM_Jones)->RangeMultiplier(10)->Range(10'000, 1'000'000)->Unit(benchmark::kMillisecond);

/// Maximal dart throwing on a flat quadtree, darts swept in time order.
void BM_Ebeida(benchmark::State& state) {
  run(state, 0.6965, [](double r) { return pds::ebeida<2>({r}, pds::Domain<2>::unit(true), 1); });
}
BENCHMARK(BM_Ebeida)->RangeMultiplier(10)->Range(10'000, 10'000'000)->Unit(benchmark::kMillisecond);

/// 3D unit torus: N r^3 = 0.7336 at saturation (coverage 0.3841 of balls of diameter r).
void BM_Ebeida3D(benchmark::State& state) {
  const double radius = std::cbrt(0.7336 / static_cast<double>(state.range(0)));
  std::size_t count = 0;
  for (auto _ : state) {
    const auto points = pds::ebeida<3>({radius}, pds::Domain<3>::unit(true), 1);
    count = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * count));
  state.counters["N"] = static_cast<double>(count);
}
BENCHMARK(BM_Ebeida3D)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

/// Maximal dart throwing decided window by window, state.range(1) threads
/// (the same samples for every count).
void BM_MaximalDarts(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(1));
  run(state, 0.6965, [&](double r) { return pds::maximal_darts<2>({r, threads}, pds::Domain<2>::unit(true), 1); });
}
BENCHMARK(BM_MaximalDarts)
    ->ArgsProduct({{10'000, 100'000, 1'000'000, 10'000'000}, {1}})
    ->ArgsProduct({{1'000'000, 10'000'000}, {2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// The same on the 3D unit torus (N r^3 = 0.7336 at saturation).
void BM_MaximalDarts3D(benchmark::State& state) {
  const double radius = std::cbrt(0.7336 / static_cast<double>(state.range(0)));
  const int threads = static_cast<int>(state.range(1));
  std::size_t count = 0;
  for (auto _ : state) {
    const auto points = pds::maximal_darts<3>({radius, threads}, pds::Domain<3>::unit(true), 1);
    count = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * count));
  state.counters["N"] = static_cast<double>(count);
}
BENCHMARK(BM_MaximalDarts3D)->ArgsProduct({{100'000, 1'000'000}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();

// The baseline: dart throwing with its default failure bound, which
// stops near rho 0.75 without maximality. Its failure bound grows with N, so
// the cost is superlinear; 10^6 takes longer than a benchmark run should.
void BM_DartThrowingBaseline(benchmark::State& state) {
  run(state, 0.66, [](double r) { return pds::dart_throwing<2>({r}, pds::Domain<2>::unit(true), 1); });
}
BENCHMARK(BM_DartThrowingBaseline)->RangeMultiplier(10)->Range(10'000, 100'000)->Unit(benchmark::kMillisecond);

}  // namespace
