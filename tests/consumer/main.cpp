// Uses the installed library: generate a set and check it.
#include <pds/analysis/distance.h>
#include <pds/registry.h>

#include <iostream>

int main() {
  pds::GenerateRequest request;
  request.count = 256;
  request.seed = 7;
  const pds::PointCloud cloud = pds::generate("jittered", request);
  const auto points = cloud.as<2>();
  const auto m = pds::min_distance(points, pds::Domain<2>::unit());
  std::cout << "consumer: " << points.size() << " points, min distance " << m.distance << "\n";
  return points.size() == 256 && m.distance > 0 ? 0 : 1;
}
