// cyCodeBase's cySampleElim.h (C. Yuksel; commit 348dad1): weighted sample
// elimination with its defaults (alpha 8, beta 0.65, gamma 1.5, weight limiting
// on), tiling on (the unit torus), from 5 N uniform candidates drawn outside the
// timing (std::mt19937_64), double coordinates, not progressive. Built without
// OpenMP: one thread. Times only Eliminate. Usage: cyse N [SEED=1] [OUT.csv]
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "cySampleElim.h"
#include "cyVector.h"
#include "timing.h"

int main(int argc, char** argv) {
  if (argc < 2) return std::fprintf(stderr, "usage: %s N [SEED] [OUT.csv]\n", argv[0]), 2;
  const auto n = static_cast<std::size_t>(std::atoll(argv[1]));
  std::mt19937_64 rng(argc > 2 ? std::atoll(argv[2]) : 1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<cy::Vec2d> in(5 * n), out(n);
  for (auto& p : in) {
    const double x = u(rng);
    p = cy::Vec2d(x, u(rng));
  }
  cy::WeightedSampleElimination<cy::Vec2d, double, 2, std::size_t> wse;
  wse.SetTiling(true);
  const double c0 = pds_peer_now(CLOCK_THREAD_CPUTIME_ID), w0 = pds_peer_now(CLOCK_MONOTONIC);
  wse.Eliminate(in.data(), in.size(), out.data(), out.size(), false);
  const double c1 = pds_peer_now(CLOCK_THREAD_CPUTIME_ID), w1 = pds_peer_now(CLOCK_MONOTONIC);
  pds_peer_report("cySampleElim", 2, out.size(), c1 - c0, w1 - w0);
  if (argc > 3) {
    FILE* f = std::fopen(argv[3], "w");
    std::fputs("x,y\n", f);
    for (const auto& p : out) std::fprintf(f, "%.17g,%.17g\n", p.x, p.y);
    std::fclose(f);
  }
  return 0;
}
