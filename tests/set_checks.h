#pragma once
// The checks every Poisson disk sampler's tests make of its output, with
// failure messages that say which points broke what.

#include <gtest/gtest.h>

#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"

namespace pds::testing_checks {

/// Every point inside the domain and every pair at least r apart (all pairs,
/// under the domain's metric).
template <int D>
::testing::AssertionResult poisson_disk_set(const PointSet<D>& points, const Domain<D>& domain, double r) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!domain.contains(points[i]))
      return ::testing::AssertionFailure() << "point " << i << " " << points[i] << " outside " << domain;
  const MinDistance closest = min_distance_brute_force(points, domain);
  if (!(closest.distance >= r))
    return ::testing::AssertionFailure() << "points " << closest.i << " and " << closest.j << " at " << closest.distance
                                         << " < r = " << r << " in " << domain;
  return ::testing::AssertionSuccess();
}

/// A Poisson disk set that also leaves no point of the domain farther than r
/// from every sample (check_maximality's default tolerance).
template <int D>
::testing::AssertionResult maximal_poisson_disk_set(const PointSet<D>& points, const Domain<D>& domain, double r) {
  if (auto spaced = poisson_disk_set(points, domain, r); !spaced) return spaced;
  const auto coverage = check_maximality(points, domain, r);
  if (!coverage.maximal && coverage.gap)
    return ::testing::AssertionFailure() << "uncovered point " << *coverage.gap << " at distance "
                                         << coverage.gap_distance << " > r = " << r << " from the nearest sample in "
                                         << domain;
  if (!coverage.maximal) return ::testing::AssertionFailure() << "not maximal (no witness point) in " << domain;
  return ::testing::AssertionSuccess();
}

}  // namespace pds::testing_checks
