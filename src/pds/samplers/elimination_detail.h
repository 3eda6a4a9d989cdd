#pragma once
// Weighted sample elimination with a given d_max and per-sample scales, for
// the samplers built on it inside the core (elimination.cpp, surface.cpp).

#include <cstdint>
#include <span>
#include <vector>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"
#include "pds/samplers/elimination.h"

namespace pds::detail {

/// Eliminates `points` (inside `domain`, at most 2^31) down to `count`
/// (1 <= count <= size) with the weights of Yuksel 2015 and the given d_max
/// (d_min from it, the weights' beta and gamma). `scale`: empty, or one
/// positive factor a point; a pair then uses d_max and d_min times the larger
/// of its two factors. Progressive: the kept set is ordered by halving rounds
/// that grow d_max by 2^(1/growth_dim) each (growth_dim is the dimension of
/// the set: 2 on a surface). Returns indices into `points`, the kept ones in
/// output order. `progress` hears the candidates removed over all rounds. The
/// caller validates.
template <int D>
std::vector<std::uint32_t> eliminate_indices(std::span<const Point<D>> points, std::span<const double> scale,
                                             std::size_t count, const Domain<D>& domain, double d_max,
                                             const EliminationWeights& weights, bool progressive, int growth_dim,
                                             const Progress& progress = {});

/// The same elimination with every removal taken from a heap, one at a time
/// (the paper's loop, as cySampleElim.h runs it): eliminate_indices removes
/// most candidates in sweeps instead, and must give exactly these indices in
/// this order. For tests.
template <int D>
std::vector<std::uint32_t> eliminate_indices_by_heap(std::span<const Point<D>> points, std::span<const double> scale,
                                                     std::size_t count, const Domain<D>& domain, double d_max,
                                                     const EliminationWeights& weights, bool progressive,
                                                     int growth_dim);

/// Throws InvalidArgument for weights out of range.
void validate_elimination_weights(const EliminationWeights& weights);

}  // namespace pds::detail
