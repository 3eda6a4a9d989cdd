#pragma once
// Building blocks shared by the low-discrepancy sequences (Halton, Hammersley,
// Sobol): digit reversal (the radical inverse), the two scramblings that keep
// a net a net (random digit permutation and Owen's nested scrambling), and the
// map from the unit cube to a request's domain.
//
// Every coordinate is carried as an integer R in [0, B^K): the first K base-B
// digits of a number in [0, 1), most significant first, where K is the least
// number of digits with B^K >= 2^32. Indices are below 2^32, so an index's
// radical inverse is exact in R, and scrambling permutes digits of R without
// rounding. Only the final conversion to double rounds (correctly, by one
// division), so the unscrambled sequences are exact to the last bit.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>
#include <utility>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/rng.h"

namespace pds {

/// How a digital sequence is randomised. All three keep the (t, m, s)-net
/// structure of the unscrambled points (Owen 1995; Matousek 1998).
enum class Scramble : int {
  none = 0,            // the exact published sequence; ignores the seed
  permute_digits = 1,  // one random permutation per digit position and axis (base 2: a random XOR)
  owen = 2,            // nested uniform scrambling: the permutation of a digit depends on all digits before it
};

/// Sequences are indexed by 32-bit integers: first + count must not exceed this.
inline constexpr std::uint64_t kSequenceIndexLimit = std::uint64_t{1} << 32;

/// Throws InvalidArgument unless [first, first + count) lies within the indices
/// a sequence supports.
void require_index_range(const std::string& method, std::uint64_t first, std::uint64_t count);

/// Throws InvalidArgument unless `value` names a Scramble.
Scramble scramble_from(const std::string& method, int value);


/// The bases of the Halton sequence, one per axis.
inline constexpr std::array<unsigned, 8> kPrimes{2, 3, 5, 7, 11, 13, 17, 19};

/// K and B^K for base B (see the top of this file).
template <unsigned B>
struct DigitScale {
  static_assert(B >= 2 && B <= 64);
  static constexpr int digits = [] {
    int k = 0;
    for (std::uint64_t p = 1; p < (std::uint64_t{1} << 32); p *= B) ++k;
    return k;
  }();
  static constexpr std::uint64_t scale = [] {
    std::uint64_t p = 1;
    for (int k = 0; k < digits; ++k) p *= B;
    return p;
  }();
};

/// The base-B digits of `index` in reverse order, as R (see above): the radical
/// inverse of index is R / B^K exactly.
template <unsigned B>
constexpr std::uint64_t reverse_digits(std::uint32_t index) {
  std::uint64_t r = 0;
  for (int k = 0; k < DigitScale<B>::digits; ++k) {
    r = r * B + index % B;
    index /= B;
  }
  return r;
}

/// R / B^K plus `tail` units of the last digit, correctly rounded and below 1.
template <unsigned B>
inline double digits_to_unit(std::uint64_t r, double tail = 0.0) {
  // r < B^K < 2^38: the signed conversion is exact and, unlike the unsigned one, a single instruction.
  const double x =
      (static_cast<double>(static_cast<std::int64_t>(r)) + tail) / static_cast<double>(DigitScale<B>::scale);
  return x < 1.0 ? x : 0x1.fffffffffffffp-1;
}

/// The radical inverse of `index` in base B: its digits mirrored about the
/// radix point (van der Corput 1935), correctly rounded.
template <unsigned B>
double radical_inverse(std::uint32_t index) {
  return digits_to_unit<B>(reverse_digits<B>(index));
}

/// A uniformly random permutation of {0, ..., B-1} drawn from the bits of h
/// (Fisher-Yates; the bias of h % k is below 2^-55 for B <= 19).
template <unsigned B>
std::array<std::uint8_t, B> digit_permutation(std::uint64_t h) {
  std::array<std::uint8_t, B> p;
  for (unsigned i = 0; i < B; ++i) p[i] = static_cast<std::uint8_t>(i);
  for (unsigned k = B; k > 1; --k) {
    const unsigned j = static_cast<unsigned>(h % k);
    h /= k;
    std::swap(p[k - 1], p[j]);
  }
  return p;
}

/// The key of one axis of one scrambled sequence: every random choice of the
/// scrambling is a hash of this key, so any point can be computed alone.
inline std::uint64_t scramble_key(std::uint64_t seed, std::uint64_t method_tag, int axis) {
  return mix64(mix64(seed ^ mix64(method_tag)) + static_cast<std::uint64_t>(axis) * 0x9e3779b97f4a7c15ULL);
}

/// Random digit permutation (Matousek's "random digit scrambling" with full
/// permutations): digit k of every point goes through the same permutation
/// pi_k. The digits past the K-th, all zero before scrambling, become the same
/// random tail for every point, kept as a fraction of the last digit.
template <unsigned B>
class DigitPermutation {
 public:
  static constexpr int K = DigitScale<B>::digits;

  explicit DigitPermutation(std::uint64_t key) {
    for (int k = 0; k < K; ++k) perm_[k] = digit_permutation<B>(mix64(key + 0x632be59bd9b4e019ULL * (k + 1)));
    tail_ = static_cast<double>(mix64(key ^ 0xd1b54a32d192ed03ULL) >> 11) * 0x1.0p-53;
    weight_[K - 1] = 1;
    for (int k = K - 2; k >= 0; --k) weight_[k] = weight_[k + 1] * B;
    if constexpr (B == 2)
      for (int k = 0; k < K; ++k) xor_mask_ |= static_cast<std::uint64_t>(perm_[k][0]) * weight_[k];
  }

  /// Digit k (0: most significant) mapped through pi_k.
  std::uint8_t map(int k, unsigned digit) const { return perm_[k][digit]; }
  /// The weight of digit k in R.
  std::uint64_t weight(int k) const { return weight_[k]; }
  double tail() const { return tail_; }

  /// R with every digit permuted.
  std::uint64_t apply(std::uint64_t r) const {
    if constexpr (B == 2) {
      return r ^ xor_mask_;  // a permutation of {0, 1} either keeps or flips the bit
    } else {
      std::uint64_t out = 0;
      for (int k = K - 1; k >= 0; --k) {
        out += perm_[k][r % B] * weight_[k];
        r /= B;
      }
      return out;
    }
  }

 private:
  std::array<std::array<std::uint8_t, B>, K> perm_;
  std::array<std::uint64_t, K> weight_;
  std::uint64_t xor_mask_ = 0;
  double tail_ = 0;
};

/// Owen's nested uniform scrambling of R (Owen 1995): digit k goes through a
/// random permutation chosen by hashing (key, k, the k digits above it), so
/// points that share a leading digit prefix are permuted alike and the net
/// structure survives (in base 2 one hash covers 6 levels of the digit tree). Below the K-th digit every point's prefix
/// is unique, so the remaining digits of a nested scrambling are independent uniform digits; they are drawn as one
/// uniform tail from the hash of the full prefix.
template <unsigned B>
double owen_scramble(std::uint64_t r, std::uint64_t key) {
  constexpr int K = DigitScale<B>::digits;
  std::uint64_t out = 0;
  if constexpr (B == 2) {
    // One 64-bit hash serves a whole subtree of 6 levels: the subtree's root
    // (depth top, named (1 << top) | prefix, unique over all depths) is hashed
    // and its 63 nodes take bits 1 ... 63 of the hash in heap order (child of
    // j with digit d: 2j + d). Every node still gets its own uniform bit, at a
    // sixth of the hashes of one hash per node.
    constexpr int kLevels = 6;
    std::uint64_t flips = 0;
    for (int top = 0; top < K; top += kLevels) {
      const std::uint64_t h = mix64(key ^ ((std::uint64_t{1} << top) | (r >> (K - top))));
      std::uint64_t node = 1;
      for (int k = top; k < top + kLevels && k < K; ++k) {
        const std::uint64_t digit = (r >> (K - 1 - k)) & 1;
        flips |= ((h >> node) & 1) << (K - 1 - k);
        node = 2 * node + digit;
      }
    }
    out = r ^ flips;
  } else {
    std::array<std::uint8_t, K> digit;
    std::uint64_t rest = r;
    for (int k = K - 1; k >= 0; --k) {
      digit[k] = static_cast<std::uint8_t>(rest % B);
      rest /= B;
    }
    // A node at depth k is B^k + its prefix (prefix < B^k): unique over all depths.
    std::uint64_t prefix = 0, level = 1;
    for (int k = 0; k < K; ++k) {
      out = out * B + digit_permutation<B>(mix64(key ^ (level + prefix)))[digit[k]];
      prefix = prefix * B + digit[k];
      level *= B;
    }
  }
  const std::uint64_t leaf = DigitScale<B>::scale + r;
  const double tail = static_cast<double>(mix64(key ^ leaf ^ 0xa0761d6478bd642fULL) >> 11) * 0x1.0p-53;
  return digits_to_unit<B>(out, tail);
}

/// The map from the unit cube to a domain's box, x = lo + u (hi - lo), with a
/// result that rounds up to hi (or past it, if hi - lo rounded up) moved to
/// the largest double below hi: always in [lo, hi). Set up once per set.
template <int D>
class UnitCubeMap {
 public:
  explicit UnitCubeMap(const Domain<D>& domain) {
    for (int i = 0; i < D; ++i) {
      lo_[i] = domain.lo[i];
      extent_[i] = domain.extent(i);
      top_[i] = std::nextafter(domain.hi[i], domain.lo[i]);
    }
  }
  double operator()(int axis, double u) const { return std::min(lo_[axis] + u * extent_[axis], top_[axis]); }
  Point<D> operator()(const Point<D>& u) const {
    Point<D> p;
    for (int i = 0; i < D; ++i) p[i] = (*this)(i, u[i]);
    return p;
  }

 private:
  std::array<double, D> lo_, extent_, top_;
};

/// The point u of the unit cube mapped to the domain's box (UnitCubeMap).
template <int D>
Point<D> from_unit_cube(const Point<D>& u, const Domain<D>& domain) {
  return UnitCubeMap<D>(domain)(u);
}

/// Radical inverses of consecutive indices in base B, with optional digit
/// permutation, at a table look-up, an addition and a division each. An index
/// i = h L + l (L = B^k <= 1024) has R(i) = low[l] + high(h): the k low digits
/// of i only set the k leading digits of R. low[] is tabulated once; high(h)
/// is recomputed every L indices.
template <unsigned B>
class RadicalInverseWalk {
 public:
  static constexpr std::uint32_t kLow = [] {
    std::uint32_t l = 1;
    while (l * B <= 1024) l *= B;
    return l;
  }();

  /// Starts at `index`; `perm` (null: no scrambling) must outlive the walk.
  RadicalInverseWalk(std::uint32_t index, const DigitPermutation<B>* perm)
      : perm_(perm), tail_(perm ? perm->tail() : 0.0), high_(index / kLow), low_index_(index % kLow) {
    for (std::uint32_t l = 0; l < kLow; ++l) low_[l] = permuted(reverse_digits<B>(l));
    high_r_ = high_part(high_);
  }

  /// The radical inverse of the current index; then moves to the next index.
  double next() {
    const double x = digits_to_unit<B>(low_[low_index_] + high_r_, tail_);
    if (++low_index_ == kLow) {
      low_index_ = 0;
      high_r_ = high_part(++high_);
    }
    return x;
  }

 private:
  std::uint64_t permuted(std::uint64_t r) const { return perm_ ? perm_->apply(r) : r; }
  // The digits of h L, less the permuted zeros of its k low digits that low[] holds.
  std::uint64_t high_part(std::uint64_t h) const {
    const std::uint64_t index = h * kLow;
    if (index >= (std::uint64_t{1} << 32)) return 0;  // past the last index: never read
    return permuted(reverse_digits<B>(static_cast<std::uint32_t>(index))) - low_[0];
  }

  const DigitPermutation<B>* perm_;
  double tail_;
  std::uint64_t high_;
  std::uint32_t low_index_;
  std::uint64_t high_r_ = 0;
  std::array<std::uint64_t, kLow> low_;
};

namespace detail {

template <int D, int Lead, std::size_t... A, class LeadFn>
void fill_radical_inverse_points(std::index_sequence<A...>, PointSet<D>& points, std::uint32_t first, Scramble scramble,
                                 const std::array<std::uint64_t, D>& keys, const Domain<D>& domain, LeadFn& lead) {
  const std::size_t n = points.size();
  const UnitCubeMap<D> to_domain(domain);
  if (scramble == Scramble::owen) {
    for (std::size_t i = 0; i < n; ++i) {
      const auto index = static_cast<std::uint32_t>(first + i);
      Point<D> u;
      lead(index, u);
      ((u[Lead + A] = owen_scramble<kPrimes[A]>(reverse_digits<kPrimes[A]>(index), keys[Lead + A])), ...);
      points[i] = to_domain(u);
    }
    return;
  }
  const std::tuple<DigitPermutation<kPrimes[A]>...> perms{DigitPermutation<kPrimes[A]>(keys[Lead + A])...};
  const bool permute = scramble == Scramble::permute_digits;
  std::tuple<RadicalInverseWalk<kPrimes[A]>...> walks{
      RadicalInverseWalk<kPrimes[A]>(first, permute ? &std::get<A>(perms) : nullptr)...};
  for (std::size_t i = 0; i < n; ++i) {
    Point<D> u;
    lead(static_cast<std::uint32_t>(first + i), u);
    ((u[Lead + A] = std::get<A>(walks).next()), ...);
    points[i] = to_domain(u);
  }
}

}  // namespace detail

/// Fills points[i] with point first + i of a radical-inverse construction:
/// axes Lead ... D-1 are the radical inverses of the index in bases 2, 3, 5,
/// ... (scrambled as asked, axis a with keys[a]), axes below Lead are set by
/// lead(index, u) (Hammersley's i / N); then the unit cube is mapped to the
/// domain. Unscrambled and digit-permuted runs walk the indices (RadicalInverseWalk);
/// Owen scrambling walks every digit of every coordinate (owen_scramble).
template <int D, int Lead = 0, class LeadFn>
void fill_radical_inverse_points(PointSet<D>& points, std::uint32_t first, Scramble scramble,
                                 const std::array<std::uint64_t, D>& keys, const Domain<D>& domain, LeadFn&& lead) {
  static_assert(D - Lead <= static_cast<int>(kPrimes.size()));
  detail::fill_radical_inverse_points<D, Lead>(std::make_index_sequence<D - Lead>{}, points, first, scramble, keys,
                                               domain, lead);
}

/// Maps every point of a set built in the unit cube to the domain, in place.
template <int D>
void map_to_domain(PointSet<D>& points, const Domain<D>& domain) {
  const UnitCubeMap<D> to_domain(domain);
  for (auto& p : points) p = to_domain(p);
}

}  // namespace pds
