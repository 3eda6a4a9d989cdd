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
#include <vector>

#include "pds/progress.h"
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

/// A box in a run-time dimension, lo[a] <= x[a] < hi[a]: what the run-time
/// paths of the sequences and designs fill (the typed Domain<D> versions call
/// the same code through CloudBox::of). The bounds are validated by the caller
/// (GenerateRequest::bounds, Domain<D>::validate).
struct CloudBox {
  std::vector<double> lo, hi;

  int dim() const { return static_cast<int>(lo.size()); }
  static CloudBox unit(int dim) {
    return {std::vector<double>(static_cast<std::size_t>(dim), 0.0), std::vector<double>(static_cast<std::size_t>(dim), 1.0)};
  }
  template <int D>
  static CloudBox of(const Domain<D>& domain) {
    return {std::vector<double>(domain.lo.begin(), domain.lo.end()), std::vector<double>(domain.hi.begin(), domain.hi.end())};
  }
};

/// UnitCubeMap in a run-time dimension: the same arithmetic, so the same bytes.
class BoxMap {
 public:
  explicit BoxMap(const CloudBox& box) : lo_(box.lo), extent_(box.lo.size()), top_(box.lo.size()) {
    for (std::size_t i = 0; i < lo_.size(); ++i) {
      extent_[i] = box.hi[i] - box.lo[i];
      top_[i] = std::nextafter(box.hi[i], box.lo[i]);
    }
  }
  double operator()(int axis, double u) const { return std::min(lo_[axis] + u * extent_[axis], top_[axis]); }
  // For loops that map a whole point at once.
  const double* lo() const { return lo_.data(); }
  const double* extent() const { return extent_.data(); }
  const double* top() const { return top_.data(); }

 private:
  std::vector<double> lo_, extent_, top_;
};

/// Throws InvalidArgument unless count points of dimension dim fit in memory
/// addressable here (count * dim doubles); returns count * dim.
std::size_t cloud_doubles(const std::string& method, std::uint64_t count, int dim);

/// A PointCloud of `count` points of the box's dimension, written by
/// fill(out) (out: count * dim doubles, point after point).
template <class Fill>
PointCloud fill_cloud(const std::string& method, std::uint64_t count, const CloudBox& box, Fill&& fill) {
  PointCloud cloud{box.dim(), {}};
  // In huge pages where offered: at 10^6 points the 4 KiB page faults of
  // the block were about half the run.
  const std::size_t doubles = cloud_doubles(method, count, box.dim());
  cloud.coords.reserve(doubles);
  detail::advise_huge_pages(cloud.coords.data(), doubles * sizeof(double));
  cloud.coords.resize(doubles);
  fill(cloud.coords.data());
  return cloud;
}

/// The Halton bases: the first kRadixPrimes primes (2, 3, 5, ..., 104729),
/// computed once. Halton takes one per axis, Hammersley one per axis past the first.
inline constexpr int kRadixPrimes = 10000;
unsigned nth_prime(int k);  // k in [0, kRadixPrimes)

/// How an unscrambled radical inverse is turned into a double.
enum class RadicalRounding : int {
  correct = 0,  // the digits as an exact integer, one correctly rounded division
  scipy = 1,    // SciPy's van_der_corput: sum of digit * b^-k, b^-k by repeated division (a few ulps off)
};

/// Fills out[i * dim + a], i < count, a in [lead, dim), with the radical
/// inverse of index first + i in base nth_prime(a - lead), scrambled as asked
/// (axis a's key: scramble_key(seed, method_tag, a)) and mapped by `map`;
/// axes below lead are left alone. Bases up to 19 draw their digit
/// permutations exactly as DigitPermutation / owen_scramble do; larger bases
/// use random affine digit permutations d -> (alpha d + beta) mod b (Matousek
/// 1998), which keep nets nets and every scrambled point uniform.
/// Unscrambled, `rounding` says how digits become a double. `progress`, if
/// given, hears the points written.
void fill_radical_inverses(std::uint32_t first, std::uint64_t count, int dim, int lead, Scramble scramble,
                           RadicalRounding rounding, std::uint64_t seed, std::uint64_t method_tag, const BoxMap& map,
                           double* out, ProgressReporter* progress = nullptr);

/// Maps every point of a set built in the unit cube to the domain, in place.
template <int D>
void map_to_domain(PointSet<D>& points, const Domain<D>& domain) {
  const UnitCubeMap<D> to_domain(domain);
  for (auto& p : points) p = to_domain(p);
}

}  // namespace pds
