#pragma once
// Bridson's and dart throwing's loops under SamplingConstraints: a radius
// field r(x), a mask, fixed points (samplers/constraints.h states the pair
// rule). One implementation for both, with a background index over radius
// levels (src/pds/samplers/flat_levels.h in 1 to 3 dimensions,
// radius_levels.h from 4); the uniform pds::bridson and pds::dart_throwing
// stay the fast path when no constraint is given.

#include <cstdint>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/samplers/bridson.h"
#include "pds/samplers/constraints.h"
#include "pds/samplers/dart_throwing.h"

namespace pds {

/// Consecutive missed darts that end the search for regions Bridson's front
/// did not reach (disconnected parts of a mask; the start when there are no
/// fixed points).
inline constexpr std::uint64_t kConstrainedRestartDarts = 10'000;

/// Bridson's loop under constraints: each active sample p proposes k
/// candidates uniform by volume in the shell [r(p), 2 r(p)] around it; the
/// first that is inside the mask and conflicts with no sample (pair rule of
/// constraints.h) is accepted. Fixed points start active, so the set grows
/// around them. When no sample is active, darts uniform over the domain look
/// for space the front never reached (an island of a mask); each dart that
/// fits starts a new front, and kConstrainedRestartDarts misses in a row end
/// the run.
/// Guarantees: output = fixed points, then generated samples; every
/// generated sample is in [lo, hi), inside the mask, and keeps the pair rule
/// against every other sample (decided in Domain::distance2's arithmetic,
/// squared distance against the squared larger radius); same seed, same
/// points. Near-maximal, not proven maximal (as bridson()).
/// params.radius is the uniform radius when constraints.radius is empty and
/// is ignored otherwise; params.count is refused (the radius sizes the set).
/// The mask and the field are read at a candidate only when no sample's own
/// ball already holds it (then it conflicts whatever its radius), so a NaN
/// of the field is found where it is read, not where no sample could go.
/// Invalid (InvalidArgument): bad radius or bounds, k < 1, a count, a fixed
/// point outside the domain, a field value NaN, too many grid cells.
template <int D>
PointSet<D> bridson(const BridsonParams& params, const SamplingConstraints<D>& constraints, const Domain<D>& domain,
                    std::uint64_t seed);

/// Dart throwing under constraints: darts uniform over the domain; one is
/// accepted when it is inside the mask and conflicts with no sample. The
/// loop ends after params.max_failures rejected darts in a row (0: the
/// default rule at rmin, default_dart_failures), or once params.count
/// samples were generated (fixed points not counted; not reaching it is
/// InvalidArgument). Darts outside the mask count as rejections, so a small
/// mask ends the loop sooner: raise max_failures for one.
/// Guarantees as for the constrained bridson(); darts are accepted in the
/// order thrown, so every prefix of the generated part is spread over the
/// region with the field's density.
template <int D>
PointSet<D> dart_throwing(const DartThrowingParams& params, const SamplingConstraints<D>& constraints,
                          const Domain<D>& domain, std::uint64_t seed);

}  // namespace pds
