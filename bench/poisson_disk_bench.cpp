// Benchmarks of the Poisson disk methods dart throwing, Bridson and
// best-candidate (docs/benchmarks.md, section "Poisson disk"). Items/s is samples produced per second
// on one thread.
//
//   build/bench/pds_bench --benchmark_filter='Bridson|Dart|BestCandidate'
//
// BM_BridsonTextbook is the peer measured in the same run: the usual
// straightforward implementation (grid of sample indices, polar candidates
// with sin/cos/sqrt, all 5x5 (5x5x5) neighbour cells scanned with bounds
// checks), written here because the sandbox cannot fetch other libraries.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "pds/rng.h"
#include "pds/samplers/best_candidate.h"
#include "pds/samplers/bridson.h"
#include "pds/samplers/dart_throwing.h"
#include "pds/samplers/random.h"
#include "pds/samplers/sizing.h"

namespace {

// The radius at which a maximal Bridson set holds about n samples
// (relative radius ~0.73 in 2D, ~0.74 in 3D on the torus).
template <int D>
double bridson_radius(double n, const pds::Domain<D>& domain) {
  return pds::radius_for_count(static_cast<std::uint64_t>(n), domain, D == 2 ? 0.73 : 0.74);
}

template <int D, bool Torus>
void BM_Bridson(benchmark::State& state) {
  const auto domain = pds::Domain<D>::unit(Torus);
  pds::BridsonParams params;
  params.radius = bridson_radius<D>(static_cast<double>(state.range(0)), domain);
  std::size_t n = 0;
  for (auto _ : state) {
    const auto points = pds::bridson(params, domain, 1);
    n = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  state.counters["samples"] = static_cast<double>(n);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_Bridson<2, true>)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Bridson<2, false>)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Bridson<3, true>)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Bridson<3, false>)->Arg(100'000)->Unit(benchmark::kMillisecond);

// The textbook Bridson on the unit box (2D), k = 30.
std::vector<std::array<double, 2>> textbook_bridson(double r, std::uint64_t seed) {
  pds::Rng rng(seed);
  const double cell = r / std::sqrt(2.0);
  const int n = static_cast<int>(std::ceil(1.0 / cell));
  std::vector<int> grid(static_cast<std::size_t>(n) * n, -1);
  std::vector<std::array<double, 2>> points;
  std::vector<int> active;
  auto cell_of = [&](double x) { return std::min(n - 1, static_cast<int>(x / cell)); };
  auto add = [&](std::array<double, 2> p) {
    grid[static_cast<std::size_t>(cell_of(p[1])) * n + cell_of(p[0])] = static_cast<int>(points.size());
    active.push_back(static_cast<int>(points.size()));
    points.push_back(p);
  };
  add({rng.uniform(), rng.uniform()});
  while (!active.empty()) {
    const std::size_t slot = rng.below(active.size());
    const auto centre = points[static_cast<std::size_t>(active[slot])];
    bool found = false;
    for (int t = 0; t < 30 && !found; ++t) {
      const double angle = 2.0 * M_PI * rng.uniform();
      const double radius = std::sqrt(r * r + 3.0 * r * r * rng.uniform());  // uniform by area in [r, 2r]
      const std::array<double, 2> c{centre[0] + radius * std::cos(angle), centre[1] + radius * std::sin(angle)};
      if (c[0] < 0 || c[0] >= 1 || c[1] < 0 || c[1] >= 1) continue;
      const int cx = cell_of(c[0]), cy = cell_of(c[1]);
      bool ok = true;
      for (int y = std::max(0, cy - 2); ok && y <= std::min(n - 1, cy + 2); ++y)
        for (int x = std::max(0, cx - 2); ok && x <= std::min(n - 1, cx + 2); ++x) {
          const int q = grid[static_cast<std::size_t>(y) * n + x];
          if (q < 0) continue;
          const double dx = points[q][0] - c[0], dy = points[q][1] - c[1];
          ok = dx * dx + dy * dy >= r * r;
        }
      if (ok) {
        add(c);
        found = true;
      }
    }
    if (!found) {
      active[slot] = active.back();
      active.pop_back();
    }
  }
  return points;
}

void BM_BridsonTextbook(benchmark::State& state) {
  const double r = bridson_radius<2>(static_cast<double>(state.range(0)), pds::Domain<2>::unit());
  std::size_t n = 0;
  for (auto _ : state) {
    const auto points = textbook_bridson(r, 1);
    n = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  state.counters["samples"] = static_cast<double>(n);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_BridsonTextbook)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

// Dart throwing with a count (relative radius 0.70, the --count default): the
// textbook loop stopped at N.
template <int D>
void BM_DartThrowingCount(benchmark::State& state) {
  const auto domain = pds::Domain<D>::unit(true);
  pds::DartThrowingParams params;
  params.count = static_cast<std::uint64_t>(state.range(0));
  params.radius = pds::radius_for_count(*params.count, domain, pds::kDartCountRho);
  params.all_pairs = state.range(1) != 0;
  for (auto _ : state) benchmark::DoNotOptimize(pds::dart_throwing(params, domain, 1).data());
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_DartThrowingCount<2>)
    ->Args({10'000, 0})
    ->Args({100'000, 0})
    ->Args({1'000'000, 0})
    ->Args({10'000, 1})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DartThrowingCount<3>)->Args({100'000, 0})->Unit(benchmark::kMillisecond);

// Dart throwing with a radius only: until the failure bound (near-maximal).
template <int D>
void BM_DartThrowingToExhaustion(benchmark::State& state) {
  const auto domain = pds::Domain<D>::unit(true);
  pds::DartThrowingParams params;
  params.radius = pds::radius_for_count(static_cast<std::uint64_t>(state.range(0)), domain, D == 2 ? 0.765 : 0.77);
  std::size_t n = 0;
  for (auto _ : state) {
    const auto points = pds::dart_throwing(params, domain, 1);
    n = points.size();
    benchmark::DoNotOptimize(points.data());
  }
  state.counters["samples"] = static_cast<double>(n);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_DartThrowingToExhaustion<2>)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);

// Best-candidate with a count, on the unit torus (args: count, m).
template <int D>
void BM_BestCandidate(benchmark::State& state) {
  const auto domain = pds::Domain<D>::unit(true);
  pds::BestCandidateParams params;
  params.count = static_cast<std::uint64_t>(state.range(0));
  params.m = static_cast<int>(state.range(1));
  for (auto _ : state) benchmark::DoNotOptimize(pds::best_candidate(params, domain, 1).data());
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_BestCandidate<2>)
    ->Args({1'000, 10})
    ->Args({10'000, 10})
    ->Args({10'000, 1})
    ->Args({100'000, 10})
    ->Args({1'000'000, 10})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BestCandidate<3>)
    ->Args({1'000, 10})
    ->Args({10'000, 10})
    ->Args({100'000, 10})
    ->Unit(benchmark::kMillisecond);

}  // namespace
