// Registry entries of the fast and maximal Poisson disk methods that need
// no third-party library: Dunbar & Humphreys, Wei, Ebeida, maximal darts.
#include <algorithm>

#include "descriptors.h"
#include "pds/samplers/dunbar_humphreys.h"
#include "pds/samplers/ebeida.h"
#include "pds/samplers/maximal_darts.h"
#include "pds/samplers/wei.h"

namespace pds::registry_detail {

// Both run in 1 to 8 dimensions, but past 5 they serve small sets only:
// the open cells they cannot prove covered outgrow the samples (ebeida: a
// few hundred samples a minute in 7D, about one a second in 8D); bridson
// serves large sets there (docs/dimensions.md).
constexpr int kWeiMaxDim = 8;
constexpr int kEbeidaMaxDim = 8;

const Method& dunbar_humphreys_method() {
  static const Method method{
      .name = "dunbar-humphreys",
      .family = Family::fast_poisson_disk,
      .docs = "docs/dunbar-humphreys.md",
      .summary = "boundary sampling or scalloped sectors (Dunbar & Humphreys): maximal Poisson disk sets, 2D",
      .citation =
          "D. Dunbar, G. Humphreys, A spatial data structure for fast Poisson-disk sample generation, "
          "ACM SIGGRAPH 2006",
      .takes_radius = true,
      .min_distance = true,
      .maximal = true,
      .compare = true,
      .dims = {2, 2},
      // Measured over seeds 1-5 (variant 0, boundary sampling, denser than dart
      // throwing): box 0.880-0.885, torus 0.871-0.873.
      .rho = {{2, false, 0.02, 0.86, 0.90}, {2, true, 0.02, 0.85, 0.89}},
      .memory_ratio = 2,
      .params = {{"variant", 0, 0, 2, true,
                  "0: boundary sampling (fastest; 25% denser than dart throwing), 1: scalloped sectors, one annulus "
                  "at a time as in the paper (5% denser), 2: scalloped sectors, uniform over all free annuli "
                  "(dart-throwing statistics)"}},
      .run =
          [](const GenerateRequest& r) {
            const DunbarHumphreysParams params{*r.radius, r.max_points, static_cast<int>(r.param("variant", 0)),
                                               r.progress};
            return PointCloud::from<2>(dunbar_humphreys(params, r.domain<2>(), r.seed));
          },
  };
  return method;
}

const Method& wei_method() {
  static const Method method{
      .name = "wei",
      .family = Family::fast_poisson_disk,
      .docs = "docs/wei.md",
      .summary =
          "parallel Poisson disk sampling (Wei): phase groups of grid cells in random order, k passes of darts at "
          "Poisson times in time windows, multi-level",
      .citation = "L.-Y. Wei, Parallel Poisson disk sampling, ACM SIGGRAPH 2008",
      .takes_radius = true,
      .min_distance = true,
      .compare = true,
      // Measured over seeds 1-5: 2D box 0.784-0.788, torus 0.776-0.780; 3D box
      // 0.842-0.845, torus 0.803-0.805.
      .dims = {kMinDim, kWeiMaxDim},
      .rho = {{2, false, 0.02, 0.76, 0.81},
              {2, true, 0.02, 0.755, 0.80},
              {3, false, 0.08, 0.82, 0.87},
              {3, true, 0.08, 0.78, 0.83}},
      // Measured 2.9 in 1D and 2.4 in 2D, 5.3 over the estimate's typical
      // count in 3D; from 4D the open parts of the finer levels dominate: 53
      // MB for 35,147 points in 4D, 680 MB for 103,730 in 5D (unit torus,
      // docs/wei.md). Past 5D, 1.5 times the ratio measured on the unit torus
      // (scripts/peak_memory.py, 820, 261 and 63 points): 349 in 6D, 1,505 in
      // 7D, 31,366 in 8D.
      .memory_ratio = 3.5,
      .memory_ratio_from_dim = {{3, 6.5}, {4, 50}, {5, 170}, {6, 550}, {7, 2300}, {8, 47000}},
      .params =
          {{"k", double(WeiParams{}.trials), 1, 1000, true,
            "dart passes per level (each a unit of dart-throwing time: a Poisson(1) number of darts per empty cell)"},
           {"levels", double(WeiParams{}.levels), 1, kWeiMaxLevels, true,
            "grid levels (each halves the cells of the last and retries where no single disk covers)"},
           {"windows", double(WeiParams{}.windows), 1, kWeiMaxWindows, true,
            "time windows per pass, run in order, groups in a random order in each (1: a pass in one visit, "
            "whose first group leaves a lattice)"}},
      .run =
          [](const GenerateRequest& r) {
            return run_typed<kMinDim, kWeiMaxDim>(r, [&](const auto& domain) {
              const WeiParams params{*r.radius,
                                     static_cast<int>(r.param("k", WeiParams{}.trials)),
                                     static_cast<int>(r.param("levels", WeiParams{}.levels)),
                                     static_cast<int>(r.param("windows", WeiParams{}.windows)),
                                     r.threads,
                                     r.max_points,
                                     r.progress};
              return wei(params, domain, r.seed);
            });
          },
  };
  return method;
}

const Method& ebeida_method() {
  static const Method method{
      .name = "ebeida",
      .family = Family::maximal_poisson_disk,
      .docs = "docs/ebeida.md",
      .summary = "maximal Poisson disk, fast (Ebeida et al. flat quadtree, darts swept in time order), --radius",
      .citation =
          "M. S. Ebeida, S. A. Mitchell, A. Patney, A. A. Davidson, J. D. Owens, A simple algorithm for maximal "
          "Poisson-disk sampling in high dimensions, Computer Graphics Forum 31(2), 2012",
      .takes_radius = true,
      .min_distance = true,
      .maximal = true,
      .compare = true,
      // Measured over seeds 1-5: 2D box 0.784-0.788, torus 0.774-0.778; 3D box
      // 0.842-0.845, torus 0.803-0.805 (maximal dart throwing).
      .dims = {kMinDim, kEbeidaMaxDim},
      .rho = {{2, false, 0.02, 0.76, 0.81},
              {2, true, 0.02, 0.755, 0.80},
              {3, false, 0.08, 0.82, 0.87},
              {3, true, 0.08, 0.78, 0.83}},
      // Measured 4.6 in 2D at 10^6 and 10^7 (growth over the output; 0.35 of
      // this estimate); over the estimate's typical count 16.6 in 3D, 20.7 in
      // 4D and 249 in 5D, where the listed sub-cells hold about 18 KB a
      // sample (docs/reliability.md). Past 5D, 1.5 times the ratio measured
      // on the unit torus (scripts/peak_memory.py, 822, 256 and 63 points):
      // 1,248 in 6D, 4,629 in 7D, 18,552 in 8D.
      .memory_ratio = 11,
      .memory_ratio_from_dim = {{3, 20}, {4, 25}, {5, 300}, {6, 2000}, {7, 7000}, {8, 28000}},
      .run =
          [](const GenerateRequest& r) {
            const EbeidaParams params{*r.radius, r.max_points, r.progress};
            return run_typed<kMinDim, kEbeidaMaxDim>(r, [&](const auto& domain) { return ebeida(params, domain, r.seed); });
          },
  };
  return method;
}

const Method& maximal_darts_method() {
  static const Method method{
      .name = "maximal-darts",
      .family = Family::maximal_poisson_disk,
      .docs = "docs/maximal-darts.md",
      .summary =
          "maximal Poisson disk with dart throwing's statistics, parallel (Ebeida et al.'s grid, darts at Poisson "
          "times decided window by window; the same output for any thread count), --radius",
      .citation =
          "M. S. Ebeida, S. A. Mitchell, A. Patney, A. A. Davidson, J. D. Owens, A simple algorithm for maximal "
          "Poisson-disk sampling in high dimensions, Computer Graphics Forum 31(2), 2012",
      .takes_radius = true,
      .min_distance = true,
      .maximal = true,
      .compare = true,
      // The same process as ebeida (maximal dart throwing), so the same bands.
      .dims = {2, 3},
      .rho = {{2, false, 0.02, 0.76, 0.81},
              {2, true, 0.02, 0.755, 0.80},
              {3, false, 0.08, 0.82, 0.87},
              {3, true, 0.08, 0.78, 0.83}},
      // scripts/peak_memory.py at 10^6: growth 2.8 times the output (the grid,
      // the samples and the open sub-cells of the first refinement levels),
      // 2.4 over the estimate's typical count; in 3D 3.5 over it.
      .memory_ratio = 3.5,
      .memory_ratio_from_dim = {{3, 5}},
      .run =
          [](const GenerateRequest& r) {
            const MaximalDartsParams params{*r.radius, r.threads, r.max_points, r.progress};
            return run_typed<2, 3>(r, [&](const auto& domain) { return maximal_darts(params, domain, r.seed); });
          },
  };
  return method;
}

}  // namespace pds::registry_detail
