#pragma once
// Fourier view of point sets: the exact periodogram, its radial average and
// the anisotropy (Ulichney, "Digital Halftoning", 1987; the measures of
// Schlomer and Heck's PSA and of pbrt's pspec).
//
// Normalisation. The points x_1..x_N of one set are mapped to the unit cube,
// u = (x - lo) / L per axis, and for every integer frequency vector k with
// |k_i| <= K the periodogram is
//
//     P(k) = |sum_j exp(-2 pi i k.u_j)|^2 / N,
//
// the exact discrete Fourier transform of the points (no binning of
// positions). k counts cycles per domain extent, so on a torus these are
// exactly the frequencies the domain carries. For N independent uniform
// points E[P(k)] = 1 for every k != 0 (white noise is flat at 1) and
// P(0) = N. M sets are averaged frequency by frequency; the average of M
// white-noise periodograms has mean 1 and variance about 1/M.
//
// Radial average and anisotropy. Frequencies are grouped in annuli of width
// one frequency step (1 / the longest extent) around |f| = b steps, b >= 1;
// only annuli that lie entirely inside the computed cube are kept (b <= K).
// For each annulus the power is the mean of P and the anisotropy is
// 10 log10(s^2 / mean^2) dB with s^2 the sample variance: about
// 10 log10(1/M) dB for an isotropic spectrum, so -10 dB at M = 10. The
// frequency of an annulus is reported as nu = |f| * d, with d = (V / N)^(1/D)
// the mean inter-point distance, so that sets of different N compare: a
// square grid has its first peak at nu = 1 and blue noise its ring near 1.

#include <cstddef>
#include <span>
#include <vector>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

struct PeriodogramOptions {
  /// K: frequencies k_i = -K..K on every axis, (2K+1)^D in all. The default
  /// gives the 257 x 257 image of 2D tools. At most 1024 (2D) or 128 (3D).
  int max_frequency = 128;
};

/// The averaged periodogram on the integer frequency cube [-K, K]^D.
struct Periodogram {
  int dim = 2;
  int max_frequency = 0;       // K
  std::size_t sets = 0;        // M, the number of sets averaged
  double mean_count = 0;       // mean N over the sets
  std::vector<double> extent;  // domain extent per axis (frequency k_i is k_i / extent_i cycles per unit)
  /// P averaged over the sets; axis 0 varies fastest, index (k_i + K).
  std::vector<double> power;

  int side() const { return 2 * max_frequency + 1; }
  /// The mean inter-point distance (V / N)^(1/D) of the sets.
  double mean_spacing() const;
  /// P at frequency (kx, ky) of a 2D periodogram, |k_i| <= K.
  double at(int kx, int ky) const {
    return power[static_cast<std::size_t>(ky + max_frequency) * side() + static_cast<std::size_t>(kx + max_frequency)];
  }
};

/// The periodogram of each set, averaged over the sets (all in `domain`). Each
/// set needs at least one point. Computed by the exact DFT: each point's
/// complex exponentials along an axis follow from one another by a rotation
/// (the recurrence e^{-2 pi i (k+1) u} = e^{-2 pi i k u} e^{-2 pi i u},
/// re-anchored every 32 steps), and the frequency rows are spread over
/// threads; each frequency sums its points in a fixed order, so the result does not
/// depend on the number of threads. Cost: N M (2K+1)^D / 2 complex
/// multiply-adds. Throws InvalidArgument for no sets, an empty set, a point
/// outside the domain or K out of range. Optional progress (chunks of
/// frequency rows done) and cancellation (pds/progress.h): with a listener
/// the rows run in batches of two chunks a thread, reported between them
/// (the result is the same).
template <int D>
Periodogram periodogram(std::span<const PointSet<D>> sets, const Domain<D>& domain,
                        const PeriodogramOptions& options = {}, const Progress& progress = {});

/// One annulus per frequency step b = 1..K (see the header comment).
struct RadialSpectrum {
  std::vector<double> frequency;      // nu: annulus centre times the mean inter-point distance
  std::vector<double> power;          // mean P over the annulus
  std::vector<double> anisotropy_db;  // 10 log10(variance / mean^2)
  std::vector<std::size_t> samples;   // frequencies in the annulus
  std::size_t sets = 0;
};

RadialSpectrum radial_average(const Periodogram& periodogram);

}  // namespace pds
