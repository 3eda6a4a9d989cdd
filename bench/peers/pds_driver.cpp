// pds through its registry (pds::generate, what `pds generate` calls), one
// thread, on the unit square/cube (box or torus). Times only that call.
// Usage: pds_driver METHOD DIM torus|box count|radius VALUE [SEED=0] [OUT.csv] [NAME=VALUE...]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "pds/registry.h"
#include "timing.h"

int main(int argc, char** argv) {
  if (argc < 6) return std::fprintf(stderr, "usage: %s METHOD DIM torus|box count|radius VALUE [SEED] [OUT.csv] [P=V...]\n", argv[0]), 2;
  pds::GenerateRequest req;
  req.dim = std::atoi(argv[2]);
  req.torus = std::string(argv[3]) == "torus";
  if (std::string(argv[4]) == "count")
    req.count = std::strtoull(argv[5], nullptr, 10);
  else
    req.radius = std::strtod(argv[5], nullptr);
  req.seed = argc > 6 ? std::strtoull(argv[6], nullptr, 10) : 0;
  req.threads = 1;
  for (int i = 8; i < argc; ++i) {
    const std::string kv = argv[i];
    const auto eq = kv.find('=');
    req.params[kv.substr(0, eq)] = std::strtod(kv.c_str() + eq + 1, nullptr);
  }
  const double c0 = pds_peer_now(CLOCK_THREAD_CPUTIME_ID), w0 = pds_peer_now(CLOCK_MONOTONIC);
  const pds::PointCloud pts = pds::generate(argv[1], req);
  const double c1 = pds_peer_now(CLOCK_THREAD_CPUTIME_ID), w1 = pds_peer_now(CLOCK_MONOTONIC);
  pds_peer_report((std::string("pds-") + argv[1]).c_str(), req.dim, pts.size(), c1 - c0, w1 - w0);
  if (argc > 7 && std::string(argv[7]) != "-") {
    FILE* f = std::fopen(argv[7], "w");
    std::fputs(req.dim == 2 ? "x,y\n" : "x,y,z\n", f);
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (int d = 0; d < req.dim; ++d) std::fprintf(f, d + 1 < req.dim ? "%.17g," : "%.17g\n", pts.point(i)[d]);
    std::fclose(f);
  }
  return 0;
}
