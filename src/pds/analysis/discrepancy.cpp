// L2-star discrepancy (Warnock's formula), the centered, wrap-around and
// mixture discrepancies (Hickernell 1998; Zhou, Fang & Ning 2013), and the
// exact star discrepancy by the critical boxes; definitions and limits in
// include/pds/analysis/discrepancy.h.

#include "pds/analysis/discrepancy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pds/detail/instantiate.h"
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


void require_discrepancy_size(std::size_t n, const char* what) {
  if (n > kMaxL2StarPoints)
    throw InvalidArgument(std::string(what) + ": at most " + std::to_string(kMaxL2StarPoints) +
                          " points (the formula is O(N^2)), got " + std::to_string(n));
}

// The kernels below evaluate every product and sum in the order and the
// grouping of SciPy's scipy.stats.qmc.discrepancy (workers=1): the centered,
// wrap-around and mixture double sums in one running sum over the pairs
// (i, j) in row-major order, the L2-star double sum row by row. The results
// are then the same doubles as SciPy's, where a more accurate summation would
// differ from it by the rounding of SciPy's own sum (the three terms of each
// formula nearly cancel, which magnifies it to 1e-9 relative and more at
// 10^3 points). The products are computed on several threads a block of rows
// at a time; the running sum is added on one thread in the fixed order, so
// the result does not depend on the thread count.

// Rows per block: about 2^20 terms (8 MiB) at a time.
std::size_t block_rows(std::size_t n) { return std::max<std::size_t>(1, (std::size_t{1} << 20) / n); }

// sum_i sum_j term(i, j) in row-major order, one running sum. Reports the
// rows done after each block.
template <class Term>
double pair_sum_running(std::size_t n, const Term& term, ProgressReporter& progress) {
  const std::size_t rows = block_rows(n);
  std::vector<double> terms(std::min(rows, n) * n);
  double sum = 0.0;
  for (std::size_t first = 0; first < n; first += rows) {
    const std::size_t last = std::min(n, first + rows);
    parallel_for(first, last, 1, 0, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i != e; ++i) {
        double* row = terms.data() + (i - first) * n;
        for (std::size_t j = 0; j < n; ++j) row[j] = term(i, j);
      }
    });
    const std::size_t count = (last - first) * n;
    for (std::size_t k = 0; k < count; ++k) sum += terms[k];
    progress.update(static_cast<double>(last));
  }
  return sum;
}

// sum_i (sum_j term(i, j)): each row summed alone, the rows added in order.
// Blocks of rows as above, only so that progress is heard between them.
template <class Term>
double pair_sum_by_rows(std::size_t n, const Term& term, ProgressReporter& progress) {
  std::vector<double> row_sums(n);
  const std::size_t rows = block_rows(n);
  for (std::size_t first = 0; first < n; first += rows) {
    const std::size_t last = std::min(n, first + rows);
    parallel_for(first, last, 16, 0, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i != e; ++i) {
        double row = 0.0;
        for (std::size_t j = 0; j < n; ++j) row += term(i, j);
        row_sums[i] = row;
      }
    });
    progress.update(static_cast<double>(last));
  }
  double sum = 0.0;
  for (const double r : row_sums) sum += r;
  return sum;
}

// The discrepancy (squared for CD, WD, MD) of points in the unit cube;
// `progress` hears the rows of the double sum done.
double unit_cube_discrepancy(const PointCloud& points, DiscrepancyMethod method, ProgressReporter& progress) {
  const std::size_t n = points.size();
  const std::size_t d = static_cast<std::size_t>(points.dim);
  const double* x = points.coords.data();
  const double nd = static_cast<double>(n);
  const double dd = static_cast<double>(points.dim);
  // |x - 1/2| per coordinate, used by the centered and mixture formulas.
  std::vector<double> half;
  if (method == DiscrepancyMethod::Centered || method == DiscrepancyMethod::Mixture) {
    half.resize(n * d);
    for (std::size_t k = 0; k < n * d; ++k) half[k] = std::fabs(x[k] - 0.5);
  }
  const double* h = half.data();
  switch (method) {
    case DiscrepancyMethod::L2Star: {
      double single = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        double prod = 1.0;
        for (std::size_t k = 0; k < d; ++k) prod *= 1.0 - x[i * d + k] * x[i * d + k];
        single += prod;
      }
      const double pair = pair_sum_by_rows(n, [&](std::size_t i, std::size_t j) {
        double prod = 1.0;
        for (std::size_t k = 0; k < d; ++k) prod *= 1.0 - std::max(x[i * d + k], x[j * d + k]);
        return prod;
      }, progress);
      const double t2 = std::pow(3.0, -dd) - 1.0 / nd * std::pow(2.0, 1.0 - dd) * single + 1.0 / (nd * nd) * pair;
      return std::sqrt(std::max(0.0, t2));
    }
    case DiscrepancyMethod::Centered: {
      double single = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        double prod = 1.0;
        for (std::size_t k = 0; k < d; ++k) {
          const double a = h[i * d + k];
          prod *= 1.0 + 0.5 * a - 0.5 * (a * a);
        }
        single += prod;
      }
      const double pair = pair_sum_running(n, [&](std::size_t i, std::size_t j) {
        double prod = 1.0;
        for (std::size_t k = 0; k < d; ++k)
          prod *= 1.0 + 0.5 * h[i * d + k] + 0.5 * h[j * d + k] - 0.5 * std::fabs(x[i * d + k] - x[j * d + k]);
        return prod;
      }, progress);
      return std::pow(13.0 / 12.0, dd) - 2.0 / nd * single + 1.0 / (nd * nd) * pair;
    }
    case DiscrepancyMethod::WrapAround: {
      const double pair = pair_sum_running(n, [&](std::size_t i, std::size_t j) {
        double prod = 1.0;
        for (std::size_t k = 0; k < d; ++k) {
          const double t = std::fabs(x[i * d + k] - x[j * d + k]);
          prod *= 1.5 - t + t * t;
        }
        return prod;
      }, progress);
      return -std::pow(4.0 / 3.0, dd) + 1.0 / (nd * nd) * pair;
    }
    case DiscrepancyMethod::Mixture: {
      double single = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        double prod = 1.0;
        for (std::size_t k = 0; k < d; ++k) {
          const double a = h[i * d + k];
          prod *= 5.0 / 3.0 - 0.25 * a - 0.25 * (a * a);
        }
        single += prod;
      }
      const double pair = pair_sum_running(n, [&](std::size_t i, std::size_t j) {
        double prod = 1.0;
        for (std::size_t k = 0; k < d; ++k) {
          const double t = std::fabs(x[i * d + k] - x[j * d + k]);
          prod *= 15.0 / 8.0 - 0.25 * h[i * d + k] - 0.25 * h[j * d + k] - 0.75 * t + 0.5 * (t * t);
        }
        return prod;
      }, progress);
      return std::pow(19.0 / 12.0, dd) - 2.0 / nd * single + 1.0 / (nd * nd) * pair;
    }
  }
  throw InvalidArgument("discrepancy: unknown method");
}

double unit_cube_discrepancy(const PointCloud& points, DiscrepancyMethod method, const Progress& progress) {
  ProgressReporter reporter(progress, static_cast<double>(points.size()));
  const double value = unit_cube_discrepancy(points, method, reporter);
  reporter.finish();
  return value;
}

}  // namespace

std::string_view discrepancy_method_name(DiscrepancyMethod method) {
  switch (method) {
    case DiscrepancyMethod::L2Star:
      return "L2-star";
    case DiscrepancyMethod::Centered:
      return "CD";
    case DiscrepancyMethod::WrapAround:
      return "WD";
    case DiscrepancyMethod::Mixture:
      return "MD";
  }
  return "?";
}

DiscrepancyMethod parse_discrepancy_method(std::string_view name) {
  for (const DiscrepancyMethod m : kDiscrepancyMethods)
    if (name == discrepancy_method_name(m)) return m;
  throw InvalidArgument("discrepancy: method must be one of L2-star, CD, WD, MD (SciPy's names), got '" +
                        std::string(name) + "'");
}

double discrepancy(const PointCloud& points, DiscrepancyMethod method, const Progress& progress) {
  if (points.dim < 1)
    throw InvalidArgument("discrepancy: dimension " + std::to_string(points.dim) + " is not positive");
  if (points.size() == 0) throw InvalidArgument("discrepancy: the point set is empty");
  require_discrepancy_size(points.size(), "discrepancy");
  for (std::size_t k = 0; k < points.coords.size(); ++k) {
    const double v = points.coords[k];
    if (!(v >= 0.0 && v <= 1.0))
      throw InvalidArgument("discrepancy: point " + std::to_string(k / static_cast<std::size_t>(points.dim)) +
                            " lies outside the unit cube [0, 1]^" + std::to_string(points.dim) + " (coordinate " +
                            std::to_string(k % static_cast<std::size_t>(points.dim)) + ")");
  }
  return unit_cube_discrepancy(points, method, progress);
}

double discrepancy(const PointCloud& points, std::span<const double> lo, std::span<const double> hi,
                   DiscrepancyMethod method, const Progress& progress) {
  const std::size_t d = static_cast<std::size_t>(std::max(points.dim, 0));
  if (lo.size() != d || hi.size() != d)
    throw InvalidArgument("discrepancy: the bounds have " + std::to_string(lo.size()) + " and " +
                          std::to_string(hi.size()) + " coordinates, the points " + std::to_string(points.dim));
  for (std::size_t k = 0; k < d; ++k) validate_axis(static_cast<int>(k), lo[k], hi[k]);
  PointCloud u{points.dim, std::vector<double>(points.coords.size())};
  for (std::size_t k = 0; k < u.coords.size(); ++k) {
    const std::size_t a = k % d;
    const double v = points.coords[k];
    if (!(v >= lo[a] && v <= hi[a]))
      throw InvalidArgument("discrepancy: point " + std::to_string(k / d) + " lies outside the domain (axis " +
                            std::to_string(a) + ")");
    u.coords[k] = (v - lo[a]) / (hi[a] - lo[a]);
  }
  return discrepancy(u, method, progress);
}

bool star_discrepancy_feasible(std::size_t n, int dim) {
  const double m = static_cast<double>(n) + 1.0;
  return n > 0 &&
         2.0 * static_cast<double>(n) * std::pow(m, dim - 1) + 2.0 * std::pow(m, dim) <= kMaxStarDiscrepancyWork;
}

template <int D>
double l2_star_discrepancy(const PointSet<D>& points, const Domain<D>& domain, const Progress& progress) {
  require_discrepancy_size(points.size(), "L2-star discrepancy");
  const auto u = to_unit_cube(points, domain, "L2-star discrepancy");
  PointCloud cloud{D, {}};
  cloud.coords.reserve(u.size() * D);
  for (const auto& p : u) cloud.coords.insert(cloud.coords.end(), p.begin(), p.end());
  return unit_cube_discrepancy(cloud, DiscrepancyMethod::L2Star, progress);
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

#define PDS_INSTANTIATE(D)                                                                         \
  template double l2_star_discrepancy<D>(const PointSet<D>&, const Domain<D>&, const Progress&); \
  template double star_discrepancy<D>(const PointSet<D>&, const Domain<D>&);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
