// thinks/poisson-disk-sampling, C++ template release v0.3 (tag v0.3, commit
// cbb67bf): thinks::PoissonDiskSampling(radius, x_min, x_max, k, seed) on the
// unit square or cube (a box: it has no tiling), float coordinates.
// Times only that call. Usage: thinks_v03 DIM RADIUS [K=30] [SEED=0] [OUT.csv]
#include <array>
#include <cstdio>
#include <cstdlib>

#include "thinks/poisson_disk_sampling/poisson_disk_sampling.h"
#include "timing.h"

template <std::size_t N>
int run(float radius, std::uint32_t k, std::uint32_t seed, const char* out) {
  std::array<float, N> lo{}, hi{};
  hi.fill(1.0f);
  const double c0 = pds_peer_now(CLOCK_THREAD_CPUTIME_ID), w0 = pds_peer_now(CLOCK_MONOTONIC);
  const auto samples = thinks::PoissonDiskSampling(radius, lo, hi, k, seed);
  const double c1 = pds_peer_now(CLOCK_THREAD_CPUTIME_ID), w1 = pds_peer_now(CLOCK_MONOTONIC);
  pds_peer_report("thinks-v0.3", static_cast<int>(N), samples.size(), c1 - c0, w1 - w0);
  if (out) {
    FILE* f = std::fopen(out, "w");
    std::fputs(N == 2 ? "x,y\n" : "x,y,z\n", f);
    for (const auto& p : samples) {
      for (std::size_t i = 0; i < N; ++i) std::fprintf(f, i + 1 < N ? "%.9g," : "%.9g\n", static_cast<double>(p[i]));
    }
    std::fclose(f);
  }
  return 0;
}

int main(int argc, char** argv) {
  if (argc < 3) return std::fprintf(stderr, "usage: %s DIM RADIUS [K] [SEED] [OUT.csv]\n", argv[0]), 2;
  const int dim = std::atoi(argv[1]);
  const float r = std::strtof(argv[2], nullptr);
  const auto k = static_cast<std::uint32_t>(argc > 3 ? std::atoi(argv[3]) : 30);
  const auto seed = static_cast<std::uint32_t>(argc > 4 ? std::atoi(argv[4]) : 0);
  const char* out = argc > 5 ? argv[5] : nullptr;
  return dim == 3 ? run<3>(r, k, seed, out) : run<2>(r, k, seed, out);
}
