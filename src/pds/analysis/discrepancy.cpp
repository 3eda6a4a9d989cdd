// L2-star discrepancy (Warnock's formula) and exact star discrepancy by the
// critical boxes; definitions and limits in include/pds/analysis/discrepancy.h.

#include "pds/analysis/discrepancy.h"


#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "pds/error.h"
#include "pds/parallel.h"

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
  const double m = static_cast<double>(n) + 1.0;
  return n > 0 &&
         2.0 * static_cast<double>(n) * std::pow(m, dim - 1) + 2.0 * std::pow(m, dim) <= kMaxStarDiscrepancyWork;
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
  parallel_for(0, n, 64, 0, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i != last; ++i) {
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
    throw InvalidArgument("star discrepancy: exact evaluation needs 2 N (N+1)^(D-1) + 2 (N+1)^D <= " +
                          std::to_string(static_cast<long long>(kMaxStarDiscrepancyWork)) +
                          "; N = " + std::to_string(points.size()) + " in " + std::to_string(D) + "D is too many");
  auto u = to_unit_cube(points, domain, "star discrepancy");
  const std::size_t n = u.size();
  // Candidate corner coordinates per axis: the points' coordinates and 1.
  std::array<std::vector<double>, D> grid;
  for (int a = 0; a < D; ++a) {
    for (const auto& p : u) grid[a].push_back(p[a]);
    grid[a].push_back(1.0);
    std::sort(grid[a].begin(), grid[a].end());
    grid[a].erase(std::unique(grid[a].begin(), grid[a].end()), grid[a].end());
  }
  // Sweep along axis 0. For the corners y = (g, y_1..) at one g, `open`
  // counts the points with u_0 < g and u_a < y_a on the other axes, `closed`
  // those with u_0 <= g and u_a <= y_a; both are tables over the corners of
  // the other axes, updated as the sweep passes each point.
  std::sort(u.begin(), u.end(), [](const auto& p, const auto& q) { return p[0] < q[0]; });
  std::array<std::size_t, D> stride{};
  std::size_t cells = 1;
  for (int a = 1; a < D; ++a) {
    stride[a] = cells;
    cells *= grid[a].size();
  }
  std::vector<std::uint32_t> open(cells, 0), closed(cells, 0);
  // Adds a point to the corners y with y_a > u_a (strict) or y_a >= u_a.
  auto add = [&](const std::array<double, D>& p, std::vector<std::uint32_t>& table, bool strict) {
    std::array<std::size_t, D> first{}, index{};
    for (int a = 1; a < D; ++a) {
      const auto& g = grid[a];
      first[a] = static_cast<std::size_t>(
          (strict ? std::upper_bound(g.begin(), g.end(), p[a]) : std::lower_bound(g.begin(), g.end(), p[a])) -
          g.begin());
      if (first[a] == g.size()) return;
      index[a] = first[a];
    }
    while (true) {
      std::size_t cell = 0;
      for (int a = 1; a < D; ++a) cell += index[a] * stride[a];
      ++table[cell];
      int a = 1;
      while (a < D && ++index[a] == grid[a].size()) {
        index[a] = first[a];
        ++a;
      }
      if (a == D) return;
    }
  };
  std::vector<double> volume(cells);  // product of y_a over the other axes
  for (std::size_t cell = 0; cell < cells; ++cell) {
    double v = 1.0;
    std::size_t rest = cell;
    for (int a = 1; a < D; ++a) {
      v *= grid[a][rest % grid[a].size()];
      rest /= grid[a].size();
    }
    volume[cell] = v;
  }
  const double inv_n = 1.0 / static_cast<double>(n);
  double best = 0.0;
  std::size_t next_open = 0, next_closed = 0;
  for (const double g : grid[0]) {
    while (next_open < n && u[next_open][0] < g) add(u[next_open++], open, true);
    while (next_closed < n && u[next_closed][0] <= g) add(u[next_closed++], closed, false);
    for (std::size_t cell = 0; cell < cells; ++cell) {
      const double v = g * volume[cell];
      best = std::max({best, v - open[cell] * inv_n, closed[cell] * inv_n - v});
    }
  }
  return best;
}

template double l2_star_discrepancy<2>(const PointSet<2>&, const Domain<2>&);
template double l2_star_discrepancy<3>(const PointSet<3>&, const Domain<3>&);
template double star_discrepancy<2>(const PointSet<2>&, const Domain<2>&);
template double star_discrepancy<3>(const PointSet<3>&, const Domain<3>&);

}  // namespace pds
