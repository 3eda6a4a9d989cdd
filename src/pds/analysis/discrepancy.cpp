// L2-star discrepancy (Warnock's formula) and exact star discrepancy by the
// critical boxes; definitions and limits in include/pds/analysis/discrepancy.h.

#include "pds/analysis/discrepancy.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pds/error.h"

namespace pds {
namespace {

template <int D>
std::vector<std::array<double, D>> to_unit_cube(const PointSet<D>& points, const Domain<D>& domain, const char* what) {
  domain.validate();
  if (points.empty()) throw InvalidArgument(std::string(what) + ": the point set is empty");
  std::vector<std::array<double, D>> u(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!domain.contains(points[i]))
      throw InvalidArgument(std::string(what) + ": point " + std::to_string(i) + " lies outside the domain");
    for (int a = 0; a < D; ++a) u[i][a] = (points[i][a] - domain.lo[a]) / domain.extent(a);
  }
  return u;
}

}  // namespace

bool star_discrepancy_feasible(std::size_t n, int dim) {
  return n > 0 && std::pow(static_cast<double>(n) + 1.0, dim) * static_cast<double>(n) <= kMaxStarDiscrepancyWork;
}

template <int D>
double l2_star_discrepancy(const PointSet<D>& points, const Domain<D>& domain) {
  if (points.size() > kMaxL2StarPoints)
    throw InvalidArgument("L2-star discrepancy: at most " + std::to_string(kMaxL2StarPoints) +
                          " points (the formula is O(N^2)), got " + std::to_string(points.size()));
  const auto u = to_unit_cube(points, domain, "L2-star discrepancy");
  const std::size_t n = u.size();
  // rows[i] = prod(1 - u_i^2) term and sum_j prod(1 - max) for row i.
  std::vector<double> single(n), pair(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 64), [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      double s = 1.0;
      for (int a = 0; a < D; ++a) s *= 1.0 - u[i][a] * u[i][a];
      single[i] = s;
      double row = 0.0;
      for (std::size_t j = 0; j < n; ++j) {
        double p = 1.0;
        for (int a = 0; a < D; ++a) p *= 1.0 - std::max(u[i][a], u[j][a]);
        row += p;
      }
      pair[i] = row;
    }
  });
  double sum_single = 0.0, sum_pair = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sum_single += single[i];
    sum_pair += pair[i];
  }
  const double N = static_cast<double>(n);
  const double t2 = std::pow(3.0, -D) - std::pow(2.0, 1 - D) / N * sum_single + sum_pair / (N * N);
  return std::sqrt(std::max(0.0, t2));
}

template <int D>
double star_discrepancy(const PointSet<D>& points, const Domain<D>& domain) {
  if (!star_discrepancy_feasible(points.size(), D))
    throw InvalidArgument("star discrepancy: exact evaluation needs (N+1)^D N <= " +
                          std::to_string(static_cast<long long>(kMaxStarDiscrepancyWork)) +
                          "; N = " + std::to_string(points.size()) + " in " + std::to_string(D) + "D is too many");
  const auto u = to_unit_cube(points, domain, "star discrepancy");
  const std::size_t n = u.size();
  // Candidate corner coordinates per axis: the points' coordinates and 1.
  std::array<std::vector<double>, D> grid;
  for (int a = 0; a < D; ++a) {
    for (const auto& p : u) grid[a].push_back(p[a]);
    grid[a].push_back(1.0);
    std::sort(grid[a].begin(), grid[a].end());
    grid[a].erase(std::unique(grid[a].begin(), grid[a].end()), grid[a].end());
  }
  // Corners are split over threads by their first axis; each chunk keeps its
  // own maximum and the maxima are combined in order (max is exact anyway).
  std::vector<double> best(grid[0].size(), 0.0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, grid[0].size()), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i0 = r.begin(); i0 != r.end(); ++i0) {
      std::array<std::size_t, D> index{};
      index[0] = i0;
      double local = 0.0;
      while (true) {
        std::array<double, D> y;
        double volume = 1.0;
        for (int a = 0; a < D; ++a) {
          y[a] = grid[a][index[a]];
          volume *= y[a];
        }
        std::size_t open = 0, closed = 0;
        for (const auto& p : u) {
          bool in_open = true, in_closed = true;
          for (int a = 0; a < D; ++a) {
            in_open = in_open && p[a] < y[a];
            in_closed = in_closed && p[a] <= y[a];
          }
          open += in_open;
          closed += in_closed;
        }
        local = std::max({local, volume - static_cast<double>(open) / n, static_cast<double>(closed) / n - volume});
        int a = 1;
        while (a < D && ++index[a] == grid[a].size()) index[a++] = 0;
        if (a == D) break;
      }
      best[i0] = local;
    }
  });
  return *std::max_element(best.begin(), best.end());
}

template double l2_star_discrepancy<2>(const PointSet<2>&, const Domain<2>&);
template double l2_star_discrepancy<3>(const PointSet<3>&, const Domain<3>&);
template double star_discrepancy<2>(const PointSet<2>&, const Domain<2>&);
template double star_discrepancy<3>(const PointSet<3>&, const Domain<3>&);

}  // namespace pds
