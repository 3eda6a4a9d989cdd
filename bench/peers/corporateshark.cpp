// corporateshark/poisson-disk-generator (commit 5339f69, v1.7.0):
// PoissonGenerator::generatePoissonPoints(numPoints, prng, isCircle = false,
// newPointsCount = K, minDist = RADIUS) on the unit square (a box: it has no
// tiling), float coordinates. numPoints is set far above what fits, so the loop
// runs until its process list is empty. Times only that call.
// Usage: corporateshark RADIUS [K=30] [SEED=0: its default] [OUT.csv]
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "PoissonGenerator.h"
#include "timing.h"

int main(int argc, char** argv) {
  if (argc < 2) return std::fprintf(stderr, "usage: %s RADIUS [K] [SEED] [OUT.csv]\n", argv[0]), 2;
  const float r = std::strtof(argv[1], nullptr);
  const auto k = static_cast<std::uint32_t>(argc > 2 ? std::atoi(argv[2]) : 30);
  // Its PRNG is multiplicative: seed 0 would stay 0, so SEED 0 means its default seed.
  PoissonGenerator::DefaultPRNG prng = argc > 3 && std::atoi(argv[3]) != 0 ? PoissonGenerator::DefaultPRNG(std::atoi(argv[3])) : PoissonGenerator::DefaultPRNG();
  // 2 / r^2 is above the densest packing (2 / (sqrt(3) r^2)); the library
  // doubles it and scales by pi/4 for the square, still above.
  const auto cap = static_cast<std::uint32_t>(std::ceil(2.0 / (double(r) * r)));
  const double c0 = pds_peer_now(CLOCK_THREAD_CPUTIME_ID), w0 = pds_peer_now(CLOCK_MONOTONIC);
  const auto pts = PoissonGenerator::generatePoissonPoints(cap, prng, false, k, r);
  const double c1 = pds_peer_now(CLOCK_THREAD_CPUTIME_ID), w1 = pds_peer_now(CLOCK_MONOTONIC);
  pds_peer_report("corporateshark", 2, pts.size(), c1 - c0, w1 - w0);
  if (argc > 4) {
    FILE* f = std::fopen(argv[4], "w");
    std::fputs("x,y\n", f);
    for (const auto& p : pts) std::fprintf(f, "%.9g,%.9g\n", double(p.x), double(p.y));
    std::fclose(f);
  }
  return 0;
}
