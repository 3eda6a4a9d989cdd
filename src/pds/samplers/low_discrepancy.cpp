// Checks shared by the low-discrepancy sequences, and the radical inverses in
// run-time bases that Halton and Hammersley fill any dimension with; the
// compile-time digit arithmetic is inline in the header (see there for the
// design).
//
// Radical inverses in run-time bases: one odometer per axis holds the base-b
// digits of the current index, the integer R of its reversed digits and, for
// random digit permutation, the permuted R; moving to the next index changes
// one digit in (b-1)/b of the steps, so a coordinate costs O(1) integer work
// plus the conversion. SciPy's rounding (RadicalRounding::scipy) sums the
// digits as SciPy's van_der_corput does, one multiply-add per digit of the
// index: the file is compiled without contraction (-ffp-contract=off), so no
// target fuses them and the sums equal SciPy's on every machine.
// Scrambling in bases up to 19 reuses DigitPermutation's and owen_scramble's
// draws exactly (the 2D/3D output of every earlier version is unchanged);
// past 19 a digit's permutation is affine, d -> (alpha d + beta) mod b with
// alpha in [1, b) and beta in [0, b) from one hash: a bijection (b prime), so
// nets stay nets, and uniform for every digit value, so every scrambled point
// is uniform in the cube. A full random permutation of 10^5 digits per node
// would cost 10^5 times more for nothing the tests could tell apart.

#include "pds/samplers/low_discrepancy.h"

#include <limits>
#include <mutex>

#include "pds/error.h"

namespace pds {

void require_index_range(const std::string& method, std::uint64_t first, std::uint64_t count) {
  if (first >= kSequenceIndexLimit || count > kSequenceIndexLimit - first)
    throw InvalidArgument(method + ": indices first " + std::to_string(first) + " + count " + std::to_string(count) +
                          " exceed the sequence's 2^32 points");
}

Scramble scramble_from(const std::string& method, int value) {
  if (value < 0 || value > 2)
    throw InvalidArgument(method + ": scramble must be 0 (none), 1 (digit permutation) or 2 (Owen), got " +
                          std::to_string(value));
  return static_cast<Scramble>(value);
}

std::size_t cloud_doubles(const std::string& method, std::uint64_t count, int dim) {
  if (dim < 1 || dim > kMaxCloudDim)
    throw InvalidArgument(method + ": dimension " + std::to_string(dim) + " is not supported (supported: 1 to " +
                          std::to_string(kMaxCloudDim) + ")");
  const std::uint64_t limit = std::numeric_limits<std::size_t>::max() / sizeof(double) / static_cast<std::uint64_t>(dim);
  if (count > limit)
    throw InvalidArgument(method + ": " + std::to_string(count) + " points of dimension " + std::to_string(dim) +
                          " exceed the addressable memory");
  return static_cast<std::size_t>(count) * static_cast<std::size_t>(dim);
}

unsigned nth_prime(int k) {
  static const std::vector<unsigned> primes = [] {
    // The 10,000th prime is 104,729: sieve below 104,730.
    const unsigned n = 104730;
    std::vector<bool> composite(n, false);
    std::vector<unsigned> out;
    out.reserve(kRadixPrimes);
    for (unsigned p = 2; p < n && out.size() < static_cast<std::size_t>(kRadixPrimes); ++p) {
      if (composite[p]) continue;
      out.push_back(p);
      for (std::uint64_t q = std::uint64_t{p} * p; q < n; q += p) composite[q] = true;
    }
    return out;
  }();
  if (k < 0 || k >= static_cast<int>(primes.size()))
    throw InvalidArgument("radical inverse: axis " + std::to_string(k) + " is past the " +
                          std::to_string(primes.size()) + " prime bases");
  return primes[static_cast<std::size_t>(k)];
}

namespace {

// Fisher-Yates from the bits of h, as digit_permutation<B> (B <= 19).
void small_permutation(std::uint64_t h, unsigned b, std::uint32_t* p) {
  for (unsigned i = 0; i < b; ++i) p[i] = i;
  for (unsigned k = b; k > 1; --k) {
    const unsigned j = static_cast<unsigned>(h % k);
    h /= k;
    std::swap(p[k - 1], p[j]);
  }
}

constexpr unsigned kLargestTabulatedBase = 19;

/// One axis: base, digit scale, odometer, scrambling.
class RadixAxis {
 public:
  RadixAxis(unsigned base, Scramble scramble, std::uint64_t key) : b_(base), key_(key), scramble_(scramble) {
    std::uint64_t p = 1;
    while (p < (std::uint64_t{1} << 32)) {
      p *= b_;
      ++k_;
    }
    scale_ = p;
    weight_.assign(static_cast<std::size_t>(k_), 1);
    for (int k = k_ - 2; k >= 0; --k) weight_[k] = weight_[k + 1] * b_;
    scipy_weight_.resize(static_cast<std::size_t>(k_));
    double w = 1.0 / b_;
    for (int k = 0; k < k_; ++k, w /= b_) scipy_weight_[k] = w;
    digit_.assign(static_cast<std::size_t>(k_), 0);
    if (scramble_ == Scramble::permute_digits) {
      tail_ = static_cast<double>(mix64(key_ ^ 0xd1b54a32d192ed03ULL) >> 11) * 0x1.0p-53;
      if (b_ <= kLargestTabulatedBase) {
        table_.resize(static_cast<std::size_t>(k_) * b_);
        for (int k = 0; k < k_; ++k)
          small_permutation(mix64(key_ + 0x632be59bd9b4e019ULL * (k + 1)), b_, &table_[static_cast<std::size_t>(k) * b_]);
      } else {
        affine_.resize(static_cast<std::size_t>(k_));
        for (int k = 0; k < k_; ++k) affine_[k] = affine(mix64(key_ + 0x632be59bd9b4e019ULL * (k + 1)));
      }
    }
  }

  void start(std::uint32_t index) {
    r_ = rp_ = 0;
    used_ = 0;
    for (int k = 0; k < k_; ++k) {
      digit_[k] = index % b_;
      index /= b_;
      if (digit_[k]) used_ = k + 1;
      r_ += digit_[k] * weight_[k];
      if (scramble_ == Scramble::permute_digits) rp_ += perm(k, digit_[k]) * weight_[k];
    }
  }

  void advance() {
    const bool permute = scramble_ == Scramble::permute_digits;
    for (int k = 0; k < k_; ++k) {
      const std::uint32_t old = digit_[k];
      const std::uint32_t next = old + 1 == b_ ? 0 : old + 1;
      digit_[k] = next;
      r_ = r_ - old * weight_[k] + next * weight_[k];
      if (permute) rp_ = rp_ - perm(k, old) * weight_[k] + perm(k, next) * weight_[k];
      if (next != 0) {
        if (k >= used_) used_ = k + 1;
        return;
      }
    }
  }

  double value(RadicalRounding rounding) const {
    switch (scramble_) {
      case Scramble::none:
        // In base 2 SciPy's sums are exact (dyadic, under 53 bits): the exact value is theirs.
        if (rounding == RadicalRounding::scipy && b_ != 2) {
          double s = 0.0;
          for (int k = 0; k < used_; ++k) s += static_cast<double>(digit_[k]) * scipy_weight_[k];
          return s;
        }
        return to_unit(r_, 0.0);
      case Scramble::permute_digits:
        return to_unit(rp_, tail_);
      case Scramble::owen:
        return owen();
    }
    return 0.0;
  }

 private:
  struct Affine {
    std::uint64_t alpha, beta;
  };
  Affine affine(std::uint64_t h) const { return {1 + h % (b_ - 1), (h / (b_ - 1)) % b_}; }
  std::uint64_t perm(int k, std::uint32_t d) const {
    if (!table_.empty()) return table_[static_cast<std::size_t>(k) * b_ + d];
    return (affine_[k].alpha * d + affine_[k].beta) % b_;
  }
  double to_unit(std::uint64_t r, double tail) const {
    const double x = (static_cast<double>(static_cast<std::int64_t>(r)) + tail) / static_cast<double>(scale_);
    return x < 1.0 ? x : 0x1.fffffffffffffp-1;
  }
  double owen() const {
    switch (b_) {
      case 2: return owen_scramble<2>(r_, key_);
      case 3: return owen_scramble<3>(r_, key_);
      case 5: return owen_scramble<5>(r_, key_);
      case 7: return owen_scramble<7>(r_, key_);
      case 11: return owen_scramble<11>(r_, key_);
      case 13: return owen_scramble<13>(r_, key_);
      case 17: return owen_scramble<17>(r_, key_);
      case 19: return owen_scramble<19>(r_, key_);
      default: break;
    }
    // As owen_scramble<B>: node (depth k, prefix) is b^k + prefix, its
    // permutation drawn from the hash of (key, node); the tail from the leaf.
    std::uint64_t out = 0, prefix = 0, level = 1;
    for (int k = 0; k < k_; ++k) {
      const std::uint64_t d = digit_[k];  // R's digits, most significant first: the index's, least first
      const Affine f = affine(mix64(key_ ^ (level + prefix)));
      out = out * b_ + (f.alpha * d + f.beta) % b_;
      prefix = prefix * b_ + d;
      level *= b_;
    }
    const std::uint64_t leaf = scale_ + r_;
    const double tail = static_cast<double>(mix64(key_ ^ leaf ^ 0xa0761d6478bd642fULL) >> 11) * 0x1.0p-53;
    return to_unit(out, tail);
  }

  unsigned b_;
  std::uint64_t key_;
  Scramble scramble_;
  int k_ = 0;
  int used_ = 0;
  std::uint64_t scale_ = 1;
  std::vector<std::uint64_t> weight_;
  std::vector<double> scipy_weight_;
  std::vector<std::uint32_t> digit_;  // digit k of the index: weight b^k in the index, weight_[k] in R
  std::uint64_t r_ = 0, rp_ = 0;
  std::vector<std::uint32_t> table_;
  std::vector<Affine> affine_;
  double tail_ = 0.0;
};

}  // namespace

void fill_radical_inverses(std::uint32_t first, std::uint64_t count, int dim, int lead, Scramble scramble,
                           RadicalRounding rounding, std::uint64_t seed, std::uint64_t method_tag, const BoxMap& map,
                           double* out, ProgressReporter* progress) {
  std::vector<RadixAxis> axes;
  axes.reserve(static_cast<std::size_t>(dim - lead));
  for (int a = lead; a < dim; ++a) {
    axes.emplace_back(nth_prime(a - lead), scramble, scramble_key(seed, method_tag, a));
    axes.back().start(first);
  }
  const auto stride = static_cast<std::size_t>(dim);
  for (std::uint64_t i = 0; i < count; ++i) {
    if (progress && (i & 1023) == 0) progress->update(static_cast<double>(i));
    double* p = out + i * stride;
    for (int a = lead; a < dim; ++a) {
      RadixAxis& axis = axes[static_cast<std::size_t>(a - lead)];
      p[a] = map(a, axis.value(rounding));
      if (i + 1 < count) axis.advance();
    }
  }
}

}  // namespace pds
