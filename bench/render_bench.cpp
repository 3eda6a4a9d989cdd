// Benchmarks of the renderer (docs/rendering.md): a 512 x 512 image at 4 spp through
// each sampler and filter, on 1 and all threads; the per-pixel jittered
// sampler is the baseline the tiled ones are measured against. Also the tiled
// pattern's rectangle queries and the torus discrepancy sweep.
#include <benchmark/benchmark.h>

#include <string>

#include "pds/registry.h"
#include "pds/render/render.h"
#include "pds/rng.h"
#include "pds/tiling/tiled_pattern.h"

namespace {

constexpr int kSide = 512;

// Samplers to time: per pixel, then tiled from registry methods (whichever of
// these the registry has).
std::vector<std::string> bench_samplers() {
  std::vector<std::string> names = {"random", "jittered", "sobol-pixel", "tiled:jittered"};
  for (const char* m : {"best-candidate", "bridson", "dart-throwing", "sobol"})
    for (const pds::Method& method : pds::methods())
      if (method.name == m) names.push_back(m);
  return names;
}

void render_bench(benchmark::State& state, const std::string& sampler_name, const std::string& filter, int threads) {
  const pds::CheckerboardScene scene(kSide, kSide);
  const auto sampler = pds::make_image_sampler(sampler_name, {.spp = 4, .seed = 1});  // tile made here, untimed
  const pds::RenderOptions options{pds::parse_filter(filter), threads};
  pds::RenderStats stats;
  for (auto _ : state) benchmark::DoNotOptimize(pds::render(scene, *sampler, kSide, kSide, options, &stats));
  state.SetItemsProcessed(state.iterations() * kSide * kSide * 4);  // samples (before the block margins)
  state.counters["evaluated"] = static_cast<double>(stats.samples);
}

const bool registered = [] {
  for (const std::string& s : bench_samplers())
    for (int threads : {1, 0})
      benchmark::RegisterBenchmark(("BM_Render512x4spp/" + s + "/gaussian/threads:" + (threads ? "1" : "all")).c_str(),
                                   [=](benchmark::State& st) { render_bench(st, s, "gaussian", threads); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
  for (const std::string& f : pds::filter_names())
    benchmark::RegisterBenchmark(("BM_Render512x4spp/jittered/" + f + "/threads:all").c_str(),
                                 [=](benchmark::State& st) { render_bench(st, "jittered", f, 0); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  return true;
}();

// One pixel-sized query at a random place: what a renderer asks per pixel.
void BM_TiledPixelQuery(benchmark::State& state) {
  pds::GenerateRequest request;
  request.torus = true;
  request.count = 4096;
  request.seed = 1;
  const pds::TiledPattern pattern(pds::generate("jittered", request).as<2>(), static_cast<double>(state.range(0)));
  pds::Rng rng(2);
  std::vector<pds::Point<2>> out;
  for (auto _ : state) {
    out.clear();
    const double x = std::floor(rng.uniform(-1e5, 1e5)), y = std::floor(rng.uniform(-1e5, 1e5));
    pattern.samples_in({x, y, x + 1, y + 1}, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TiledPixelQuery)->Arg(1)->Arg(4)->Arg(16);

void BM_TorusDiscrepancy(benchmark::State& state) {
  pds::GenerateRequest request;
  request.torus = true;
  request.count = static_cast<std::uint64_t>(state.range(0));
  const auto tile = pds::generate("jittered", request).as<2>();
  for (auto _ : state) benchmark::DoNotOptimize(pds::torus_rectangle_discrepancy(tile));
}
BENCHMARK(BM_TorusDiscrepancy)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace
