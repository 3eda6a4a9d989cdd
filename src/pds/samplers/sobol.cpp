// Sobol sequence.
//
// I. M. Sobol, On the distribution of points in a cube and the approximate
// evaluation of integrals, USSR Comput. Math. Math. Phys. 7(4), 1967.
// Direction numbers: S. Joe and F. Y. Kuo, Constructing Sobol sequences with
// better two-dimensional projections, SIAM J. Sci. Comput. 30(5), 2008: their
// new-joe-kuo-6.21201 table (https://web.maths.unsw.edu.au/~fkuo/sobol/,
// BSD-style licence), bit-packed in data/sobol/new-joe-kuo-6.21201.bin
// (scripts/sobol_directions.py writes it) and embedded at build time
// (cmake/embed_binary.cmake); decoded once, on first use. Gray-code order: I. A.
// Antonov and V. M. Saleev, USSR Comput. Math. Math. Phys. 19(1), 1979.
// Scrambling: A. B. Owen, Randomly permuted (t,m,s)-nets and (t,s)-sequences,
// 1995.
//
// Method: axis a of point i is the XOR of the direction numbers v_a[k] over
// the set bits k of gray(i) = i ^ (i >> 1); consecutive Gray codes differ in
// bit ctz(i + 1), so walking a range costs one XOR per coordinate after a
// direct computation of its first point.
// Guarantees: see sobol.h; in 2D the sequence is a (0, 2)-sequence in base 2.
// Complexity: O(count * D), about one XOR, one conversion and one multiply-add
// a coordinate unscrambled (a transposed table of the axes' direction numbers
// keeps the XOR of a step contiguous); Owen scrambling walks all 32 bits (6 hashes).
// Limits: indices below 2^32 (32-bit direction numbers); up to 21,201 axes.
// One code path for every dimension: the typed sobol<D> fills its points
// through sobol_fill.
// Why not GSL's gsl_qrng_sobol: it only steps forward from the start (no
// random access to a range), has no scrambling, and costs a call per point;
// the code here is a few lines. The tests compare the two point by point.

#include "pds/samplers/sobol.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <mutex>
#include <optional>
#include <vector>

#include "mapped_pages.h"
#include "pds/detail/instantiate.h"
#include "pds/error.h"

namespace pds {
namespace detail {
// Generated from data/sobol/new-joe-kuo-6.21201.bin (cmake/embed_binary.cmake).
extern const unsigned char kSobolJoeKuoData[];
extern const std::size_t kSobolJoeKuoDataSize;
}  // namespace detail

namespace {

/// Reads the table's bit stream, least significant bit first.
class BitReader {
 public:
  BitReader(const unsigned char* data, std::size_t size) : data_(data), size_(size) {}
  std::uint32_t take(int width) {
    std::uint32_t v = 0;
    for (int k = 0; k < width; ++k, ++bit_) {
      if (bit_ / 8 >= size_) throw Failure("sobol: the embedded direction numbers are truncated");
      v |= static_cast<std::uint32_t>((data_[bit_ / 8] >> (bit_ % 8)) & 1u) << k;
    }
    return v;
  }

 private:
  const unsigned char* data_;
  std::size_t size_;
  std::size_t bit_ = 0;
};

/// Direction numbers of the first `axes` axes, v[axis][k]: decoded from the
/// table's bit stream (read in order) as far as any call has asked, once.
/// Not the whole table at once: that is 2.7 MB, which a call in a few
/// dimensions never needs (it was most of a 2D run's memory at 10^5 points).
/// The returned block holds at least `axes` rows and never moves (its room
/// is reserved for every axis; pages not written are not resident).
const std::array<std::uint32_t, 32>* directions(int axes) {
  struct Decoded {
    std::mutex mutex;
    std::vector<std::array<std::uint32_t, 32>> v;
    std::optional<BitReader> in;
    bool corrupt = false;  // a decode failed: the stream's place is lost, every call fails
  };
  static Decoded decoded;
  const std::lock_guard<std::mutex> lock(decoded.mutex);
  if (decoded.corrupt) throw Failure("sobol: the embedded direction numbers are corrupt");
  auto& v = decoded.v;
  if (!decoded.in) {
    const unsigned char* data = detail::kSobolJoeKuoData;
    const std::size_t size = detail::kSobolJoeKuoDataSize;
    std::uint32_t rows = 0;
    if (size < 8 || std::memcmp(data, "JK6", 4) != 0) throw Failure("sobol: the embedded direction numbers are corrupt");
    for (int b = 0; b < 4; ++b) rows |= static_cast<std::uint32_t>(data[4 + b]) << (8 * b);
    if (rows + 1 != static_cast<std::uint32_t>(kSobolMaxDim))
      throw Failure("sobol: the embedded table has " + std::to_string(rows) + " rows, expected " +
                    std::to_string(kSobolMaxDim - 1));
    v.reserve(kSobolMaxDim);
    v.emplace_back();
    for (int k = 0; k < 32; ++k) v[0][k] = std::uint32_t{1} << (31 - k);  // axis 0: van der Corput
    decoded.in.emplace(data + 8, size - 8);
  }
  BitReader& in = *decoded.in;
  try {
    while (static_cast<int>(v.size()) < axes) {
      const int s = static_cast<int>(in.take(5));
      if (s < 1 || s > 31) throw Failure("sobol: the embedded direction numbers are corrupt");
      const std::uint32_t a = in.take(s - 1);  // the coefficients of x^(s-1) ... x^1, highest first
      std::array<std::uint32_t, 32> d{};
      for (int k = 0; k < s; ++k) d[k] = (2 * in.take(k) + 1) << (31 - k);  // m_(k+1), odd, below 2^(k+1)
      // Bratley & Fox's recurrence on left-aligned direction numbers.
      for (int k = s; k < 32; ++k) {
        d[k] = d[k - s] ^ (d[k - s] >> s);
        for (int l = 1; l < s; ++l)
          if ((a >> (s - 1 - l)) & 1) d[k] ^= d[k - l];
      }
      v.push_back(d);
    }
  } catch (...) {
    decoded.corrupt = true;
    throw;
  }
  return v.data();
}

}  // namespace

std::array<std::uint32_t, 32> sobol_directions(int axis) {
  if (axis < 0 || axis >= kSobolMaxDim)
    throw InvalidArgument("sobol: axis " + std::to_string(axis) + " is beyond the " + std::to_string(kSobolMaxDim) +
                          " embedded axes");
  return directions(axis + 1)[axis];
}

namespace {

/// The walk through a range of the sequence: set up once (the first point
/// from its Gray code, the scrambling of every axis), then points block after
/// block, so that a caller can stage them in a small buffer.
class SobolWalk {
 public:
  SobolWalk(const SobolParams& params, const CloudBox& box, std::uint64_t seed)
      : n_(static_cast<std::size_t>(box.dim())), scramble_(params.scramble), index_(params.first), map_(box) {
    const int dim = box.dim();
    if (dim < 1 || dim > kSobolMaxDim)
      throw InvalidArgument("sobol: dimension " + std::to_string(dim) + " is not supported (supported: 1 to " +
                            std::to_string(kSobolMaxDim) + ", Joe & Kuo's direction numbers)");
    require_index_range("sobol", params.first, params.count);
    const auto* v = directions(dim);
    // Step k's direction numbers of every axis side by side: vt[k * dim + a].
    vt_.resize(32 * n_);
    for (std::size_t a = 0; a < n_; ++a)
      for (int k = 0; k < 32; ++k) vt_[static_cast<std::size_t>(k) * n_ + a] = v[a][k];
    // The first point directly from its Gray code, the others by one XOR each.
    x_.assign(n_, 0);
    const auto first = static_cast<std::uint32_t>(params.first);
    const std::uint32_t gray = first ^ (first >> 1);
    for (int k = 0; k < 32; ++k)
      if ((gray >> k) & 1)
        for (std::size_t a = 0; a < n_; ++a) x_[a] ^= vt_[static_cast<std::size_t>(k) * n_ + a];
    if (scramble_ != Scramble::none) {
      key_.resize(n_);
      shift_.resize(n_);
      tail_.resize(n_);
      for (std::size_t a = 0; a < n_; ++a) {
        key_[a] = scramble_key(seed, 3, static_cast<int>(a));
        const DigitPermutation<2> perm(key_[a]);
        shift_[a] = perm.apply(0);  // the XOR mask of a base-2 digit permutation
        tail_[a] = perm.tail();
      }
    }
  }

  /// The next `count` points into out (count * dim doubles).
  void fill(std::uint64_t count, double* out) {
    switch (scramble_) {
      case Scramble::none:
        walk<Scramble::none>(count, out);
        break;
      case Scramble::permute_digits:
        walk<Scramble::permute_digits>(count, out);
        break;
      case Scramble::owen:
        walk<Scramble::owen>(count, out);
        break;
    }
  }

 private:
  // One loop per scrambling, so that the choice is not re-made per coordinate.
  template <Scramble scramble>
  void walk(std::uint64_t count, double* out) {
    const std::size_t n = n_;
    const double* __restrict lo = map_.lo();
    const double* __restrict extent = map_.extent();
    const double* __restrict top = map_.top();
    std::uint32_t* __restrict xs = x_.data();
    for (std::uint64_t i = 0; i < count; ++i, ++index_) {
      double* __restrict p = out + i * n;
      for (std::size_t a = 0; a < n; ++a) {
        double u;
        if constexpr (scramble == Scramble::none)
          u = xs[a] * 0x1.0p-32;
        else if constexpr (scramble == Scramble::permute_digits)
          u = digits_to_unit<2>(xs[a] ^ shift_[a], tail_[a]);
        else
          u = owen_scramble<2>(xs[a], key_[a]);
        p[a] = std::min(lo[a] + u * extent[a], top[a]);
      }
      const int bit = std::countr_zero(static_cast<std::uint32_t>(index_ + 1));  // 32 after the last index
      if (bit < 32) {
        const std::uint32_t* __restrict step = vt_.data() + static_cast<std::size_t>(bit) * n;
        for (std::size_t a = 0; a < n; ++a) xs[a] ^= step[a];
      }
    }
  }

  std::size_t n_;
  Scramble scramble_;
  std::uint64_t index_;
  BoxMap map_;
  std::vector<std::uint32_t> vt_, x_;
  std::vector<std::uint64_t> key_, shift_;
  std::vector<double> tail_;
};

}  // namespace

void sobol_fill(const SobolParams& params, const CloudBox& box, std::uint64_t seed, double* out) {
  SobolWalk walk(params, box, seed);
  ProgressReporter progress(params.progress, static_cast<double>(params.count));
  const std::uint64_t block = std::max<std::uint64_t>(1, 32768 / static_cast<std::uint64_t>(box.dim()));
  for (std::uint64_t done = 0; done < params.count;) {
    const std::uint64_t now = std::min(block, params.count - done);
    walk.fill(now, out + done * static_cast<std::uint64_t>(box.dim()));
    done += now;
    progress.update(static_cast<double>(done));
  }
  progress.finish();
}

PointCloud sobol(const SobolParams& params, const CloudBox& box, std::uint64_t seed) {
  PointCloud cloud{box.dim(), {}};
  const std::size_t total = cloud_doubles("sobol", params.count, box.dim());
  SobolWalk walk(params, box, seed);
  ProgressReporter progress(params.progress, static_cast<double>(params.count));
  // Staged through a buffer of about 256 KB and appended: the set's memory
  // is written once, not zeroed first (as resize would) and then written.
  const std::uint64_t block = std::max<std::uint64_t>(1, 32768 / static_cast<std::uint64_t>(box.dim()));
  std::vector<double> stage(static_cast<std::size_t>(std::min(block, params.count)) * static_cast<std::size_t>(box.dim()));
  cloud.coords.reserve(total);
  detail::advise_huge_pages(cloud.coords);
  for (std::uint64_t done = 0; done < params.count;) {
    const std::uint64_t now = std::min(block, params.count - done);
    walk.fill(now, stage.data());
    cloud.coords.insert(cloud.coords.end(), stage.begin(), stage.begin() + static_cast<std::ptrdiff_t>(now * box.dim()));
    done += now;
    progress.update(static_cast<double>(done));
  }
  progress.finish();
  return cloud;
}

template <int D>
PointSet<D> sobol(const SobolParams& params, const Domain<D>& domain, std::uint64_t seed) {
  require_index_range("sobol", params.first, params.count);
  PointSet<D> points = detail::output_points<D>(params.count);
  sobol_fill(params, CloudBox::of(domain), seed, points.data()->data());
  return points;
}

#define PDS_INSTANTIATE(D) template PointSet<D> sobol<D>(const SobolParams&, const Domain<D>&, std::uint64_t);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
