// Boundary sampling with the AVX-512 neighbourhood kernel (x86-64-v4: AVX-512
// F, BW, CD, DQ, VL), chosen at run time by kernel_select.cpp when the
// processor has that level; the same bytes as the scalar kernel (tested).
//
// Only the functions here carry the target (the attribute
// "arch=x86-64-v4"); the translation unit is not built with -march. The
// shared inline code of the headers (the grid, the free arcs, the random
// numbers) is then emitted for the baseline wherever it is not inlined, as in
// every other file: a whole-file -march would emit AVX-512 copies of those
// inline functions, and the linker keeps one copy of each for the whole
// library, which could be this one on a processor without AVX-512. Built
// with -fno-math-errno and -ffp-contract=off, as boundary_scalar.cpp.
#include "boundary.h"

#if PDS_HAVE_AVX512_KERNEL
#include <immintrin.h>

#include "boundary_loop.h"

namespace pds::detail::dh {
namespace {

#define PDS_AVX512 __attribute__((target("arch=x86-64-v4")))

struct Avx512Neighbours {
  // Up to 16 neighbours or arcs (the usual case) sit in two vectors. block and
  // the exact check run one masked step for up to 8 (82% of front samples,
  // so the branch is mostly predicted) and two up to 16; the complement
  // always handles both vectors.
  static constexpr int kUsual = 16;

  /// The lanes [0, n) of an 8-lane step, for any n (clamped to 0..8).
  PDS_AVX512 static __mmask8 first_lanes(int n) { return static_cast<__mmask8>((1u << std::clamp(n, 0, 8)) - 1); }
  /// The largest lane (exact; written out rather than _mm512_reduce_max_pd,
  /// which trips a GCC 12 warning in its own header).
  PDS_AVX512 static double max_lane(__m512d v) {
    alignas(64) double lanes[8];
    _mm512_store_pd(lanes, v);
    return std::max(std::max(std::max(lanes[0], lanes[1]), std::max(lanes[2], lanes[3])),
                    std::max(std::max(lanes[4], lanes[5]), std::max(lanes[6], lanes[7])));
  }
  /// Steps of 8 covering n: 1 up to 8, 2 up to 16, then as many as needed.
  static int steps(int n) { return n <= 8 ? 1 : (n <= kUsual ? kUsual / 8 : (n + 7) / 8); }

  /// 2 - copysign(1 + u, y): a diamond angle from its quotient u, as in
  /// diamond_arc_one_division, the copysign as bit operations on the sign bit.
  PDS_AVX512 static __m512d diamond_angle(__m512d u, __m512d y) {
    const __m512i sign = _mm512_set1_epi64(static_cast<long long>(0x8000000000000000ull));
    const __m512d v = _mm512_abs_pd(_mm512_add_pd(_mm512_set1_pd(1.0), u));
    const __m512i signed_v = _mm512_or_si512(_mm512_castpd_si512(v), _mm512_and_si512(sign, _mm512_castpd_si512(y)));
    return _mm512_sub_pd(_mm512_set1_pd(2.0), _mm512_castsi512_pd(signed_v));
  }

  /// As ScalarNeighbours::block, eight neighbours per step.
  PDS_AVX512 static void block(double inv_reach, const Point<2>& p, bool seam, Neighbourhood& nb) {
    const __m512d scale = _mm512_set1_pd(inv_reach), four = _mm512_set1_pd(4.0), one = _mm512_set1_pd(1.0);
    const __m512d zero = _mm512_setzero_pd(), three = _mm512_set1_pd(3.0);
    const __m512d px = _mm512_set1_pd(p[0]), py = _mm512_set1_pd(p[1]);
    for (int step = 0, n = steps(nb.count); step < n; ++step) {
      const int i = 8 * step;
      const __mmask8 live = first_lanes(nb.count - i);
      __m512d dx, dy;
      if (seam) {
        dx = _mm512_maskz_loadu_pd(live, nb.dx + i), dy = _mm512_maskz_loadu_pd(live, nb.dy + i);
      } else {  // the gather's subtraction again
        dx = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, nb.sx + i), px);
        dy = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, nb.sy + i), py);
      }
      // Dead lanes compute on (1, 0): no division by 0.
      const __m512d ex = _mm512_mask_mul_pd(one, live, dx, scale), ey = _mm512_maskz_mul_pd(live, dy, scale);
      const __m512d e2 = _mm512_add_pd(_mm512_mul_pd(ex, ex), _mm512_mul_pd(ey, ey));
      const __m512d rest = _mm512_sub_pd(one, e2);
      const __m512d room = _mm512_mul_pd(_mm512_mask_max_pd(rest, 0xFF, rest, zero), e2);  // (masked: see t)
      const __m512d t = _mm512_mask_sqrt_pd(room, 0xFF, room);  // (the unmasked form warns in GCC 12)
      const __m512d ax = _mm512_mul_pd(ex, e2), ay = _mm512_mul_pd(ey, e2);
      const __m512d bx = _mm512_mul_pd(ey, t), by = _mm512_mul_pd(ex, t);
      const __m512d x1 = _mm512_add_pd(ax, bx), y1 = _mm512_sub_pd(ay, by);
      const __m512d x2 = _mm512_sub_pd(ax, bx), y2 = _mm512_add_pd(ay, by);
      const __m512d s1 = _mm512_add_pd(_mm512_abs_pd(x1), _mm512_abs_pd(y1));
      const __m512d s2 = _mm512_add_pd(_mm512_abs_pd(x2), _mm512_abs_pd(y2));
      const __m512d inv = _mm512_div_pd(one, _mm512_mul_pd(s1, s2));
      const __m512d q1 = _mm512_mul_pd(_mm512_mul_pd(x1, s2), inv), q2 = _mm512_mul_pd(_mm512_mul_pd(x2, s1), inv);
      const __m512d u1 = _mm512_mask_min_pd(q1, 0xFF, q1, one), u2 = _mm512_mask_min_pd(q2, 0xFF, q2, one);
      __m512d lo = diamond_angle(u1, y1);
      __m512d len = _mm512_sub_pd(diamond_angle(u2, y2), lo);
      // lo -= 4 (lo >= 4), len += 4 (len < 0): the same exact subtraction and addition of 0 or 4.
      lo = _mm512_sub_pd(lo, _mm512_maskz_mov_pd(_mm512_cmp_pd_mask(lo, four, _CMP_GE_OQ), four));
      len = _mm512_add_pd(len, _mm512_maskz_mov_pd(_mm512_cmp_pd_mask(len, zero, _CMP_LT_OQ), four));
      len = _mm512_maskz_mov_pd(_mm512_cmp_pd_mask(len, three, _CMP_LE_OQ), len);  // len * (len <= 3)
      _mm512_storeu_pd(nb.lo + nb.blocked + i, lo);
      _mm512_storeu_pd(nb.len + nb.blocked + i, len);
    }
    nb.blocked += nb.count;
  }

  /// As ScalarNeighbours::clear_of_neighbours, eight neighbours per step
  /// (the same subtractions, products and comparison per neighbour; no
  /// early exit, whose trip count would be a mispredicted branch).
  PDS_AVX512 static bool clear_of_neighbours(const Neighbourhood& nb, const Point<2>& q, double r2, bool seam,
                                             const Domain<2>& domain) {
    if (seam) return ScalarNeighbours::clear_of_neighbours(nb, q, r2, seam, domain);
    const __m512d qx = _mm512_set1_pd(q[0]), qy = _mm512_set1_pd(q[1]), limit = _mm512_set1_pd(r2);
    __mmask8 close = 0;
    for (int step = 0, n = steps(nb.count); step < n; ++step) {
      const int i = 8 * step;
      const __mmask8 live = first_lanes(nb.count - i);
      const __m512d dx = _mm512_sub_pd(qx, _mm512_maskz_loadu_pd(live, nb.sx + i));
      const __m512d dy = _mm512_sub_pd(qy, _mm512_maskz_loadu_pd(live, nb.sy + i));
      const __m512d d2 = _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy));
      close |= _mm512_mask_cmp_pd_mask(live, d2, limit, _CMP_NGE_UQ);  // not (d2 >= r2), as the scalar test
    }
    return close == 0;
  }

  /// As ScalarNeighbours::complement (FreeArcs::assign_complement_unsorted),
  /// on up to 16 arcs held in two vectors: for each arc i, every arc k that
  /// starts after it takes max(covered_k, end_i); the gaps that stay open are
  /// compressed out in list order, then the one that ends at 4.
  PDS_AVX512 static void complement(const Neighbourhood& nb, detail::FreeArcs& arcs) {
    const int n = nb.blocked;
    if (n > kUsual) return ScalarNeighbours::complement(nb, arcs);
    const __mmask8 live[2] = {first_lanes(n), first_lanes(n - 8)};
    __m512d lo[2], end[2], covered[2];
    __m512d first = _mm512_setzero_pd(), last = _mm512_setzero_pd();
    for (int h = 0; h < 2; ++h) {
      lo[h] = _mm512_maskz_loadu_pd(live[h], nb.lo + 8 * h);
      end[h] = _mm512_add_pd(lo[h], _mm512_maskz_loadu_pd(live[h], nb.len + 8 * h));
      first = _mm512_mask_max_pd(first, live[h], first, _mm512_sub_pd(end[h], _mm512_set1_pd(4.0)));
      last = _mm512_mask_max_pd(last, live[h], last, end[h]);
    }
    // covered_k = max(from, the ends of the arcs listed before k): maxima are
    // exact in any order, so two chains over alternate arcs (shorter latency)
    // and `from` last give the scalar kernel's numbers.
    __m512d even[2] = {_mm512_setzero_pd(), _mm512_setzero_pd()}, odd[2] = {even[0], even[1]};
    const auto take = [&](int i, __m512d* acc) PDS_AVX512 {
      const __m512d lo_i = _mm512_set1_pd(nb.lo[i]), end_i = _mm512_set1_pd(nb.lo[i] + nb.len[i]);
      const unsigned listed_after = ~((2u << i) - 1);  // the arcs k > i, one bit each
      for (int h = 0; h < 2; ++h) {
        const auto later = static_cast<__mmask8>(listed_after >> (8 * h));
        const __mmask8 after = _mm512_mask_cmp_pd_mask(live[h], lo[h], lo_i, _CMP_GT_OQ) |
                               _mm512_mask_cmp_pd_mask(live[h] & later, lo[h], lo_i, _CMP_EQ_OQ);
        acc[h] = _mm512_mask_max_pd(acc[h], after, acc[h], end_i);
      }
    };
    int i = 0;
    for (; i + 1 < n; i += 2) take(i, even), take(i + 1, odd);
    if (i < n) take(i, even);
    const double from = max_lane(first);  // over the arcs and 0
    for (int h = 0; h < 2; ++h) {
      const __m512d both = _mm512_mask_max_pd(even[h], 0xFF, even[h], odd[h]);  // (masked: see block)
      covered[h] = _mm512_mask_max_pd(both, 0xFF, both, _mm512_set1_pd(from));
    }
    const double to = std::max(from, max_lane(last));
    detail::DiamondArc* out = arcs.begin_fill(3 * kUsual);
    auto* slots = reinterpret_cast<double*>(out);
    std::size_t kept = 0;
    const __m512i pairs_low = _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0);
    const __m512i pairs_high = _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4);
    const __m512d min_arc = _mm512_set1_pd(detail::FreeArcs::min_arc());
    for (int h = 0; h < 2; ++h) {
      const __m512d gap = _mm512_sub_pd(lo[h], covered[h]);
      const __mmask8 open = _mm512_mask_cmp_pd_mask(live[h], gap, min_arc, _CMP_GT_OQ);
      const __m512d starts = _mm512_maskz_compress_pd(open, covered[h]), lengths = _mm512_maskz_compress_pd(open, gap);
      _mm512_storeu_pd(slots + 2 * kept, _mm512_permutex2var_pd(starts, pairs_low, lengths));
      _mm512_storeu_pd(slots + 2 * kept + 8, _mm512_permutex2var_pd(starts, pairs_high, lengths));
      kept += static_cast<std::size_t>(__builtin_popcount(open));
    }
    out[kept] = {to, 4.0 - to};
    kept += 4.0 - to > detail::FreeArcs::min_arc();
    arcs.finish_fill(kept);
  }
};

}  // namespace

PDS_AVX512 PointSet<2> boundary_sampling_avx512(const DunbarHumphreysParams& params, const Domain<2>& domain,
                                                std::uint64_t seed) {
  return boundary_sampling_with<Avx512Neighbours>(params, domain, seed);
}

PDS_AVX512 std::vector<std::array<double, 2>> free_arcs_avx512(const Point<2>& p, const PointSet<2>& neighbours,
                                                               double radius) {
  return free_arcs_with<Avx512Neighbours>(p, neighbours, radius);
}

}  // namespace pds::detail::dh
#endif
