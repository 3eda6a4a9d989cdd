#pragma once
// The seeded random generator every sampler uses.
//
// xoshiro256++ (Blackman & Vigna 2018): 256 bits of state, period 2^256 - 1,
// passes BigCrush, a few cycles a number. Only integer arithmetic and exact
// conversions are used, so a seed gives the same stream on every platform and
// compiler (std::*_distribution gives no such promise, so none is used).
//
// Streams are split by key, not by sequence: Rng(seed, key...) hashes the seed
// and the keys with SplitMix64 into an independent state. A parallel method
// derives a cell's generator from (seed, level, cell), never from the thread
// that happens to run it, so its output does not depend on the thread count.

#include <cmath>
#include <cstdint>
#include <initializer_list>

namespace pds {

__extension__ typedef unsigned __int128 u128;  // GCC/Clang; exact 64x64 products

/// SplitMix64 finaliser: a bijective 64-bit mix with good avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class Rng {
 public:
  /// The stream for `seed`, optionally split by keys (cell index, level, ...).
  explicit Rng(std::uint64_t seed, std::initializer_list<std::uint64_t> keys = {}) {
    std::uint64_t h = mix64(seed + 0x9e3779b97f4a7c15ULL);
    for (std::uint64_t k : keys) h = mix64(h ^ mix64(k + 0x632be59bd9b4e019ULL));
    // Expand the hash into four state words with SplitMix64's sequence.
    for (auto& s : state_) {
      h += 0x9e3779b97f4a7c15ULL;
      s = mix64(h);
    }
  }

  /// An independent child stream; the parent is unchanged.
  Rng split(std::uint64_t key) const {
    return Rng(state_[0] ^ mix64(state_[1]) ^ mix64(state_[2] + 1) ^ state_[3], {key});
  }

  /// 64 uniformly distributed bits.
  std::uint64_t next() {
    const std::uint64_t result = rotl(state_[0] + state_[3], 23) + state_[0];
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

  /// Uniform in [0, 1), a multiple of 2^-53.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  /// Uniform in [lo, hi); the rounding that could give hi is mapped below it.
  double uniform(double lo, double hi) {
    const double x = lo + (hi - lo) * uniform();
    return x < hi ? x : std::nextafter(hi, lo);
  }

  /// Uniform integer in [0, n), n > 0, without bias (Lemire 2019).
  std::uint64_t below(std::uint64_t n) {
    u128 m = static_cast<u128>(next()) * n;
    auto low = static_cast<std::uint64_t>(m);
    if (low < n) {
      const std::uint64_t threshold = (0 - n) % n;
      while (low < threshold) {
        m = static_cast<u128>(next()) * n;
        low = static_cast<std::uint64_t>(m);
      }
    }
    return static_cast<std::uint64_t>(m >> 64);
  }

 private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t state_[4];
};

}  // namespace pds
