// Hammersley point set.
//
// J. M. Hammersley, Monte Carlo methods for solving multivariable problems,
// Annals of the New York Academy of Sciences 86, 1960.
//
// Method: point i of N is (i / N, phi_2(i), phi_3(i)); the radical inverses
// and their scrambling are those of the Halton sequence (low_discrepancy.h).
// Guarantees: star discrepancy O(log^(D-1) N / N), one log better than Halton
// because N is known in advance; in 2D with N = 2^m, a (0, m, 2)-net in base 2,
// and Owen or digit scrambling of axis 1 keeps it one (they permute digits of
// points sharing a prefix alike).
// Complexity: O(count * D), one code path for every dimension
// (fill_radical_inverses). Limits: N fixed in advance (a prefix of the set is
// not well distributed along axis 0); N <= 2^32; 10,001 axes.

#include "pds/samplers/hammersley.h"

#include "mapped_pages.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"

namespace pds {

void hammersley_fill(const HammersleyParams& params, const CloudBox& box, std::uint64_t seed, double* out) {
  const int dim = box.dim();
  if (dim < 1 || dim > kHammersleyMaxDim)
    throw InvalidArgument("hammersley: dimension " + std::to_string(dim) + " is not supported (supported: 1 to " +
                          std::to_string(kHammersleyMaxDim) + ")");
  require_index_range("hammersley", params.first, params.count);
  const std::uint64_t size = params.size ? params.size : params.first + params.count;
  if (params.first + params.count > size)
    throw InvalidArgument("hammersley: points first " + std::to_string(params.first) + " + count " +
                          std::to_string(params.count) + " exceed the set's size " + std::to_string(size));
  const BoxMap map(box);
  // Axes 1 and up: Halton's radical inverses, correctly rounded (SciPy has no Hammersley set to follow).
  ProgressReporter progress(params.progress, static_cast<double>(params.count));
  fill_radical_inverses(static_cast<std::uint32_t>(params.first), params.count, dim, 1, params.scramble,
                        RadicalRounding::correct, seed, 2, map, out, &progress);
  const double n = static_cast<double>(size);
  const auto stride = static_cast<std::size_t>(dim);
  for (std::uint64_t i = 0; i < params.count; ++i)
    out[i * stride] = map(0, static_cast<double>(params.first + i) / n);
  progress.finish();
}

PointCloud hammersley(const HammersleyParams& params, const CloudBox& box, std::uint64_t seed) {
  return fill_cloud("hammersley", params.count, box, [&](double* out) { hammersley_fill(params, box, seed, out); });
}

template <int D>
PointSet<D> hammersley(const HammersleyParams& params, const Domain<D>& domain, std::uint64_t seed) {
  require_index_range("hammersley", params.first, params.count);
  PointSet<D> points = detail::output_points<D>(params.count);
  hammersley_fill(params, CloudBox::of(domain), seed, points.data()->data());
  return points;
}

#define PDS_INSTANTIATE(D) \
  template PointSet<D> hammersley<D>(const HammersleyParams&, const Domain<D>&, std::uint64_t);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
