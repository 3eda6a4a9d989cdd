// A. G. M. Ahmed, J. Ren, P. Wonka, Gaussian Blue Noise, ACM Transactions on
// Graphics 41(6), article 260 (SIGGRAPH Asia 2022).
//
// Method: the energy E = sum over pairs of g(x_i - x_j), g(d) =
// exp(-|d|^2 / (2 s^2)) with s = sigma times the mean spacing, is lowered by
// plain gradient descent: every step moves each point by
// step x sum_j (x_i - x_j) g(x_i - x_j), which is -step s^2 times the
// gradient, so a step is a fixed fraction of the spacing whatever the count.
// All points move at once from the previous positions (Jacobi, as the
// paper's GPU code), so the result does not depend on the order or on the
// threads. Neighbours come from a pds::Grid rebuilt every step, within
// kGbnCutoff s (on a torus at most half the shortest period: one image of
// each neighbour). In a box a point also feels the uniform density
// N / volume over the box through the same kernel, whose pull is the
// gradient of its integral over the box, a product of erfs: without it the
// points' repulsion pushes the outermost ones onto the faces.
//
// Why GBN among the optimisers beyond farthest-point optimization
// (capacity-constrained Voronoi tessellation, BNOT): the paper shows its
// spectra at or beyond BNOT's, it runs in any dimension with the same code,
// and it needs no triangulation; a step costs a neighbour sum a point.
//
// Guarantees: gbn.h. Complexity: a step is O(N K), K the neighbours within
// the cutoff (about pi (5 sigma)^2 = 38 in 2D at sigma 0.7, (4/3) pi
// (5 sigma)^3 = 180 in 3D); memory: the points twice and the grid.

#include "pds/samplers/gbn.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pds/detail/format.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"
#include "pds/grid.h"
#include "pds/parallel.h"
#include "pds/portable_math.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

// v^(1/D) with the same bits everywhere: square roots where they suffice
// (IEEE-754 rounds them exactly), else the portable exp and log.
double root(double v, int d) {
  switch (d) {
    case 1:
      return v;
    case 2:
      return std::sqrt(v);
    case 4:
      return std::sqrt(std::sqrt(v));
    case 8:
      return std::sqrt(std::sqrt(std::sqrt(v)));
    default:
      return portable_exp(-neg_log(v) / d);
  }
}

void validate(const GbnParams& params, std::size_t count) {
  if (count < 2) throw InvalidArgument("gbn: needs at least 2 points, got " + std::to_string(count));
  if (params.iterations < 1)
    throw InvalidArgument("gbn: iterations must be at least 1, got " + std::to_string(params.iterations));
  for (const auto& [name, value] : {std::pair{"sigma", params.sigma}, std::pair{"step", params.step}})
    if (!(value > 0.0) || !std::isfinite(value))
      throw InvalidArgument(std::string("gbn: ") + name + " must be positive and finite, got " +
                            detail::format_number(value));
}

}  // namespace

template <int D>
PointSet<D> gbn_optimize(PointSet<D> points, const Domain<D>& domain, const GbnParams& params) {
  domain.validate();
  validate(params, points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!domain.contains(points[i]))
      throw InvalidArgument("gbn: starting point " + std::to_string(i) + " lies outside the domain");
  const std::size_t n = points.size();
  const double volume = domain.volume();
  double shortest = domain.extent(0);
  for (int k = 1; k < D; ++k) shortest = std::min(shortest, domain.extent(k));
  const double spacing = root(volume / static_cast<double>(n), D);
  const double s = params.sigma * spacing;
  const double inv_two_s2 = 1.0 / (2.0 * s * s);
  double reach = kGbnCutoff * s;
  if (domain.periodic) reach = std::min(reach, 0.5 * shortest);
  // The box's pull: s^2 (N / volume) times the gradient of the kernel's
  // integral over the box, whose factor along axis m is
  // s sqrt(pi / 2) (erf((hi - x) / (s sqrt 2)) + erf((x - lo) / (s sqrt 2))).
  const double pull = s * s * static_cast<double>(n) / volume;
  const double mass_scale = s * 1.2533141373155002512;  // s sqrt(pi / 2)
  const double inv_s_sqrt2 = 1.0 / (s * 1.4142135623730950488);
  // Cells of edge reach / 2 in the plane and space (a 5^D block holds a
  // ball of the reach with less waste than 3^D cells of edge reach), reach
  // from 4 dimensions, where 5^D cells outgrow the points they hold; never
  // below the mean spacing, so that a torus with a short period (and so a
  // short reach) does not get far more cells than points.
  const double edge = std::max(D <= 3 ? 0.5 * reach : reach, spacing);
  ProgressReporter progress(params.progress, params.iterations);
  PointSet<D> next(n);
  for (int iteration = 0; iteration < params.iterations; ++iteration) {
    Grid<D> grid(domain, edge);
    for (const Point<D>& p : points) grid.insert(p);
    parallel_for(0, n, 2048, params.threads, [&](std::size_t first, std::size_t last) {
      for (std::size_t i = first; i < last; ++i) {
        const Point<D>& x = points[i];
        Point<D> move{};
        grid.for_each_within(x, reach, [&](std::int32_t j, double d2) {
          if (static_cast<std::size_t>(j) == i) return true;
          const double w = exp_neg_table(d2 * inv_two_s2);
          const Point<D>& y = points[static_cast<std::size_t>(j)];
          for (int k = 0; k < D; ++k) move[k] += domain.delta(y[k], x[k], k) * w;
          return true;
        });
        if (!domain.periodic) {
          std::array<double, D> mass, slope;
          for (int k = 0; k < D; ++k) {
            const double below = x[k] - domain.lo[k], above = domain.hi[k] - x[k];
            mass[k] = mass_scale * (portable_erf(above * inv_s_sqrt2) + portable_erf(below * inv_s_sqrt2));
            slope[k] = exp_neg(below * below * inv_two_s2) - exp_neg(above * above * inv_two_s2);
          }
          for (int k = 0; k < D; ++k) {
            double f = pull * slope[k];
            for (int m = 0; m < D; ++m)
              if (m != k) f *= mass[m];
            move[k] += f;
          }
        }
        Point<D> y;
        for (int k = 0; k < D; ++k) y[k] = x[k] + params.step * move[k];
        if (domain.periodic) {
          y = domain.wrap(y);
        } else {
          for (int k = 0; k < D; ++k) y[k] = std::clamp(y[k], domain.lo[k], std::nextafter(domain.hi[k], domain.lo[k]));
        }
        next[i] = y;
      }
    });
    points.swap(next);
    progress.update(iteration + 1);
  }
  progress.finish();
  return points;
}

template <int D>
PointSet<D> gbn(const GbnParams& params, const Domain<D>& domain, std::uint64_t seed) {
  domain.validate();
  validate(params, static_cast<std::size_t>(std::min<std::uint64_t>(params.count, 1u << 31)));
  Rng rng(seed);
  PointSet<D> points(static_cast<std::size_t>(params.count));
  for (Point<D>& p : points) p = uniform_point(rng, domain);
  return gbn_optimize(std::move(points), domain, params);
}

#define PDS_INSTANTIATE(D)                                                        \
  template PointSet<D> gbn<D>(const GbnParams&, const Domain<D>&, std::uint64_t); \
  template PointSet<D> gbn_optimize<D>(PointSet<D>, const Domain<D>&, const GbnParams&);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
