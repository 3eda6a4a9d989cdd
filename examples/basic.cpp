// The README's library example: generate a pattern through the registry,
// then verify it with the analysis functions.
#include <pds/analysis/distance.h>
#include <pds/analysis/maximality.h>
#include <pds/analysis/relative_radius.h>
#include <pds/io/point_file.h>
#include <pds/registry.h>
#include <pds/samplers/jittered.h>

#include <iostream>

int main() {
  // Typed call: 32 x 32 strata on the unit torus, seed 1.
  const auto domain = pds::Domain<2>::unit(/*periodic=*/true);
  const pds::PointSet<2> points = pds::jittered<2>({.cells = {32, 32, 1}}, domain, /*seed=*/1);

  // The same through the registry, as the command line does it.
  pds::GenerateRequest request;
  request.count = 1024;
  request.torus = true;
  request.seed = 1;
  const pds::PointCloud cloud = pds::generate("jittered", request);

  const pds::MinDistance m = pds::min_distance(points, domain);
  const double rho = pds::relative_radius(m.distance, domain.volume(), points.size(), 2);
  const auto cover = pds::check_maximality(points, domain, /*radius=*/0.045);
  std::cout << points.size() << " points, min distance " << m.distance << ", rho " << rho
            << (cover.maximal ? ", maximal at 0.045" : ", not maximal at 0.045")
            << (cloud.as<2>() == points ? ", registry agrees" : ", registry differs") << "\n";
  pds::write_points("jittered.csv", cloud);
  return 0;
}
