// Multi-jittered and correlated multi-jittered sampling.
//
// K. Chiu, P. Shirley and C. Wang, Multi-jittered sampling, Graphics Gems IV,
// 1994. A. Kensler, Correlated multi-jittered sampling, Pixar Technical Memo
// 13-01, 2013.
//
// Method, in D dimensions: the domain is cut into c_0 x ... x c_{D-1} = N
// strata. Along axis k each stratum column j_k is cut further into M_k = N/c_k
// slabs of width 1/N. The canonical arrangement gives the point of stratum j
// the slab j_k M_k + r_k(j), where r_k(j) numbers the other coordinates of j
// (mixed radix), so the slabs of a column go one to each of its M_k strata:
// in 2D this is Chiu, Shirley and Wang's starting pattern. Then r_k is
// shuffled: by an independent permutation per column (Chiu et al.) or by one
// permutation per axis for all columns (Kensler's correlated variant).
// Either shuffle is a bijection within each column, so the jitter and the
// N-rooks properties both survive; each point is uniform within its slab.
// Guarantees: see multi_jittered.h. Complexity: O(N D) time, O(N) memory for
// the permutations. Limits: N must factor into near-cubic strata (the
// registry uses strata_for_count and names the nearest counts that do).

#include "pds/samplers/multi_jittered.h"

#include <string>
#include <vector>

#include "mapped_pages.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"
#include "pds/rng.h"
#include "pds/samplers/latin_hypercube.h"
#include "pds/samplers/low_discrepancy.h"
#include "pds/samplers/strata.h"

namespace pds {

template <int D>
PointSet<D> multi_jittered(const MultiJitteredParams& params, const Domain<D>& domain, std::uint64_t seed) {
  std::uint64_t n = 1;
  for (int k = 0; k < D; ++k) {
    if (params.cells[k] < 1)
      throw InvalidArgument("multi-jittered: strata along axis " + std::to_string(k) + " must be at least 1, got " +
                            std::to_string(params.cells[k]));
    n *= static_cast<std::uint64_t>(params.cells[k]);
    if (n > (std::uint64_t{1} << 32)) throw InvalidArgument("multi-jittered: more than 2^32 strata requested");
  }
  // Per axis: the shuffles (shuffle[k][c * m + r]: the permutation of column c,
  // only column 0 when correlated) and a jitter stream of its own.
  std::array<std::vector<std::uint32_t>, D> shuffle;
  std::array<std::uint64_t, D> m;  // slabs per column
  std::vector<Rng> jitter;
  for (int k = 0; k < D; ++k) {
    const auto columns = static_cast<std::uint32_t>(params.cells[k]);
    m[k] = n / columns;
    shuffle[k].reserve(params.correlated ? m[k] : n);
    for (std::uint32_t c = 0; c < (params.correlated ? 1 : columns); ++c) {
      Rng rng(seed, {0, static_cast<std::uint64_t>(k), c});
      const auto p = random_permutation(static_cast<std::uint32_t>(m[k]), rng);
      shuffle[k].insert(shuffle[k].end(), p.begin(), p.end());
    }
    jitter.emplace_back(seed, std::initializer_list<std::uint64_t>{1, static_cast<std::uint64_t>(k)});
  }
  const SlabJitter within(n);
  const UnitCubeMap<D> to_domain(domain);
  PointSet<D> points = detail::output_points<D>(n);
  std::array<std::uint32_t, D> cell{};
  ProgressReporter progress(params.progress, static_cast<double>(n));
  for (std::size_t i = 0; i < points.size(); ++i) {
    if ((i & 65535) == 0) progress.update(static_cast<double>(i));
    Point<D>& p = points[i];
    Point<D> u;
    for (int k = 0; k < D; ++k) {
      std::uint64_t r = 0;  // the other coordinates of the cell, mixed radix, highest axis first
      for (int l = D - 1; l >= 0; --l)
        if (l != k) r = r * static_cast<std::uint64_t>(params.cells[l]) + cell[l];
      const std::uint64_t column = cell[k];
      const std::uint64_t slab = column * m[k] + shuffle[k][(params.correlated ? 0 : column) * m[k] + r];
      u[k] = within(slab, jitter[k]);
    }
    p = to_domain(u);
    for (int l = 0; l < D && ++cell[l] == static_cast<std::uint32_t>(params.cells[l]); ++l) cell[l] = 0;
  }
  progress.finish();
  return points;
}

#define PDS_INSTANTIATE(D) \
  template PointSet<D> multi_jittered<D>(const MultiJitteredParams&, const Domain<D>&, std::uint64_t);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
