#pragma once
// The Sobol sequence (Sobol 1967) with Joe and Kuo's direction numbers,
// optionally with a random digital shift or Owen's nested scrambling.

#include <array>
#include <cstdint>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/samplers/low_discrepancy.h"

namespace pds {

/// Axes for which direction numbers are embedded: axis 0 (van der Corput)
/// and Joe & Kuo's new-joe-kuo-6.21201 rows d = 2 ... 21201
/// (data/sobol/, scripts/sobol_directions.py).
inline constexpr int kSobolMaxDim = 21201;

struct SobolParams {
  std::uint64_t count = 1024;  // points returned, >= 1
  std::uint64_t first = 0;     // index of the first point; first + count <= 2^32
  Scramble scramble = Scramble::none;
  // Optional progress (points written, against the count) and cancellation (pds/progress.h).
  Progress progress;
};

/// Points first, ..., first + count - 1 of the D-dimensional Sobol sequence in
/// Gray-code order (the order of Joe and Kuo's reference generator, MATLAB's
/// sobolset and SciPy: (0,0), (1/2,1/2), (3/4,1/4), (1/4,3/4), ...; index i
/// is row i of scipy.stats.qmc.Sobol(d, scramble=False).random, which
/// starts at the origin, and the unscrambled points equal SciPy's), mapped
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

/// The same in a run-time dimension, 1 to kSobolMaxDim (box.dim()), point
/// after point; the typed version is this one.
PointCloud sobol(const SobolParams& params, const CloudBox& box, std::uint64_t seed);
/// Writes the points to out (count * box.dim() doubles): a caller can fill
/// one buffer block after block (first = 0, n, 2n, ...).
void sobol_fill(const SobolParams& params, const CloudBox& box, std::uint64_t seed, double* out);

/// The 32 direction numbers of one axis (0-based, axis < kSobolMaxDim): bit k
/// of an index's Gray code contributes direction[k] to the coordinate * 2^32.
std::array<std::uint32_t, 32> sobol_directions(int axis);

}  // namespace pds
