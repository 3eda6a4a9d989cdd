// Sobol sequence.
//
// I. M. Sobol, On the distribution of points in a cube and the approximate
// evaluation of integrals, USSR Comput. Math. Math. Phys. 7(4), 1967.
// Direction numbers: S. Joe and F. Y. Kuo, Constructing Sobol sequences with
// better two-dimensional projections, SIAM J. Sci. Comput. 30(5), 2008 (the
// first rows of their new-joe-kuo-6.21201 table). Gray-code order: I. A.
// Antonov and V. M. Saleev, USSR Comput. Math. Math. Phys. 19(1), 1979.
// Scrambling: A. B. Owen, Randomly permuted (t,m,s)-nets and (t,s)-sequences,
// 1995.
//
// Method: axis a of point i is the XOR of the direction numbers v_a[k] over
// the set bits k of gray(i) = i ^ (i >> 1); consecutive Gray codes differ in
// bit ctz(i + 1), so walking a range costs one XOR per coordinate after a
// direct computation of its first point.
// Guarantees: see sobol.h; in 2D the sequence is a (0, 2)-sequence in base 2.
// Complexity: O(count * D), about one XOR, one conversion and one multiply-add
// a coordinate unscrambled; Owen scrambling walks all 32 bits (6 hashes).
// Limits: indices below 2^32 (32-bit direction numbers); up to kSobolMaxDim axes.
// Why not GSL's gsl_qrng_sobol: it only steps forward from the start (no
// random access to a range), has no scrambling, and costs a call per point;
// the code here is a few lines. The tests compare the two point by point.

#include "pds/samplers/sobol.h"

#include <bit>

#include "pds/error.h"

namespace pds {
namespace {

struct PrimitivePolynomial {
  int degree;                            // s
  unsigned interior;                     // a: the coefficients of x^(s-1) ... x^1, highest first
  std::array<std::uint32_t, 5> initial;  // m_1 ... m_s
};

// Joe & Kuo, new-joe-kuo-6.21201, rows d = 2 ... 8 (axis 0 is van der Corput).
constexpr std::array<PrimitivePolynomial, kSobolMaxDim - 1> kJoeKuo{{
    {1, 0, {1}},
    {2, 1, {1, 3}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}},
    {4, 4, {1, 3, 5, 13}},
    {5, 2, {1, 1, 5, 5, 17}},
}};

struct DirectionTable {
  std::array<std::array<std::uint32_t, 32>, kSobolMaxDim> v;
  DirectionTable() {
    for (int axis = 0; axis < kSobolMaxDim; ++axis) v[axis] = sobol_directions(axis);
  }
};

const DirectionTable& directions() {
  static const DirectionTable table;
  return table;
}

}  // namespace

std::array<std::uint32_t, 32> sobol_directions(int axis) {
  if (axis < 0 || axis >= kSobolMaxDim)
    throw InvalidArgument("sobol: axis " + std::to_string(axis) + " is beyond the " + std::to_string(kSobolMaxDim) +
                          " embedded axes");
  std::array<std::uint32_t, 32> v{};
  if (axis == 0) {
    for (int k = 0; k < 32; ++k) v[k] = std::uint32_t{1} << (31 - k);
    return v;
  }
  const PrimitivePolynomial& p = kJoeKuo[axis - 1];
  const int s = p.degree;
  for (int k = 0; k < s; ++k) v[k] = p.initial[k] << (31 - k);
  // Bratley & Fox's recurrence on left-aligned direction numbers.
  for (int k = s; k < 32; ++k) {
    v[k] = v[k - s] ^ (v[k - s] >> s);
    for (int l = 1; l < s; ++l)
      if ((p.interior >> (s - 1 - l)) & 1) v[k] ^= v[k - l];
  }
  return v;
}

template <int D>
PointSet<D> sobol(const SobolParams& params, const Domain<D>& domain, std::uint64_t seed) {
  static_assert(D <= kSobolMaxDim);
  require_index_range("sobol", params.first, params.count);
  const auto& v = directions().v;

  // The first point directly from its Gray code, the others by one XOR each.
  std::array<std::uint32_t, D> x{};
  const auto first = static_cast<std::uint32_t>(params.first);
  const std::uint32_t gray = first ^ (first >> 1);
  for (int a = 0; a < D; ++a)
    for (int k = 0; k < 32; ++k)
      if ((gray >> k) & 1) x[a] ^= v[a][k];

  std::array<std::uint64_t, D> key{};
  std::array<std::uint64_t, D> shift{};
  std::array<double, D> tail{};
  for (int a = 0; a < D; ++a) {
    key[a] = scramble_key(seed, 3, a);
    const DigitPermutation<2> perm(key[a]);
    shift[a] = perm.apply(0);  // the XOR mask of a base-2 digit permutation
    tail[a] = perm.tail();
  }

  const UnitCubeMap<D> to_domain(domain);
  PointSet<D> points(params.count);
  // One loop per scrambling, so that the choice is not re-made per coordinate.
  auto walk = [&](auto mode) {
    constexpr Scramble scramble = decltype(mode)::value;
    for (std::uint64_t i = 0; i < params.count; ++i) {
      for (int a = 0; a < D; ++a) {
        double u;
        if constexpr (scramble == Scramble::none)
          u = x[a] * 0x1.0p-32;
        else if constexpr (scramble == Scramble::permute_digits)
          u = digits_to_unit<2>(x[a] ^ shift[a], tail[a]);
        else
          u = owen_scramble<2>(x[a], key[a]);
        points[i][a] = to_domain(a, u);
      }
      const int bit = std::countr_zero(static_cast<std::uint32_t>(first + i + 1));  // 32 after the last index
      if (bit < 32)
        for (int a = 0; a < D; ++a) x[a] ^= v[a][bit];
    }
  };
  switch (params.scramble) {
    case Scramble::none:
      walk(std::integral_constant<Scramble, Scramble::none>{});
      break;
    case Scramble::permute_digits:
      walk(std::integral_constant<Scramble, Scramble::permute_digits>{});
      break;
    case Scramble::owen:
      walk(std::integral_constant<Scramble, Scramble::owen>{});
      break;
  }
  return points;
}

template PointSet<2> sobol<2>(const SobolParams&, const Domain<2>&, std::uint64_t);
template PointSet<3> sobol<3>(const SobolParams&, const Domain<3>&, std::uint64_t);

}  // namespace pds
