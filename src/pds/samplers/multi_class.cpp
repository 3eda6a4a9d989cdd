// Multi-class hard-disk sampling (L.-Y. Wei, Multi-class blue noise sampling,
// ACM TOG 29(4), SIGGRAPH 2010, the hard-disk algorithm; dart throwing as in
// R. L. Cook, Stochastic sampling in computer graphics, ACM TOG 5(1), 1986).
//
// Method: the radius matrix of multi_class_matrix(); darts uniform over the
// domain, each for the open class with the lowest fill rate; a dart of class
// c is kept when no sample q of class j lies closer than r(c, j). The
// neighbours are found in one pds::Grid for the smallest matrix entry,
// searched out to the largest entry of row c (r(c, c) for Wei's matrix).
//
// Guarantees: see multi_class.h. Complexity: a dart reads the cells within
// r_c; with radii far apart the sparse classes read many small cells.
// Limits: no target counts: each class fills, by the fill-rate priority,
// until it closes, so the counts follow from the radii (about in proportion
// to r_c^-D); placed samples are never removed.

#include "pds/samplers/multi_class.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "pds/detail/format.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"
#include "pds/grid.h"
#include "pds/limits.h"
#include "pds/rng.h"
#include "pds/samplers/dart_throwing.h"
#include "pds/samplers/random.h"

namespace pds {

std::vector<double> multi_class_matrix(const std::vector<double>& radii, int dim) {
  if (radii.empty()) throw InvalidArgument("multi-class: need at least one class");
  for (const double r : radii) require_radius(r, "class radius");
  const std::size_t k = radii.size();
  std::vector<double> m(k * k);
  for (std::size_t c = 0; c < k; ++c)
    for (std::size_t j = 0; j < k; ++j) {
      if (c == j) {
        m[c * k + j] = radii[c];
        continue;
      }
      const double smaller = std::min(radii[c], radii[j]);
      double density = 0.0;  // sum of r^-dim over the classes at least as sparse
      for (const double r : radii)
        if (r >= smaller) density += std::pow(r, -dim);
      m[c * k + j] = std::pow(density, -1.0 / dim);
    }
  return m;
}

namespace {

std::vector<double> checked_matrix(const std::vector<double>& radii, const std::vector<double>& m) {
  if (radii.empty()) throw InvalidArgument("multi-class: need at least one class");
  const std::size_t k = radii.size();
  if (m.size() != k * k)
    throw InvalidArgument("multi-class: the radius matrix has " + std::to_string(m.size()) + " entries; " +
                          std::to_string(k) + " classes need " + std::to_string(k * k));
  for (const double r : m) require_radius(r, "class matrix entry");
  for (std::size_t c = 0; c < k; ++c) {
    if (m[c * k + c] != radii[c])
      throw InvalidArgument("multi-class: the matrix's diagonal entry " + std::to_string(c) + " is " +
                            detail::format_number(m[c * k + c]) + ", not the class radius " +
                            detail::format_number(radii[c]));
    for (std::size_t j = c + 1; j < k; ++j)
      if (m[c * k + j] != m[j * k + c])
        throw InvalidArgument("multi-class: the radius matrix is not symmetric (entries " + std::to_string(c) + "," +
                              std::to_string(j) + " and " + std::to_string(j) + "," + std::to_string(c) + ")");
  }
  return m;
}

}  // namespace

template <int D>
MultiClassSet<D> multi_class(const MultiClassParams& params, const Domain<D>& domain, std::uint64_t seed) {
  domain.validate();
  const std::vector<double> m =
      params.matrix.empty() ? multi_class_matrix(params.radii, D) : checked_matrix(params.radii, params.matrix);
  const std::size_t k = params.radii.size();
  std::vector<double> reach(k, 0.0);  // the largest entry of each row
  for (std::size_t c = 0; c < k; ++c) reach[c] = *std::max_element(m.begin() + c * k, m.begin() + (c + 1) * k);
  const double smallest = *std::min_element(m.begin(), m.end());
  const std::uint64_t bound = params.max_failures ? params.max_failures : default_dart_failures(domain, smallest);
  Grid<D> grid = Grid<D>::for_conflicts(domain, smallest);
  MultiClassSet<D> out;
  std::vector<std::uint64_t> count(k, 0), failures(k, 0);
  std::vector<double> weight(k);  // fill rate = count * r^D
  for (std::size_t c = 0; c < k; ++c) weight[c] = std::pow(params.radii[c], D);
  std::vector<bool> open(k, true);
  std::size_t open_count = k;
  Rng rng(seed);
  while (open_count > 0) {
    std::size_t c = k;
    for (std::size_t i = 0; i < k; ++i)
      if (open[i] && (c == k || static_cast<double>(count[i]) * weight[i] < static_cast<double>(count[c]) * weight[c]))
        c = i;
    const Point<D> dart = uniform_point(rng, domain);
    const double* row = m.data() + c * k;
    const bool free = grid.for_each_within(dart, reach[c], [&](std::int32_t q, double d2) {
      const double r = row[out.classes[static_cast<std::size_t>(q)]];
      return !(d2 < r * r);
    });
    if (free) {
      grid.insert(dart);
      out.classes.push_back(static_cast<std::uint32_t>(c));
      ++count[c];
      failures[c] = 0;
    } else if (++failures[c] >= bound) {
      open[c] = false;
      --open_count;
    }
  }
  out.points = grid.points();
  return out;
}

#define PDS_INSTANTIATE(D) \
  template MultiClassSet<D> multi_class<D>(const MultiClassParams&, const Domain<D>&, std::uint64_t);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
