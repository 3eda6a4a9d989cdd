#pragma once
// Bridson's candidate offsets, shared by the uniform loop (bridson.cpp) and
// the constrained one (constrained.cpp, at unit radius, scaled by each
// active sample's own radius).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "pds/point.h"
#include "pds/rng.h"
#include "pds/samplers/bridson.h"

namespace pds::detail {

// Offsets uniform (by volume) in the annulus r <= |v| <= 2r, by rejection
// from the cube [-2r, 2r]^D: exact and platform-independent (59% of draws
// accepted in 2D, 46% in 3D). An offset does not depend on the centre it is
// added to, so they are drawn ahead in batches, which changes nothing in
// distribution but lets the batch loop keep a draw without a branch (a
// rejected draw is overwritten by the next): drawn one at a time, the
// rejection test is mispredicted about every other candidate. Each axis has
// its own stream (split from the seed), so the D generators run side by side
// instead of one after the other.
// With `surface` each accepted offset is scaled onto the sphere of radius
// kSurfaceRadius r (its direction is uniform, as that of any uniform point of
// the annulus is). Bits 32 (SciPy's loop) takes two coordinates from a draw.
template <int D, int Bits>
class AnnulusOffsets {
  static_assert(Bits == 53 || Bits == 32);

 public:
  AnnulusOffsets(double r, bool surface, std::uint64_t seed)
      : inner2_(r * r),
        outer2_(4.0 * r * r),
        step_(2.0 * r * (Bits == 53 ? 0x1.0p-52 : 0x1.0p-31)),
        sphere_(surface ? kSurfaceRadius * r : 0.0),
        streams_(make_streams(seed, std::make_index_sequence<D>())) {}

  [[gnu::always_inline]] const Point<D>& next() {
    if (next_ == kBatch) refill();
    return batch_[next_++];
  }

 private:
  void refill() {
    std::size_t n = 0;
    while (n < kBatch) {
      if constexpr (Bits == 53) {
        Point<D> v;
        for (int i = 0; i < D; ++i) {
          // Uniform in [-2r, 2r) on a grid of 2r 2^-52: the top 53 bits as a
          // signed value times `step_` (one rounding, as (value 2^-52) 2r has).
          v[i] = static_cast<double>(static_cast<std::int64_t>(streams_[i].next()) >> 11) * step_;
        }
        n += keep(v, n);
      } else {
        // Two numbers a draw: the low and the high 32 bits as signed values
        // on a grid of 2r 2^-31.
        std::array<std::uint64_t, D> words;
        for (int i = 0; i < D; ++i) words[i] = streams_[i].next();
        for (int half = 0; half < 2; ++half) {
          Point<D> v;
          for (int i = 0; i < D; ++i) {
            const int j = half * D + i;
            const auto bits = static_cast<std::uint32_t>(words[static_cast<std::size_t>(j / 2)] >> (32 * (j % 2)));
            v[i] = static_cast<double>(static_cast<std::int32_t>(bits)) * step_;
          }
          n += keep(v, n);
        }
      }
    }
    next_ = 0;
  }

  // Writes v (or its image on the sphere) to slot n; 1 if it is kept (in
  // the annulus), 0 to be overwritten.
  [[gnu::always_inline]] std::size_t keep(Point<D> v, std::size_t n) {
    double s = 0.0;
    for (int i = 0; i < D; ++i) s += v[i] * v[i];
    if (sphere_ > 0.0) {
      const double scale = sphere_ / std::sqrt(std::max(s, inner2_));
      for (int i = 0; i < D; ++i) v[i] *= scale;
    }
    batch_[n] = v;
    return static_cast<std::size_t>((s >= inner2_) & (s <= outer2_));
  }

  template <std::size_t... Axis>
  static std::array<Rng, D> make_streams(std::uint64_t seed, std::index_sequence<Axis...>) {
    return {Rng(seed, {0x616e6e756c7573 /* "annulus" */, Axis})...};
  }

  static constexpr std::size_t kBatch = 64;
  double inner2_, outer2_, step_, sphere_;
  std::array<Rng, D> streams_;
  std::size_t next_ = kBatch;
  std::array<Point<D>, kBatch + 2> batch_;  // spare slots for the last rejected draws
};

}  // namespace pds::detail
