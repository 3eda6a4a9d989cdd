#pragma once
// Multi-class Poisson disk sampling by dart throwing (L.-Y. Wei, Multi-class
// blue noise sampling, ACM TOG 29(4), SIGGRAPH 2010): k classes, each with
// its own minimum distance, kept apart across classes by a symmetric radius
// matrix so that every class alone and the unions of the sparser classes are
// Poisson disk sets.

#include <cstdint>
#include <vector>

#include "pds/domain.h"
#include "pds/point.h"

namespace pds {

/// Wei's radius matrix for classes with minimum distances `radii` (any
/// order) in dimension `dim`, k x k row-major: r(c, c) = radii[c]; for
/// c != j, r(c, j) = (sum of r_i^-dim over the classes i with r_i >=
/// min(r_c, r_j))^(-1/dim), the minimum distance of the union of those
/// classes taken as one set of their summed density. So r(c, j) <=
/// min(r_c, r_j). Throws InvalidArgument for no class or a radius that is not
/// positive and finite (kMinRadius to kMaxRadius).
std::vector<double> multi_class_matrix(const std::vector<double>& radii, int dim);

struct MultiClassParams {
  std::vector<double> radii;  // the minimum distance within each class
  /// Empty: Wei's matrix (multi_class_matrix). Otherwise k x k row-major,
  /// symmetric, every entry a radius (kMinRadius to kMaxRadius), the
  /// diagonal equal to `radii`: r(c, j) is the least distance between a
  /// sample of class c and one of class j.
  std::vector<double> matrix;
  std::uint64_t max_failures = 0;  // rejected darts in a row that close a class; 0: default_dart_failures at
                                   // the matrix's smallest entry
};

template <int D>
struct MultiClassSet {
  PointSet<D> points;
  std::vector<std::uint32_t> classes;  // the class of each point, 0 to k - 1
};

/// Hard-disk dart throwing with Wei's matrix: each dart goes to the open
/// class with the lowest fill rate n_c r_c^D (its count over the density its
/// radius allows), is uniform over the domain, and is kept when every sample
/// q lies at least r(c, class of q) away. A class closes after max_failures
/// rejected darts in a row; the run ends when all are closed. Placed samples
/// are never removed and there are no target counts: the counts follow from
/// the radii, about in proportion to r_c^-D.
/// Guarantees: every pair at least r(class a, class b) apart (the exact
/// arithmetic of Domain::distance2), every point in [lo, hi), same seed same
/// points. Near-maximal per class, not proven maximal.
/// Invalid (InvalidArgument): as multi_class_matrix, a matrix that is not
/// k x k, not symmetric, with an entry that is not a radius or a diagonal
/// other than the radii; more than 2^31 samples' worth of grid.
template <int D>
MultiClassSet<D> multi_class(const MultiClassParams& params, const Domain<D>& domain, std::uint64_t seed);

}  // namespace pds
