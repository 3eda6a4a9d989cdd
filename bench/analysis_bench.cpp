// Benchmarks of the analysis (docs/analysis.md): the exact periodogram against the
// textbook direct DFT (one cos/sin pair per point and frequency, one thread),
// the pair correlation function and the L2-star discrepancy.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "pds/analysis/discrepancy.h"
#include "pds/analysis/pair_correlation.h"
#include "pds/parallel.h"
#include "pds/analysis/spectrum.h"
#include "pds/samplers/random.h"

namespace {

std::vector<pds::PointSet<2>> sets_of(std::size_t m, std::uint64_t n) {
  std::vector<pds::PointSet<2>> sets;
  for (std::size_t s = 0; s < m; ++s) sets.push_back(pds::white_noise<2>({n}, pds::Domain<2>::unit(true), s));
  return sets;
}

/// The target: 10 sets of 4096 points at 257 x 257 frequencies (K = 128).
/// Argument: threads.
void BM_Periodogram_10x4096_K128(benchmark::State& state) {
  pds::ThreadLimit limit(static_cast<int>(state.range(0)));
  const auto sets = sets_of(10, 4096);
  for (auto _ : state)
    benchmark::DoNotOptimize(pds::periodogram<2>(sets, pds::Domain<2>::unit(true), {.max_frequency = 128}));
  state.counters["point_freqs_per_s"] =
      benchmark::Counter(10.0 * 4096 * 257 * 257, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Periodogram_10x4096_K128)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Baseline: the direct DFT from the definition, every frequency of the cube,
/// for ONE set of 4096 points at K = 128 (multiply by 10 for the target).
void BM_NaiveDft_1x4096_K128(benchmark::State& state) {
  const auto points = sets_of(1, 4096)[0];
  const int K = 128;
  std::vector<double> power((2 * K + 1) * (2 * K + 1));
  for (auto _ : state) {
    for (int ky = -K; ky <= K; ++ky)
      for (int kx = -K; kx <= K; ++kx) {
        double re = 0, im = 0;
        for (const auto& p : points) {
          const double angle = -2.0 * std::numbers::pi * (kx * p[0] + ky * p[1]);
          re += std::cos(angle);
          im += std::sin(angle);
        }
        power[(ky + K) * (2 * K + 1) + kx + K] = (re * re + im * im) / points.size();
      }
    benchmark::DoNotOptimize(power.data());
  }
  state.counters["point_freqs_per_s"] =
      benchmark::Counter(4096.0 * 257 * 257, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_NaiveDft_1x4096_K128)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

void BM_PairCorrelation_10x4096(benchmark::State& state) {
  const auto sets = sets_of(10, 4096);
  for (auto _ : state) benchmark::DoNotOptimize(pds::pair_correlation<2>(sets, pds::Domain<2>::unit(true)));
}
BENCHMARK(BM_PairCorrelation_10x4096)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_L2StarDiscrepancy_4096(benchmark::State& state) {
  const auto points = sets_of(1, 4096)[0];
  for (auto _ : state) benchmark::DoNotOptimize(pds::l2_star_discrepancy<2>(points, pds::Domain<2>::unit()));
}
BENCHMARK(BM_L2StarDiscrepancy_4096)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
