#pragma once
// Progress of the Dunbar-Humphreys samplers: samples placed against a little
// more than the usual count at the radius (the sectors and the boundary place
// up to about 1.07 times it), every kReportEvery steps of the front. Private
// to the sampler's translation units.

#include <cstdint>

#include "pds/domain.h"
#include "pds/limits.h"
#include "pds/progress.h"
#include "pds/samplers/dunbar_humphreys.h"

namespace pds::detail::dh {

inline constexpr std::uint64_t kReportEvery = 256;

inline ProgressReporter sample_progress(const DunbarHumphreysParams& params, const Domain<2>& domain) {
  return ProgressReporter(params.progress, 1.1 * typical_count(sizing_volume(domain, params.radius), params.radius, 2));
}

}  // namespace pds::detail::dh
