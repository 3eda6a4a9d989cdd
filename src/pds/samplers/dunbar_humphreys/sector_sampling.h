#pragma once
// Variants 1 and 2 of the Dunbar-Humphreys sampler: new samples drawn from
// scalloped regions (scalloped_region.h). Private to the library; the driver
// (src/pds/samplers/dunbar_humphreys.cpp) validates the request first.

#include <cstdint>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/samplers/dunbar_humphreys.h"

namespace pds::detail::dh {

/// Variant 1, the paper's order: each front sample (picked at random) is
/// filled until its region is empty.
PointSet<2> scalloped_sector_sampling(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed);

/// Variant 2: each new sample uniform over the union of all front regions.
PointSet<2> global_scalloped_sampling(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed);

}  // namespace pds::detail::dh
