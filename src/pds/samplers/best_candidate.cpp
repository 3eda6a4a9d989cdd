// D. P. Mitchell, Generating antialiased images at low sampling densities,
// SIGGRAPH 1987, and Spectrally optimal sampling for distribution ray
// tracing, SIGGRAPH 1991 (the m*i candidates rule).
//
// Method: the first sample is uniform; sample i+1 is the candidate, among m*i
// uniform random ones, farthest from the i samples so far (on a torus the
// nearest periodic image counts). Every prefix of the output is well spread.
//
// Taken literally that is m*i nearest-sample queries a sample, O(m N^2): 5e10
// queries for N = 10^5, m = 10. Two structures, both adapting to the
// density, cut that down while keeping the distribution of the winner:
//  * A background grid of the samples for exact nearest-sample distances,
//    rebuilt with about one sample a cell whenever the count doubles.
//  * Leaf cells (about 2^D per final sample) each with an upper bound U on
//    the distance from any of its points to the nearest sample, in a max
//    tree. A new sample lowers U to its farthest-corner distance in the
//    leaves near it. A leaf visited while loose is tightened: branch and
//    bound over sub-boxes against the samples near it gives U within 5% of a
//    leaf edge of the true maximum (or proves it below the round's best).
// Once m*i >= 256, the candidates are drawn as a Poisson process of mean m*i
// (independent Poisson counts per leaf, uniform positions): the candidates of
// a leaf with U <= the best distance found so far cannot win and need not be
// drawn at all. Leaves are visited largest U first through the max tree (leaf
// ids go tile by tile, so a subtree is a compact block of space), and a
// leaf's candidates come from a hash of (seed, round, leaf), so the result
// does not depend on the visiting order or on how tight the bounds were. The
// winner is exactly the farthest point of the Poisson process; the only
// departure from Mitchell is that the candidate count is Poisson(m*i) rather
// than exactly m*i (a relative spread of 1/sqrt(m*i) <= 6%).
//
// Guarantees: samples in [lo, hi); same seed, same points; the reported
// distances are exact. No minimum distance is promised unless a radius is
// given. Measured relative radius ~0.75 (m = 10), docs/best-candidate.md.
//
// Complexity and limits: the leaves that must be looked at in a round are
// those whose gap exceeds the round's best distance, and their number grows
// with N (measured about N^1.6 in total, docs/best-candidate.md): 2D sets of
// 10^4 take seconds, 10^5 minutes; 3D is several times slower. Memory about
// 2^D leaves (24 bytes each) a sample.

#include "pds/samplers/best_candidate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "pds/error.h"
#include "pds/grid.h"
#include "pds/limits.h"
#include "pds/rng.h"
#include "pds/samplers/random.h"
#include "pds/samplers/sizing.h"

namespace pds {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string format(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

// e^-x for x >= 0 with only + * / (no libm), so that the Poisson draws are
// the same on every platform: a Taylor series on x / 2^s, squared s times.
double exp_neg(double x) {
  int s = 0;
  while (x > 0.0625) {
    x *= 0.5;
    ++s;
  }
  double term = 1.0, sum = 1.0;
  for (int k = 1; k <= 12; ++k) {
    term *= -x / k;
    sum += term;
  }
  while (s--) sum *= sum;
  return sum;
}

// Poisson(lambda) by inversion, given the uniform u >= p0 = e^-lambda that
// already ruled out 0. Bounded by the support that matters (the tail beyond
// lambda + 40 sqrt(lambda) + 100 has probability below 1e-300).
std::uint64_t poisson_above_zero(double u, double lambda, double p0) {
  double p = p0, cdf = p0;
  std::uint64_t k = 0;
  const double limit = lambda + 40.0 * std::sqrt(lambda) + 100.0;
  while (u >= cdf && k < limit) {
    ++k;
    p *= lambda / static_cast<double>(k);
    cdf += p;
  }
  return k;
}

// Leaf cells with an upper bound U on the distance from any of their points
// to the nearest sample, and a max tree over the bounds.
template <int D>
class LeafBounds {
 public:
  LeafBounds(const Domain<D>& domain, double target_leaves) : domain_(domain) {
    const double edge = std::pow(domain.volume() / target_leaves, 1.0 / D);
    leaves_ = 1;
    std::size_t tiles = 1;
    for (int i = 0; i < D; ++i) {
      cells_[i] = static_cast<int>(std::clamp(std::round(domain.extent(i) / edge), 1.0, 1e9));
      edge_[i] = domain.extent(i) / cells_[i];
      leaves_ *= static_cast<std::size_t>(cells_[i]);
      tiles_[i] = (cells_[i] + kTile - 1) / kTile;
      tile_stride_[i] = tiles;
      tiles *= static_cast<std::size_t>(tiles_[i]);
      if (leaves_ > kMaxGridCells || tiles * kTileSlots > 2 * kMaxGridCells)
        throw InvalidArgument("best-candidate: the request needs more than " + std::to_string(kMaxGridCells) +
                              " leaf cells");
    }
    const std::size_t slots = tiles * kTileSlots;
    size_ = 1;
    while (size_ < slots) size_ *= 2;
    tree_.assign(2 * size_, -kInf);
    tight_.assign(slots, 1);
    Point<D> none;
    none.fill(std::numeric_limits<double>::quiet_NaN());
    witness_.assign(slots, none);
    for (std::size_t j = 0; j < slots; ++j) {
      const auto c = coords(j);
      bool real = true;
      for (int i = 0; i < D; ++i) real &= c[i] < cells_[i];
      if (real) {
        tree_[size_ + j] = kInf;
        tight_[j] = 0;
      }
    }
    for (std::size_t n = size_ - 1; n >= 1; --n) tree_[n] = std::max(tree_[2 * n], tree_[2 * n + 1]);
  }

  /// The number of leaves (leaf ids run over more slots: see id()).
  std::size_t leaves() const { return leaves_; }
  /// No point of the domain is farther than this from every sample.
  double max_bound() const { return tree_[1]; }
  double bound(std::size_t leaf) const { return tree_[size_ + leaf]; }

  Point<D> leaf_lo(std::size_t leaf) const {
    const auto c = coords(leaf);
    Point<D> p;
    for (int i = 0; i < D; ++i) p[i] = domain_.lo[i] + static_cast<double>(c[i]) * edge_[i];
    return p;
  }
  const std::array<double, D>& edge() const { return edge_; }

  /// Lowers the bounds of the leaves whose centre is nearer to the new sample.
  void add_sample(const Point<D>& p) {
    const double reach = max_bound();
    std::array<int, D> first, count;
    for (int i = 0; i < D; ++i) {
      const double x = (p[i] - domain_.lo[i]) / edge_[i] - 0.5;  // in units of leaves, from the first centre
      double a = std::ceil(x - reach / edge_[i]), b = std::floor(x + reach / edge_[i]);
      if (!std::isfinite(reach) || (domain_.periodic && b - a + 1 >= cells_[i])) {
        a = 0;
        b = cells_[i] - 1;
      } else if (!domain_.periodic) {
        a = std::max(a, 0.0);
        b = std::min(b, cells_[i] - 1.0);
      }
      if (a > b) return;
      first[i] = static_cast<int>(a);
      count[i] = static_cast<int>(b - a) + 1;
    }
    std::array<int, D> offset{};
    while (true) {
      std::size_t leaf = 0;
      double far2 = 0.0;  // squared distance from p to the leaf's farthest point
      std::array<int, D> cell;
      for (int i = 0; i < D; ++i) {
        int c = first[i] + offset[i];
        cell[i] = c = ((c % cells_[i]) + cells_[i]) % cells_[i];
        const double far = farthest(p[i], c, i);
        far2 += far * far;
      }
      leaf = id(cell);
      const double bound = std::sqrt(far2) * (1.0 + 1e-12);
      if (bound < tree_[size_ + leaf]) {
        witness_[leaf] = p;
        lower(leaf, bound);
      }
      int axis = 0;
      while (axis < D && ++offset[axis] == count[axis]) offset[axis++] = 0;
      if (axis == D) return;
    }
  }

  bool is_tight(std::size_t leaf) const { return tight_[leaf]; }
  /// A sample near the leaf (NaN before any): no point c of the domain is
  /// farther than distance(c, witness) from every sample, a cheap filter.
  const Point<D>& witness(std::size_t leaf) const { return witness_[leaf]; }

  /// Replaces the leaf's bound by a nearly exact one: the largest distance
  /// from a point of the leaf to the nearest of `near` (which must hold every
  /// sample within bound + half diagonal of the leaf's centre), found by
  /// branch and bound over sub-boxes down to 1/32 of the leaf's edge. The
  /// bound stays valid as samples are added; add_sample() marks it loose.
  /// Boxes whose bound is at most `floor` (the round's best distance, which
  /// no distance will exceed later either) are not refined; a leaf whose
  /// bound ends at the floor stays loose, to be refined again when the best
  /// falls below it.
  void tighten(std::size_t leaf, const PointSet<D>& near, double floor) {
    if (near.empty()) return;
    struct Box {
      Point<D> lo;
      int level;
    };
    double witness = 0.0, upper = 0.0;  // max f seen at a centre; max bound of undecided boxes
    bool floored = false;
    const double tolerance = 0.05 * *std::min_element(edge_.begin(), edge_.end());
    const Point<D> leaf_lo = this->leaf_lo(leaf);
    boxes_.clear();
    boxes_.push_back(leaf_lo);
    levels_.clear();
    levels_.push_back(0);
    while (!boxes_.empty()) {
      const Point<D> lo = boxes_.back();
      const int level = levels_.back();
      boxes_.pop_back();
      levels_.pop_back();
      const double scale = 1.0 / static_cast<double>(1 << level);
      Point<D> centre;
      for (int i = 0; i < D; ++i) centre[i] = lo[i] + 0.5 * edge_[i] * scale;
      double bound2 = kInf, centre2 = kInf;
      for (const auto& q : near) {
        double far2 = 0.0;
        for (int i = 0; i < D; ++i) {
          const double far = farthest(q[i], lo[i], std::min(lo[i] + edge_[i] * scale, domain_.hi[i]), i);
          far2 += far * far;
        }
        bound2 = std::min(bound2, far2);
        const double d2 = domain_.distance2(centre, q);
        if (level == 0 && d2 < centre2) witness_[leaf] = q;
        centre2 = std::min(centre2, d2);
      }
      witness = std::max(witness, std::sqrt(centre2));
      const double bound = std::sqrt(bound2) * (1.0 + 1e-12);
      if (bound <= witness) continue;
      if (bound <= floor) {
        floored = true;
        continue;
      }
      if (level == kMaxTightenLevel || bound - witness < tolerance) {
        upper = std::max(upper, bound);
        continue;
      }
      for (int child = 0; child < (1 << D); ++child) {
        Point<D> c = lo;
        for (int i = 0; i < D; ++i)
          if (child >> i & 1) c[i] += 0.5 * edge_[i] * scale;
        boxes_.push_back(c);
        levels_.push_back(level + 1);
      }
    }
    double tight = std::max(witness * (1.0 + 1e-12), upper);
    if (floored && floor > tight) tight = floor;
    tight_[leaf] = !(floored && tight == floor);
    if (tight < tree_[size_ + leaf]) set(leaf, tight);
  }

  /// Calls visit(leaf) for leaves in decreasing order of bound (depth first,
  /// larger child first) while their bound exceeds `best`, which visit may
  /// raise.
  template <class F>
  void visit_above(const double& best, F&& visit) {
    stack_.clear();
    stack_.push_back(1);
    while (!stack_.empty()) {
      const std::size_t node = stack_.back();
      stack_.pop_back();
      if (!(tree_[node] > best)) continue;
      if (node >= size_) {
        visit(node - size_);
        continue;
      }
      const std::size_t a = 2 * node, b = a + 1;
      if (tree_[a] >= tree_[b]) {
        stack_.push_back(b);
        stack_.push_back(a);
      } else {
        stack_.push_back(a);
        stack_.push_back(b);
      }
    }
  }

 private:
  void lower(std::size_t leaf, double value) {
    tight_[leaf] = 0;
    set(leaf, value);
  }

  void set(std::size_t leaf, double value) {
    std::size_t node = size_ + leaf;
    tree_[node] = value;
    for (node /= 2; node >= 1; node /= 2) {
      const double v = std::max(tree_[2 * node], tree_[2 * node + 1]);
      if (v == tree_[node]) break;
      tree_[node] = v;
    }
  }

  // Leaf ids go tile by tile (kTile^D leaves a tile, row-major inside), so
  // that a subtree of the max tree is a compact block of space and the leaves
  // near one gap share their ancestors. Slots of partial tiles beyond the
  // domain hold -inf and are never visited.
  std::size_t id(const std::array<int, D>& c) const {
    std::size_t tile = 0, inner = 0, scale = 1;
    for (int i = 0; i < D; ++i) {
      tile += static_cast<std::size_t>(c[i] / kTile) * tile_stride_[i];
      inner += static_cast<std::size_t>(c[i] % kTile) * scale;
      scale *= kTile;
    }
    return tile * kTileSlots + inner;
  }

  std::array<int, D> coords(std::size_t id) const {
    const std::size_t tile = id / kTileSlots;
    std::size_t inner = id % kTileSlots;
    std::array<int, D> c;
    for (int i = 0; i < D; ++i) {
      c[i] = static_cast<int>(tile / tile_stride_[i] % static_cast<std::size_t>(tiles_[i])) * kTile +
             static_cast<int>(inner % kTile);
      inner /= kTile;
    }
    return c;
  }

  // The largest distance along one axis from x to a point of leaf column c
  // (on a torus, to the nearest image: at most half the period).
  double farthest(double x, int c, int axis) const {
    const double a = domain_.lo[axis] + c * edge_[axis];
    const double b = c + 1 == cells_[axis] ? domain_.hi[axis] : a + edge_[axis];
    return farthest(x, a, b, axis);
  }

  // The same for the interval [a, b] inside the domain.
  double farthest(double x, double a, double b, int axis) const {
    if (!domain_.periodic) return std::max(std::abs(x - a), std::abs(b - x));
    const double L = domain_.extent(axis);
    double antipode = x + 0.5 * L;
    if (antipode >= domain_.hi[axis]) antipode -= L;
    if (antipode >= a && antipode <= b) return 0.5 * L;
    return std::max(std::abs(domain_.delta(x, a, axis)), std::abs(domain_.delta(x, b, axis)));
  }

  Domain<D> domain_;
  std::array<int, D> cells_{};
  std::array<double, D> edge_{};
  std::array<int, D> tiles_{};
  std::array<std::size_t, D> tile_stride_{};
  std::size_t leaves_ = 0, size_ = 0;
  static constexpr int kTile = D == 2 ? 8 : 4;
  static constexpr std::size_t kTileSlots = D == 2 ? 64 : 64;
  std::vector<double> tree_;
  std::vector<std::size_t> stack_;
  std::vector<char> tight_;
  PointSet<D> witness_;
  PointSet<D> boxes_;
  std::vector<int> levels_;
  static constexpr int kMaxTightenLevel = D == 2 ? 4 : 3;
};

// Exact distances to the nearest sample, on a grid of about one sample a cell
// that is rebuilt whenever the sample count doubles.
template <int D>
class NearestSample {
 public:
  explicit NearestSample(const Domain<D>& domain) : domain_(domain), grid_(domain, max_extent(domain)) {
    for (int i = 0; i < D; ++i) diameter_ += domain.extent(i) * domain.extent(i);
    diameter_ = std::sqrt(diameter_) * 1.01;
  }

  void add(const Point<D>& p, const PointSet<D>& all) {
    if (all.size() >= 2 * built_) {
      built_ = all.size();
      grid_ = Grid<D>(domain_, std::pow(domain_.volume() / static_cast<double>(built_), 1.0 / D));
      for (const auto& q : all) grid_.insert(q);
    } else {
      grid_.insert(p);
    }
  }

  /// The samples within r of p (at least all of them; on a torus as stored).
  void gather(const Point<D>& p, double r, PointSet<D>& out) const {
    out.clear();
    grid_.for_each_within(p, std::min(r, diameter_), [&](std::int32_t index, double) {
      out.push_back(grid_.points()[static_cast<std::size_t>(index)]);
      return true;
    });
  }

  /// The squared distance from p to the nearest sample if it exceeds beat2,
  /// else a value <= beat2. `bound` is an upper bound on that distance.
  double distance2_if_above(const Point<D>& p, double beat2, double bound) const {
    for (double r = std::min(bound, diameter_);; r = diameter_) {
      double nearest2 = kInf;
      const bool whole = grid_.for_each_within(p, r, [&](std::int32_t, double d2) {
        nearest2 = std::min(nearest2, d2);
        return d2 > beat2;
      });
      if (!whole || nearest2 < kInf || r >= diameter_) return nearest2;
    }
  }

 private:
  static double max_extent(const Domain<D>& domain) {
    double e = 0.0;
    for (int i = 0; i < D; ++i) e = std::max(e, domain.extent(i));
    return e;
  }

  Domain<D> domain_;
  Grid<D> grid_;
  std::size_t built_ = 0;
  double diameter_ = 0.0;
};

template <int D>
void validate(const BestCandidateParams& params, const Domain<D>& domain) {
  domain.validate();
  if (params.m < 1) throw InvalidArgument("best-candidate: m must be at least 1, got " + std::to_string(params.m));
  if (!params.count && !params.radius) throw InvalidArgument("best-candidate needs a count or a radius");
  if (params.count && *params.count == 0) throw InvalidArgument("best-candidate: count must be at least 1, got 0");
  if (params.radius) {
    require_radius(*params.radius);
    if (params.count) require_count_fits("best-candidate", *params.count, *params.radius, domain);
  }
}

}  // namespace

template <int D>
BestCandidateResult<D> best_candidate_run(const BestCandidateParams& params, const Domain<D>& domain,
                                          std::uint64_t seed) {
  validate(params, domain);
  // Expected final size: the count, or what a radius leaves (relative radius
  // about 0.75, i.e. ~0.6 of the packing bound).
  const double expected =
      params.count ? static_cast<double>(*params.count) : 0.6 * packing_count(domain.volume(), *params.radius, D);
  LeafBounds<D> leaves(domain, std::max(1.0, expected) * (1 << D));
  NearestSample<D> nearest(domain);
  const std::uint64_t wanted = params.count.value_or(UINT64_MAX);
  const double radius = params.radius.value_or(0.0);

  BestCandidateResult<D> result;
  PointSet<D> near;
  auto place = [&](const Point<D>& p, double distance) {
    result.points.push_back(p);
    result.distance.push_back(distance);
    nearest.add(p, result.points);
    leaves.add_sample(p);
  };
  {
    Rng rng(seed, {0});
    place(uniform_point(rng, domain), kInf);
  }
  while (result.points.size() < wanted) {
    const std::uint64_t i = result.points.size();
    const std::uint64_t candidates = static_cast<std::uint64_t>(params.m) * i;
    double best2 = -1.0, best = -1.0;
    Point<D> winner{};
    auto consider = [&](const Point<D>& c, double bound) {
      const double d2 = nearest.distance2_if_above(c, best2, bound);
      if (d2 > best2) {
        best2 = d2;
        best = std::sqrt(d2);
        winner = c;
      }
    };
    if (candidates < kBestCandidateExactBelow) {
      Rng rng(seed, {i});
      for (std::uint64_t t = 0; t < candidates; ++t) consider(uniform_point(rng, domain), leaves.max_bound());
    } else {
      const double lambda = static_cast<double>(candidates) / static_cast<double>(leaves.leaves());
      const double p0 = exp_neg(lambda);
      for (std::uint64_t attempt = 0; best2 < 0.0; ++attempt) {
        // No candidate at all has probability e^-(m*i) < e^-256; bounded anyway.
        if (attempt == 16) throw Failure("best-candidate: no candidate was drawn in 16 rounds");
        const std::uint64_t round_key = mix64(mix64(seed ^ 0x6265737463616e64ULL) + mix64(i) + attempt);
        leaves.visit_above(best, [&](std::size_t leaf) {
          if (!leaves.is_tight(leaf)) {
            Point<D> centre = leaves.leaf_lo(leaf);
            double half2 = 0.0;
            for (int k = 0; k < D; ++k) {
              centre[k] += 0.5 * leaves.edge()[k];
              half2 += 0.25 * leaves.edge()[k] * leaves.edge()[k];
            }
            nearest.gather(centre, leaves.bound(leaf) + std::sqrt(half2) * (1.0 + 1e-9), near);
            leaves.tighten(leaf, near, std::max(best, 0.0));
            if (!(leaves.bound(leaf) > best)) return;
          }
          // Most leaves draw no candidate: decide that from one hash before
          // setting up the leaf's generator.
          const std::uint64_t key = mix64(round_key ^ mix64(leaf + 0x632be59bd9b4e019ULL));
          const double u = static_cast<double>(key >> 11) * 0x1.0p-53;
          if (u < p0) return;
          const std::uint64_t n = poisson_above_zero(u, lambda, p0);
          Rng rng(key);
          const Point<D> lo = leaves.leaf_lo(leaf);
          for (std::uint64_t t = 0; t < n; ++t) {
            Point<D> c;
            for (int k = 0; k < D; ++k)
              c[k] = std::min(lo[k] + rng.uniform() * leaves.edge()[k], std::nextafter(domain.hi[k], domain.lo[k]));
            // A NaN witness compares false: no filter.
            if (domain.distance2(c, leaves.witness(leaf)) <= best2) continue;
            consider(c, leaves.bound(leaf));
          }
        });
      }
    }
    if (best < radius) {
      if (!params.count) break;
      throw InvalidArgument("best-candidate: placed only " + std::to_string(i) + " of the " + std::to_string(wanted) +
                            " points requested at radius " + format(radius) +
                            " before the best candidate fell closer than the radius; ask for fewer points or a "
                            "smaller radius");
    }
    place(winner, best);
  }
  return result;
}

template BestCandidateResult<2> best_candidate_run<2>(const BestCandidateParams&, const Domain<2>&, std::uint64_t);
template BestCandidateResult<3> best_candidate_run<3>(const BestCandidateParams&, const Domain<3>&, std::uint64_t);

const Method& best_candidate_method() {
  static const Method method{
      .name = "best-candidate",
      .summary = "Mitchell's best-candidate: each sample the farthest of m*i random candidates; progressive",
      .citation = "D. P. Mitchell, Spectrally optimal sampling for distribution ray tracing, SIGGRAPH 1991",
      .takes_count = true,
      .takes_radius = true,
      .params = {{"m", kBestCandidateDefaultM, 1, 1000, true, "candidates per sample already placed"}},
      .run =
          [](const GenerateRequest& r) {
            return run_typed(r, [&](const auto& domain) {
              BestCandidateParams params;
              params.count = r.count;
              params.radius = r.radius;
              params.m = static_cast<int>(r.param("m", kBestCandidateDefaultM));
              return best_candidate(params, domain, r.seed);
            });
          },
  };
  return method;
}

}  // namespace pds
