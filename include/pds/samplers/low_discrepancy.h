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

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/registry.h"
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

/// The `scramble` and `first` parameters every sequence takes in the registry.
MethodParam scramble_param();
MethodParam first_param();

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
  const double x = (static_cast<double>(r) + tail) / static_cast<double>(DigitScale<B>::scale);
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
/// structure survives. Below the K-th digit every point's prefix is unique,
/// so the remaining digits of a nested scrambling are independent uniform
/// digits; they are drawn as one uniform tail from the hash of the full prefix.
template <unsigned B>
double owen_scramble(std::uint64_t r, std::uint64_t key) {
  constexpr int K = DigitScale<B>::digits;
  std::uint64_t out = 0;
  if constexpr (B == 2) {
    // A node at depth k is (1 << k) | its prefix: unique over all depths.
    for (int k = 0; k < K; ++k) {
      const std::uint64_t prefix = r >> (K - k);
      const std::uint64_t flip = mix64(key ^ ((std::uint64_t{1} << k) | prefix)) >> 63;
      out = (out << 1) | (((r >> (K - 1 - k)) & 1) ^ flip);
    }
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

/// The point u of the unit cube mapped to the domain's box; always in [lo, hi).
template <int D>
Point<D> from_unit_cube(const Point<D>& u, const Domain<D>& domain) {
  Point<D> p;
  for (int i = 0; i < D; ++i) {
    const double x = domain.lo[i] + u[i] * domain.extent(i);
    p[i] = x < domain.hi[i] ? x : std::nextafter(domain.hi[i], domain.lo[i]);
  }
  return p;
}

/// Calls f(std::integral_constant<unsigned, kPrimes[axis]>{}) so that digit
/// arithmetic divides by a compile-time constant.
template <class F>
decltype(auto) with_prime_base(int axis, F&& f) {
  switch (axis) {
    case 0:
      return f(std::integral_constant<unsigned, kPrimes[0]>{});
    case 1:
      return f(std::integral_constant<unsigned, kPrimes[1]>{});
    case 2:
      return f(std::integral_constant<unsigned, kPrimes[2]>{});
    case 3:
      return f(std::integral_constant<unsigned, kPrimes[3]>{});
    case 4:
      return f(std::integral_constant<unsigned, kPrimes[4]>{});
    case 5:
      return f(std::integral_constant<unsigned, kPrimes[5]>{});
    case 6:
      return f(std::integral_constant<unsigned, kPrimes[6]>{});
    default:
      return f(std::integral_constant<unsigned, kPrimes[7]>{});
  }
}

/// Radical inverses of consecutive indices in base B, with optional digit
/// permutation, at a few operations per index: incrementing the index changes
/// one digit plus its carries (on average B/(B-1) digits), and R follows by
/// adding each changed digit's difference.
template <unsigned B>
class RadicalInverseCursor {
 public:
  static constexpr int K = DigitScale<B>::digits;

  /// Starts at `index`; `perm` (may be null: no scrambling) must outlive the cursor.
  RadicalInverseCursor(std::uint32_t index, const DigitPermutation<B>* perm) : perm_(perm) {
    r_ = reverse_digits<B>(index);
    if (perm_) r_ = perm_->apply(r_);
    for (int k = 0; k < K; ++k) {
      digit_[k] = static_cast<std::uint8_t>(index % B);
      index /= B;
    }
  }

  double value() const { return digits_to_unit<B>(r_, perm_ ? perm_->tail() : 0.0); }

  /// Moves to the next index; the caller keeps the index below 2^32.
  void advance() {
    int k = 0;
    while (digit_[k] == B - 1) {
      r_ += (mapped(k, 0) - mapped(k, B - 1)) * weight(k);  // wraps modulo 2^64; the sum stays exact
      digit_[k++] = 0;
    }
    r_ += (mapped(k, digit_[k] + 1) - mapped(k, digit_[k])) * weight(k);
    ++digit_[k];
  }

 private:
  std::uint64_t mapped(int k, unsigned d) const { return perm_ ? perm_->map(k, d) : d; }
  static constexpr std::uint64_t weight(int k) { return kWeights[k]; }
  static constexpr std::array<std::uint64_t, K> kWeights = [] {
    std::array<std::uint64_t, K> w{};
    w[K - 1] = 1;
    for (int k = K - 2; k >= 0; --k) w[k] = w[k + 1] * B;
    return w;
  }();

  const DigitPermutation<B>* perm_;
  std::uint64_t r_;
  std::array<std::uint8_t, K> digit_;
};

/// Writes coordinate `axis` of points first, first+1, ..., first+count-1 of the
/// base-B radical-inverse sequence, scrambled as asked, into out[i][axis].
/// Unscrambled and digit-permuted runs walk the indices with a cursor; Owen
/// scrambling hashes every digit of every point, so it costs K hashes a value.
template <unsigned B, class Points>
void fill_radical_inverse(Points& out, int axis, std::uint32_t first, Scramble scramble, std::uint64_t key) {
  const std::size_t n = out.size();
  if (scramble == Scramble::owen) {
    for (std::size_t i = 0; i < n; ++i)
      out[i][axis] = owen_scramble<B>(reverse_digits<B>(static_cast<std::uint32_t>(first + i)), key);
    return;
  }
  DigitPermutation<B> perm(key);
  RadicalInverseCursor<B> cursor(first, scramble == Scramble::permute_digits ? &perm : nullptr);
  for (std::size_t i = 0; i < n; ++i) {
    out[i][axis] = cursor.value();
    if (i + 1 < n) cursor.advance();
  }
}

/// Maps every point of a set built in the unit cube to the domain, in place.
template <int D>
void map_to_domain(PointSet<D>& points, const Domain<D>& domain) {
  for (auto& p : points) p = from_unit_cube(p, domain);
}

}  // namespace pds
