// The C++ library's own time for one registry request over REPEAT runs, the
// reference for the Python call's overhead in bench_scipy.py. The points are
// freed after each run, as the Python benchmark drops each array.
// Usage: pds_cpp_time METHOD count|radius VALUE REPEAT [dim=D] [PARAM=VALUE ...]
// prints the best and the median seconds and the point count.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "pds/registry.h"

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s METHOD count|radius VALUE REPEAT [dim=D] [PARAM=VALUE ...]\n", argv[0]);
    return 2;
  }
  pds::GenerateRequest request;
  request.seed = 1;
  if (std::string(argv[2]) == "count")
    request.count = std::strtoull(argv[3], nullptr, 10);
  else
    request.radius = std::strtod(argv[3], nullptr);
  for (int a = 5; a < argc; ++a) {
    const std::string arg = argv[a];
    const auto eq = arg.find('=');
    if (eq == std::string::npos) {
      std::fprintf(stderr, "%s: expected KEY=VALUE\n", argv[a]);
      return 2;
    }
    const double value = std::strtod(arg.c_str() + eq + 1, nullptr);
    if (arg.compare(0, eq, "dim") == 0)
      request.dim = static_cast<int>(value);
    else
      request.params[arg.substr(0, eq)] = value;
  }
  std::vector<double> times;
  std::size_t n = 0;
  for (int i = 0, repeat = std::max(1, std::atoi(argv[4])); i < repeat; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const pds::PointCloud points = pds::generate(argv[1], request);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    n = points.size();
  }
  std::sort(times.begin(), times.end());
  std::printf("%.9f %.9f %zu\n", times.front(), times[times.size() / 2], n);
}
