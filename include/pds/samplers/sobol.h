#pragma once
// The Sobol sequence (Sobol 1967) with Joe and Kuo's direction numbers,
// optionally with a random digital shift or Owen's nested scrambling.

#include <array>
#include <cstdint>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/samplers/low_discrepancy.h"

namespace pds {

/// Axes for which direction numbers are embedded (Joe & Kuo's first rows).
inline constexpr int kSobolMaxDim = 8;

struct SobolParams {
  std::uint64_t count = 1024;  // points returned, >= 1
  std::uint64_t first = 0;     // index of the first point; first + count <= 2^32
  Scramble scramble = Scramble::none;
};

/// Points first, ..., first + count - 1 of the D-dimensional Sobol sequence in
/// Gray-code order (the order of Joe and Kuo's reference generator, MATLAB's
/// sobolset and SciPy: (0,0), (1/2,1/2), (3/4,1/4), (1/4,3/4), ...), mapped
/// from the unit cube to the domain. Progressive: any range costs only its
/// own length. Permuting digits with permute_digits is, in base 2, an XOR
/// with one random mask per axis (a random digital shift).
/// Guarantees: unscrambled, the exact sequence whatever the seed; every
/// aligned block of 2^m points (indices k 2^m ... (k+1) 2^m - 1) is a
/// (t, m, D)-net in base 2, with t = 0 in 2D (every elementary box of volume
/// 2^-m holds exactly one point), scrambled or not. Every point in [lo, hi);
/// same seed, same points.
/// Invalid: first + count above 2^32.
template <int D>
PointSet<D> sobol(const SobolParams& params, const Domain<D>& domain, std::uint64_t seed);

/// The 32 direction numbers of one axis (0-based, axis < kSobolMaxDim): bit k
/// of an index's Gray code contributes direction[k] to the coordinate * 2^32.
std::array<std::uint32_t, 32> sobol_directions(int axis);

}  // namespace pds
