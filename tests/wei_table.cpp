// The measurements of docs/wei.md: wei against maximal dart throwing (jones)
// on the unit torus, per-set statistics and the radial power per annulus.
//
//   build/tests/wei_table [sets=16] [radius=0.02] [windows=64] [levels=10] [k=2]
//
// Prints the mean count, rho (at the radius), mean nearest-neighbour distance
// and the uncovered fraction (400,000 random probes per set farther than the
// radius from every sample) for both, with Welch t, then for each annulus
// 1-48 the power ratio wei / dart throwing and its Welch t. Seeds 1..sets for
// wei, 101.. for jones, as in wei_test.cpp. Not a test: the assertions are in
// src/pds/samplers/wei_test.cpp.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "nn_statistics.h"
#include "pds/analysis/relative_radius.h"
#include "pds/rng.h"
#include "pds/samplers/jones.h"
#include "pds/samplers/wei.h"

namespace {

using namespace pds;

double mean(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m += x;
  return m / static_cast<double>(v.size());
}

/// Fraction of random probes farther than r from every sample (unit torus).
double uncovered(const PointSet<2>& points, double r, std::uint64_t seed) {
  const Domain<2> domain = Domain<2>::unit(true);
  const int n = static_cast<int>(1.0 / r);  // buckets of edge >= r
  auto bucket = [n](double x) { return std::min(n - 1, static_cast<int>(x * n)); };
  std::vector<std::vector<std::size_t>> buckets(static_cast<std::size_t>(n * n));
  for (std::size_t i = 0; i < points.size(); ++i)
    buckets[static_cast<std::size_t>(bucket(points[i][1]) * n + bucket(points[i][0]))].push_back(i);
  Rng rng(seed, {0x70be});
  constexpr int kProbes = 400000;
  int misses = 0;
  for (int k = 0; k < kProbes; ++k) {
    const Point<2> p{{rng.uniform(), rng.uniform()}};
    bool covered = false;
    for (int dy = -1; dy <= 1 && !covered; ++dy)
      for (int dx = -1; dx <= 1 && !covered; ++dx) {
        const int x = (bucket(p[0]) + dx + n) % n, y = (bucket(p[1]) + dy + n) % n;
        for (std::size_t i : buckets[static_cast<std::size_t>(y * n + x)])
          if (domain.distance2(p, points[i]) < r * r) covered = true;
      }
    misses += !covered;
  }
  return static_cast<double>(misses) / kProbes;
}

}  // namespace

int main(int argc, char** argv) {
  auto arg = [&](int i, double fallback) { return argc > i ? std::stod(argv[i]) : fallback; };
  const int sets = static_cast<int>(arg(1, 16));
  WeiParams params;
  params.radius = arg(2, 0.02);
  params.windows = static_cast<int>(arg(3, params.windows));
  params.levels = static_cast<int>(arg(4, params.levels));
  params.trials = static_cast<int>(arg(5, params.trials));
  const double r = params.radius;
  const auto domain = Domain<2>::unit(true);
  testing_stats::Realisations w, j;
  std::vector<double> w_uncovered, j_uncovered;
  for (int s = 1; s <= sets; ++s) {
    const auto a = wei<2>(params, domain, static_cast<std::uint64_t>(s));
    const auto b = jones({r}, domain, 100 + static_cast<std::uint64_t>(s));
    w.add(a, domain, r, true);
    j.add(b, domain, r, true);
    w_uncovered.push_back(uncovered(a, r, static_cast<std::uint64_t>(s)));
    j_uncovered.push_back(uncovered(b, r, static_cast<std::uint64_t>(s)));
  }
  using testing_stats::welch_t;
  auto rho = [&](double count) { return relative_radius(r, 1.0, static_cast<std::size_t>(count + 0.5), 2); };
  std::printf("wei k=%d levels=%d windows=%d, r=%g, %d + %d sets\n", params.trials, params.levels, params.windows, r,
              sets, sets);
  std::printf("count %.1f vs %.1f (t %.2f); rho %.4f vs %.4f\n", mean(w.count), mean(j.count), welch_t(w.count, j.count),
              rho(mean(w.count)), rho(mean(j.count)));
  std::printf("mean nn %.4f r vs %.4f r (t %.2f); nn < 1.1 r %.4f vs %.4f (t %.2f)\n", mean(w.mean_over_r),
              mean(j.mean_over_r), welch_t(w.mean_over_r, j.mean_over_r), mean(w.fraction_near),
              mean(j.fraction_near), welch_t(w.fraction_near, j.fraction_near));
  std::printf("uncovered %.2g vs %.2g\n", mean(w_uncovered), mean(j_uncovered));
  std::printf("annulus ratio t\n");
  for (std::size_t a = 0; a < w.spectrum.front().size(); ++a) {
    std::vector<double> x, y;
    for (const auto& s : w.spectrum) x.push_back(s[a]);
    for (const auto& s : j.spectrum) y.push_back(s[a]);
    std::printf("%zu %.3f %.2f\n", a + 1, mean(x) / mean(y), welch_t(x, y));
  }
  std::printf("max |t| over the annuli %.2f\n", testing_stats::max_spectrum_t(w.spectrum, j.spectrum));
}
