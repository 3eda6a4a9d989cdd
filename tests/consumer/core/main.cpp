// A consumer of pds::core alone (the game developer who wants Bridson in a
// rectangle): no registry, no analysis, no third-party package. Checks the
// set with its own all-pairs loop.
#include <pds/samplers/bridson.h>
#include <pds/samplers/ebeida.h>

#include <iostream>

template <class Set>
double closest_pair(const Set& points) {
  double best = 1e300;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      double d2 = 0;
      for (int a = 0; a < 2; ++a) d2 += (points[i][a] - points[j][a]) * (points[i][a] - points[j][a]);
      best = d2 < best ? d2 : best;
    }
  return best;
}

int main() {
  const auto domain = pds::Domain<2>::box({{0.0, 0.0}}, {{2.0, 1.0}});
  const auto bridson = pds::bridson<2>({.radius = 0.05}, domain, 1);
  const auto ebeida = pds::ebeida<2>({.radius = 0.05}, domain, 1);
  const double r2 = 0.05 * 0.05;
  std::cout << "core consumer: bridson " << bridson.size() << " points, ebeida " << ebeida.size() << " points\n";
  return bridson.size() > 300 && ebeida.size() > 300 && closest_pair(bridson) >= r2 && closest_pair(ebeida) >= r2 ? 0
                                                                                                                 : 1;
}
