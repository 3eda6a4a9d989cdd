// Benchmarks of the stratified and low-discrepancy patterns (docs/low-discrepancy.md) at
// N = 10^6 points: each iteration builds the whole PointSet (allocation
// included) in the unit square/cube, single-threaded. Peers in the same run:
// white noise (one xoshiro draw per coordinate) and GSL's gsl_qrng_sobol /
// gsl_qrng_halton stepping through the same points into the same layout.
#include <benchmark/benchmark.h>
#include <gsl/gsl_qrng.h>

#include <algorithm>
#include <vector>

#include "pds/samplers/halton.h"
#include "pds/samplers/hammersley.h"
#include "pds/samplers/latin_hypercube.h"
#include "pds/samplers/multi_jittered.h"
#include "pds/samplers/random.h"
#include "pds/samplers/sobol.h"

namespace {

constexpr std::uint64_t kN = 1'000'000;

template <int D>
void BM_Sobol(benchmark::State& state) {
  const auto scramble = static_cast<pds::Scramble>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(pds::sobol<D>({kN, 0, scramble}, pds::Domain<D>::unit(), 1));
  state.SetItemsProcessed(state.iterations() * kN);
}
BENCHMARK(BM_Sobol<2>)->ArgName("scramble")->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Sobol<3>)->ArgName("scramble")->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

void BM_SobolLaterRange2D(benchmark::State& state) {
  // 10^6 points starting at index 3 * 10^9: costs the same as the first 10^6.
  for (auto _ : state) benchmark::DoNotOptimize(pds::sobol<2>({kN, 3'000'000'000ull}, pds::Domain<2>::unit(), 1));
  state.SetItemsProcessed(state.iterations() * kN);
}
BENCHMARK(BM_SobolLaterRange2D)->Unit(benchmark::kMillisecond);

// Sobol in 1,000 dimensions x 10^6 points (10^9 doubles, issue 15), filled
// 10^4 points (80 MB, far past the caches) at a time into one buffer, against
// writing the same 10^9 doubles into that buffer (std::fill): the sequence's
// cost over the cost of its output alone.
constexpr int kWideDim = 1000;
constexpr std::uint64_t kWideBlock = 10'000, kWideBlocks = 100;

void BM_SobolWide(benchmark::State& state) {
  const auto scramble = static_cast<pds::Scramble>(state.range(0));
  const pds::CloudBox box = pds::CloudBox::unit(kWideDim);
  std::vector<double> buffer(kWideBlock * kWideDim);
  for (auto _ : state) {
    for (std::uint64_t k = 0; k < kWideBlocks; ++k)
      pds::sobol_fill({kWideBlock, k * kWideBlock, scramble}, box, 1, buffer.data());
    benchmark::DoNotOptimize(buffer.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kWideBlock * kWideBlocks * kWideDim));
}
BENCHMARK(BM_SobolWide)->ArgName("scramble")->DenseRange(0, 2)->Iterations(1)->Unit(benchmark::kMillisecond);

// The same through the run-time entry point, a new PointCloud per block (as
// pds generate and pds.generate get them): allocation and first touch included.
void BM_SobolWideCloud(benchmark::State& state) {
  const pds::CloudBox box = pds::CloudBox::unit(kWideDim);
  for (auto _ : state)
    for (std::uint64_t k = 0; k < kWideBlocks; ++k)
      benchmark::DoNotOptimize(pds::sobol({kWideBlock, k * kWideBlock}, box, 1));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kWideBlock * kWideBlocks * kWideDim));
}
BENCHMARK(BM_SobolWideCloud)->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_WriteDoublesWide(benchmark::State& state) {
  std::vector<double> buffer(kWideBlock * kWideDim);
  for (auto _ : state) {
    for (std::uint64_t k = 0; k < kWideBlocks; ++k) {
      std::fill(buffer.begin(), buffer.end(), static_cast<double>(k));
      benchmark::DoNotOptimize(buffer.data());
      benchmark::ClobberMemory();
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kWideBlock * kWideBlocks * kWideDim));
}
BENCHMARK(BM_WriteDoublesWide)->Iterations(1)->Unit(benchmark::kMillisecond);

template <int D>
void BM_Halton(benchmark::State& state) {
  const auto scramble = static_cast<pds::Scramble>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(pds::halton<D>({kN, 0, scramble}, pds::Domain<D>::unit(), 1));
  state.SetItemsProcessed(state.iterations() * kN);
}
BENCHMARK(BM_Halton<2>)->ArgName("scramble")->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Halton<3>)->ArgName("scramble")->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

void BM_Hammersley2D(benchmark::State& state) {
  const auto scramble = static_cast<pds::Scramble>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(pds::hammersley<2>({kN, 0, 0, scramble}, pds::Domain<2>::unit(), 1));
  state.SetItemsProcessed(state.iterations() * kN);
}
BENCHMARK(BM_Hammersley2D)->ArgName("scramble")->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

void BM_MultiJittered2D(benchmark::State& state) {
  const pds::MultiJitteredParams params{{1000, 1000, 1}, state.range(0) != 0};
  for (auto _ : state) benchmark::DoNotOptimize(pds::multi_jittered<2>(params, pds::Domain<2>::unit(), 1));
  state.SetItemsProcessed(state.iterations() * kN);
}
BENCHMARK(BM_MultiJittered2D)->ArgName("correlated")->DenseRange(0, 1)->Unit(benchmark::kMillisecond);

void BM_MultiJittered3D(benchmark::State& state) {
  const pds::MultiJitteredParams params{{100, 100, 100}, state.range(0) != 0};
  for (auto _ : state) benchmark::DoNotOptimize(pds::multi_jittered<3>(params, pds::Domain<3>::unit(), 1));
  state.SetItemsProcessed(state.iterations() * kN);
}
BENCHMARK(BM_MultiJittered3D)->ArgName("correlated")->DenseRange(0, 1)->Unit(benchmark::kMillisecond);

template <int D>
void BM_LatinHypercube(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(pds::latin_hypercube<D>({kN}, pds::Domain<D>::unit(), 1));
  state.SetItemsProcessed(state.iterations() * kN);
}
BENCHMARK(BM_LatinHypercube<2>)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LatinHypercube<3>)->Unit(benchmark::kMillisecond);

template <int D>
void BM_WhiteNoiseBaseline(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(pds::white_noise<D>({kN}, pds::Domain<D>::unit(), 1));
  state.SetItemsProcessed(state.iterations() * kN);
}
BENCHMARK(BM_WhiteNoiseBaseline<2>)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WhiteNoiseBaseline<3>)->Unit(benchmark::kMillisecond);

template <int D>
void gsl_peer(benchmark::State& state, const gsl_qrng_type* type) {
  for (auto _ : state) {
    gsl_qrng* q = gsl_qrng_alloc(type, D);
    pds::PointSet<D> points(kN);
    for (auto& p : points) gsl_qrng_get(q, p.data());
    gsl_qrng_free(q);
    benchmark::DoNotOptimize(points);
  }
  state.SetItemsProcessed(state.iterations() * kN);
}
void BM_GslSobol2D(benchmark::State& state) { gsl_peer<2>(state, gsl_qrng_sobol); }
void BM_GslHalton2D(benchmark::State& state) { gsl_peer<2>(state, gsl_qrng_halton); }
void BM_GslSobol3D(benchmark::State& state) { gsl_peer<3>(state, gsl_qrng_sobol); }
void BM_GslHalton3D(benchmark::State& state) { gsl_peer<3>(state, gsl_qrng_halton); }
BENCHMARK(BM_GslSobol2D)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GslHalton2D)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GslSobol3D)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GslHalton3D)->Unit(benchmark::kMillisecond);

}  // namespace
