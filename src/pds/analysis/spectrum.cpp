// The exact periodogram of point sets and its radial average; normalisations
// in include/pds/analysis/spectrum.h.
//
// Work plan. P is symmetric (P(-k) = P(k) for real positions), so only the
// frequency rows whose last coordinate is >= 0 are computed and the others
// mirrored. The rows are cut into fixed chunks (independent of the thread
// count) that TBB runs in parallel; a chunk walks the sets in order and, per
// set, the points in blocks: for a block it tabulates each point's
// exponentials along every axis by the rotation recurrence, then adds
// c * e^{-2 pi i kx ux} to each row of the chunk, c being the product of the
// point's exponentials on the other axes (tabulated only for the rows of the
// chunk). The innermost loop runs over kx on separate real and imaginary
// arrays, which the compiler vectorises (SSE2, and AVX2 in a clone chosen at
// run time; both clones were checked to give the same bytes). Every
// frequency adds its points (four at a time, in input order) and then its
// sets in a fixed order, so the sums are the same bytes on any number of
// threads.

#include "pds/analysis/spectrum.h"


#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "pds/error.h"
#include "pds/parallel.h"

// Function multi-versioning needs GCC or Clang on an ELF x86-64 target (ifunc).
#if defined(__x86_64__) && defined(__linux__) && (defined(__GNUC__) || defined(__clang__))
#define PDS_CLONE_AVX2 __attribute__((target_clones("avx2", "default")))
#else
#define PDS_CLONE_AVX2
#endif

namespace pds {
namespace {

constexpr int kAnchorEvery = 32;   // recompute cos/sin directly every this many steps: keeps rounding at ~1e-15
constexpr int kPointBlock = 64;    // points whose exponential tables are held at once
constexpr int kRowsPerChunk = 16;  // frequency rows per parallel task

/// e^{-2 pi i k u} for k = k_first..k_last into re[k - k_first], im[k - k_first].
void exponentials(double u, int k_first, int k_last, double* re, double* im) {
  const double step = 2.0 * std::numbers::pi * u;
  const double w_re = std::cos(step), w_im = -std::sin(step);
  for (int k = k_first; k <= k_last; ++k) {
    const int i = k - k_first;
    if (i % kAnchorEvery == 0) {
      // Reduce k*u to [0, 1) before the trigonometry so large k lose nothing.
      const double t = static_cast<double>(k) * u;
      const double angle = 2.0 * std::numbers::pi * (t - std::floor(t));
      re[i] = std::cos(angle);
      im[i] = -std::sin(angle);
    } else {
      re[i] = re[i - 1] * w_re - im[i - 1] * w_im;
      im[i] = re[i - 1] * w_im + im[i - 1] * w_re;
    }
  }
}

/// acc += sum_j c_j e_j over one frequency row, for `count` points whose row
/// exponentials e_j lie `side` apart. Four points per pass: the accumulator
/// is loaded and stored once for four multiply-adds (the loop is bound by
/// memory operations otherwise). Cloned for AVX2 where the CPU has it: the
/// lanes are independent frequencies and nothing is fused (-ffp-contract=off),
/// so both clones give the same bytes.
PDS_CLONE_AVX2 void accumulate_row(const double* coef_re, const double* coef_im, int count, const double* tab_re,
                                   const double* tab_im, std::size_t side, double* __restrict are,
                                   double* __restrict aim) {
  int j = 0;
  for (; j + 4 <= count; j += 4) {
    const double* __restrict e0r = tab_re + static_cast<std::size_t>(j) * side;
    const double* __restrict e0i = tab_im + static_cast<std::size_t>(j) * side;
    const double* __restrict e1r = e0r + side;
    const double* __restrict e1i = e0i + side;
    const double* __restrict e2r = e1r + side;
    const double* __restrict e2i = e1i + side;
    const double* __restrict e3r = e2r + side;
    const double* __restrict e3i = e2i + side;
    const double c0r = coef_re[j], c0i = coef_im[j], c1r = coef_re[j + 1], c1i = coef_im[j + 1];
    const double c2r = coef_re[j + 2], c2i = coef_im[j + 2], c3r = coef_re[j + 3], c3i = coef_im[j + 3];
    for (std::size_t k = 0; k < side; ++k) {
      const double sr = (c0r * e0r[k] - c0i * e0i[k]) + (c1r * e1r[k] - c1i * e1i[k]) +
                        ((c2r * e2r[k] - c2i * e2i[k]) + (c3r * e3r[k] - c3i * e3i[k]));
      const double si = (c0r * e0i[k] + c0i * e0r[k]) + (c1r * e1i[k] + c1i * e1r[k]) +
                        ((c2r * e2i[k] + c2i * e2r[k]) + (c3r * e3i[k] + c3i * e3r[k]));
      are[k] += sr;
      aim[k] += si;
    }
  }
  for (; j < count; ++j) {
    const double* __restrict ere = tab_re + static_cast<std::size_t>(j) * side;
    const double* __restrict eim = tab_im + static_cast<std::size_t>(j) * side;
    const double c_re = coef_re[j], c_im = coef_im[j];
    for (std::size_t k = 0; k < side; ++k) {
      are[k] += c_re * ere[k] - c_im * eim[k];
      aim[k] += c_re * eim[k] + c_im * ere[k];
    }
  }
}

template <int D>
void add_chunk(std::span<const PointSet<D>> sets, const Domain<D>& domain, int K, std::size_t row_begin,
               std::size_t row_end, double* out) {
  const std::size_t side = static_cast<std::size_t>(2 * K + 1);
  const std::size_t rows = row_end - row_begin;
  std::vector<double> acc_re(rows * side), acc_im(rows * side);
  // table[axis][point in block][k + K]
  std::vector<double> tab_re(static_cast<std::size_t>(D) * kPointBlock * side);
  std::vector<double> tab_im(tab_re.size());
  std::vector<double> coef_re(kPointBlock), coef_im(kPointBlock);
  // The higher-axis frequency offsets (k_a + K) of each row of the chunk.
  std::vector<std::array<int, D>> row_k(rows);
  for (std::size_t r = 0; r < rows; ++r) {
    std::size_t index = row_begin + r;
    for (int a = 1; a < D; ++a) {
      const std::size_t n = a + 1 < D ? side : static_cast<std::size_t>(K + 1);
      // The last axis holds only k >= 0 (offset K..2K).
      row_k[r][a] = static_cast<int>(index % n) + (a + 1 < D ? 0 : K);
      index /= n;
    }
  }
  // Axes above 0 need only the offsets their rows use: tabulate just those.
  std::array<int, D> first_k, last_k;
  first_k[0] = 0;
  last_k[0] = 2 * K;
  for (int a = 1; a < D; ++a) {
    first_k[a] = 2 * K;
    last_k[a] = 0;
    for (const auto& k : row_k) {
      first_k[a] = std::min(first_k[a], k[a]);
      last_k[a] = std::max(last_k[a], k[a]);
    }
  }
  for (const PointSet<D>& set : sets) {
    std::fill(acc_re.begin(), acc_re.end(), 0.0);
    std::fill(acc_im.begin(), acc_im.end(), 0.0);
    for (std::size_t first = 0; first < set.size(); first += kPointBlock) {
      const int count = static_cast<int>(std::min<std::size_t>(kPointBlock, set.size() - first));
      for (int j = 0; j < count; ++j)
        for (int a = 0; a < D; ++a) {
          const double u = (set[first + j][a] - domain.lo[a]) / domain.extent(a);
          const std::size_t at = (static_cast<std::size_t>(a) * kPointBlock + j) * side;
          exponentials(u, first_k[a] - K, last_k[a] - K, tab_re.data() + at, tab_im.data() + at);
        }
      for (std::size_t r = 0; r < rows; ++r) {
        // c_j: the product of point j's exponentials on the axes above 0.
        for (int j = 0; j < count; ++j) {
          double c_re = 1.0, c_im = 0.0;
          for (int a = 1; a < D; ++a) {
            const std::size_t at = (static_cast<std::size_t>(a) * kPointBlock + j) * side + (row_k[r][a] - first_k[a]);
            const double t = c_re * tab_re[at] - c_im * tab_im[at];
            c_im = c_re * tab_im[at] + c_im * tab_re[at];
            c_re = t;
          }
          coef_re[j] = c_re;
          coef_im[j] = c_im;
        }
        accumulate_row(coef_re.data(), coef_im.data(), count, tab_re.data(), tab_im.data(), side,
                       acc_re.data() + r * side, acc_im.data() + r * side);
      }
    }
    const double inv_n = 1.0 / static_cast<double>(set.size());
    for (std::size_t i = 0; i < rows * side; ++i) out[i] += (acc_re[i] * acc_re[i] + acc_im[i] * acc_im[i]) * inv_n;
  }
}

}  // namespace

double Periodogram::mean_spacing() const {
  double volume = 1.0;
  for (double e : extent) volume *= e;
  return std::pow(volume / mean_count, 1.0 / dim);
}

template <int D>
Periodogram periodogram(std::span<const PointSet<D>> sets, const Domain<D>& domain, const PeriodogramOptions& options,
                        const Progress& progress) {
  domain.validate();
  const int K = options.max_frequency;
  const int limit = D == 2 ? 1024 : 128;
  if (K < 1 || K > limit)
    throw InvalidArgument("periodogram: max frequency must be in [1, " + std::to_string(limit) + "] in " +
                          std::to_string(D) + "D, got " + std::to_string(K));
  if (sets.empty()) throw InvalidArgument("periodogram: no point sets given");
  Periodogram result;
  result.dim = D;
  result.max_frequency = K;
  result.sets = sets.size();
  for (int a = 0; a < D; ++a) result.extent.push_back(domain.extent(a));
  double total = 0;
  for (std::size_t s = 0; s < sets.size(); ++s) {
    if (sets[s].empty()) throw InvalidArgument("periodogram: point set " + std::to_string(s) + " is empty");
    for (const auto& p : sets[s])
      if (!domain.contains(p))
        throw InvalidArgument("periodogram: a point of set " + std::to_string(s) + " lies outside the domain");
    total += static_cast<double>(sets[s].size());
  }
  result.mean_count = total / static_cast<double>(sets.size());

  const std::size_t side = static_cast<std::size_t>(2 * K + 1);
  std::size_t rows = static_cast<std::size_t>(K + 1);  // the last axis, k >= 0
  for (int a = 1; a + 1 < D; ++a) rows *= side;
  // The computed half: row index r holds the higher axes in the order of
  // add_chunk, the last axis being k_last = r / (side^(D-2)) >= 0.
  std::vector<double> half(rows * side, 0.0);
  const std::size_t chunks = (rows + kRowsPerChunk - 1) / kRowsPerChunk;
  const auto run = [&](std::size_t from, std::size_t to) {
    parallel_for(from, to, 1, 0, [&](std::size_t first, std::size_t last) {
      for (std::size_t c = first; c != last; ++c) {
        const std::size_t begin = c * kRowsPerChunk, end = std::min(rows, begin + kRowsPerChunk);
        add_chunk<D>(sets, domain, K, begin, end, half.data() + begin * side);
      }
    });
  };
  if (!progress) {
    run(0, chunks);
  } else {
    // Batches of two chunks a thread: each chunk still writes only its own
    // rows, so the result does not change; the batches cost a wait each.
    ProgressReporter reporter(progress, static_cast<double>(chunks));
    const std::size_t batch = 2 * static_cast<std::size_t>(hardware_threads());
    for (std::size_t from = 0; from < chunks; from += batch) {
      run(from, std::min(chunks, from + batch));
      reporter.update(static_cast<double>(std::min(chunks, from + batch)));
    }
    reporter.finish();
  }

  // Unfold into the full cube: the computed half holds the offsets of the
  // last axis K..2K; the rest is the mirror image through the origin.
  std::size_t full = 1;
  for (int a = 0; a < D; ++a) full *= side;
  result.power.resize(full);
  const std::size_t lower = full / side;  // entries per value of the last axis
  const double inv_m = 1.0 / static_cast<double>(sets.size());
  for (std::size_t i = 0; i < full; ++i) {
    std::size_t last = i / lower;
    std::size_t source = i;
    if (last < static_cast<std::size_t>(K)) source = full - 1 - i;  // offset o -> 2K - o on every axis
    last = source / lower;
    result.power[i] = half[(last - K) * lower + source % lower] * inv_m;
  }
  return result;
}

template Periodogram periodogram<2>(std::span<const PointSet<2>>, const Domain<2>&, const PeriodogramOptions&,
                                    const Progress&);
template Periodogram periodogram<3>(std::span<const PointSet<3>>, const Domain<3>&, const PeriodogramOptions&,
                                    const Progress&);

RadialSpectrum radial_average(const Periodogram& p) {
  const int K = p.max_frequency;
  const std::size_t side = static_cast<std::size_t>(p.side());
  const double longest = *std::max_element(p.extent.begin(), p.extent.end());
  std::vector<double> sum(K + 1, 0.0), sum2(K + 1, 0.0);
  std::vector<std::size_t> count(K + 1, 0);
  std::vector<int> bin(p.power.size(), -1);
  for (std::size_t i = 0; i < p.power.size(); ++i) {
    std::size_t rest = i;
    double f2 = 0;
    for (int a = 0; a < p.dim; ++a) {
      const double k = static_cast<double>(static_cast<int>(rest % side) - K) / p.extent[a];
      rest /= side;
      f2 += k * k;
    }
    const long b = std::lround(std::sqrt(f2) * longest);
    if (b < 1 || b > K) continue;
    bin[i] = static_cast<int>(b);
    sum[b] += p.power[i];
    ++count[b];
  }
  for (std::size_t i = 0; i < p.power.size(); ++i)
    if (bin[i] > 0) {
      const double d = p.power[i] - sum[bin[i]] / static_cast<double>(count[bin[i]]);
      sum2[bin[i]] += d * d;
    }
  RadialSpectrum r;
  r.sets = p.sets;
  const double spacing = p.mean_spacing();
  for (int b = 1; b <= K; ++b) {
    if (count[b] < 2) continue;
    const double mean = sum[b] / static_cast<double>(count[b]);
    const double variance = sum2[b] / static_cast<double>(count[b] - 1);
    r.frequency.push_back(b / longest * spacing);
    r.power.push_back(mean);
    r.anisotropy_db.push_back(10.0 * std::log10(variance / (mean * mean)));
    r.samples.push_back(count[b]);
  }
  return r;
}

}  // namespace pds
