// The memory floor of the methods built on CGAL's triangulations (`jones`
// and `fpo`): peak RSS of a CGAL Delaunay triangulation of N uniform points
// in the unit square, plain and periodic, over what the points themselves
// take, per point and as a multiple of the 16-byte 2D float64 sample. The
// points are put in CGAL's spatial order in place first (CGAL::spatial_sort:
// Hilbert curves over growing random prefixes) and inserted one at a time,
// each from the last one's face, as the samplers insert: the range
// constructors would add a sorted copy of the input to the peak. Run:
//
//   build/bench/pds_triangulation_memory [plain|periodic] [N]
//
// One triangulation a process, so that each peak is its own.

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/spatial_sort.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "../peak_rss.h"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

}  // namespace

int main(int argc, char** argv) {
  const std::string kind = argc > 1 ? argv[1] : "periodic";
  const long count = argc > 2 ? std::atol(argv[2]) : 1000000;
  if ((kind != "plain" && kind != "periodic") || count < 3) {
    std::fprintf(stderr, "usage: %s [plain|periodic] [N >= 3]\n", argv[0]);
    return 2;
  }
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Kernel::Point_2> points;
  points.reserve(static_cast<std::size_t>(count));
  for (long i = 0; i < count; ++i) points.emplace_back(unit(rng), unit(rng));
  CGAL::spatial_sort(points.begin(), points.end());
  // The points are the peak so far: their vector grew once (reserved), and
  // the sort works in place.
  const double before = pds_bench::peak_rss_mb();
  // Inserted one at a time, each from the face of the one before.
  const auto fill = [&](auto& triangulation) {
    typename std::remove_reference_t<decltype(triangulation)>::Face_handle hint;
    for (const Kernel::Point_2& p : points) hint = triangulation.insert(p, hint)->face();
    return triangulation.number_of_vertices();
  };
  std::size_t vertices = 0;
  if (kind == "plain") {
    CGAL::Delaunay_triangulation_2<Kernel> triangulation;
    vertices = fill(triangulation);
  } else {
    using Traits = CGAL::Periodic_2_Delaunay_triangulation_traits_2<Kernel>;
    CGAL::Periodic_2_Delaunay_triangulation_2<Traits> triangulation;
    vertices = fill(triangulation);
  }
  const double growth = (pds_bench::peak_rss_mb() - before) * 1024.0 * 1024.0;
  std::printf(
      "%s triangulation, %zu vertices: %.1f MB over the points, %.0f bytes a point, %.1fx a 2D float64 sample\n",
      kind.c_str(), vertices, growth / 1e6, growth / count, growth / count / 16.0);
  return 0;
}
