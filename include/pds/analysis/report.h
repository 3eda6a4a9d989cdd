#pragma once
// The analysis report: the measures of docs/verification.md and
// docs/analysis.md for one or several realisations of a point process, as a
// plain struct that any front end (the `pds analyze` command, a Python
// module, a test) fills by one call and writes as it likes (JSON:
// pds/io/report_json.h).
//
// Several sets are realisations of one process: the fields of the first
// group (count, min_distance, maximality, ...) describe the first set; the
// spacing and discrepancy fields are means over the sets; the spectrum and
// the pair correlation are averaged over all of them.
//
// Dimensions: everything in 2D and 3D; in 1 and 4 to 8 dimensions all but the
// spectrum and the pair correlation; past 8 (run-time dimension) distances
// and discrepancies only. docs/analysis.md has the table.

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pds/analysis/pair_correlation.h"
#include "pds/analysis/spectrum.h"
#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

/// Periodogram work (points x frequencies / 2) done without being asked for
/// (AnalysisOptions::spectrum false): a few seconds at most.
inline constexpr double kDefaultSpectrumWork = 2e9;

struct AnalysisOptions {
  /// The minimum distance to check; also reports maximality at this radius.
  std::optional<double> radius;
  /// Periodogram frequencies -K..K per axis; 0: 128 in 2D, 32 in 3D.
  int max_frequency = 0;
  /// Compute the spectrum whatever it costs; otherwise it is skipped (and
  /// AnalysisReport::spectrum_note says so) beyond spectrum_work points x
  /// frequencies / 2.
  bool spectrum = false;
  double spectrum_work = kDefaultSpectrumWork;
  /// r_max and bandwidth of the pair correlation function (0: its defaults).
  PairCorrelationOptions pcf;
  /// The centered, wrap-around and mixture discrepancies (O(N^2 D) each) are
  /// computed for sets of at most this many points.
  std::size_t discrepancy_points = std::size_t{1} << 14;
  /// Progress (pds/progress.h): one unit per set measured, then one each for
  /// the spectrum and the pair correlation; returning false stops with
  /// pds::Cancelled.
  Progress progress;
};

/// Maximality at AnalysisOptions::radius (analysis/maximality.h).
struct MaximalityReport {
  bool maximal = false;
  bool exact = false;                      // decided exactly (tolerance 0)
  double tolerance = 0.0;                  // otherwise: every point is within radius + tolerance of a sample
  std::optional<std::vector<double>> gap;  // a point farther than the radius from every sample
  double gap_distance = 0.0;               // its distance to the nearest sample
  std::size_t cells_checked = 0;
  bool budget_exhausted = false;  // the tolerance is check_maximality's cell budget's
};

/// The radial spectrum in a few numbers (frequencies in units of the mean
/// inter-point distance, power 1 for white noise; analysis/spectrum.h).
/// NaN where the spectrum has no annulus to take it from.
struct SpectrumSummary {
  int max_frequency = 0;
  double low_frequency_power = std::numeric_limits<double>::quiet_NaN();  // mean over frequencies <= 0.5
  double peak_frequency = std::numeric_limits<double>::quiet_NaN();
  double peak_power = std::numeric_limits<double>::quiet_NaN();
  double mean_anisotropy_db = std::numeric_limits<double>::quiet_NaN();
};

/// The pair correlation function in a few numbers (analysis/pair_correlation.h).
struct PcfSummary {
  double bandwidth = 0;
  double r_max = 0;
  double peak_r = 0;  // where g is largest
  double peak_g = 0;
};

struct AnalysisReport {
  // The first set.
  std::size_t count = 0;
  int dim = 2;
  std::vector<double> lo, hi;  // the domain
  bool torus = false;
  /// The smallest distance between two points (inf for fewer than two) and a
  /// pair attaining it (i < j).
  double min_distance = std::numeric_limits<double>::infinity();
  std::optional<std::array<std::size_t, 2>> min_distance_pair;
  double mean_nn_distance = std::numeric_limits<double>::quiet_NaN();    // NaN for fewer than two points
  double relative_radius = 0;                                            // Lagae & Dutre 2008; NaN past kMaxDim
  std::string relative_radius_note;                                      // why it is NaN, when it is
  double max_packing_radius = std::numeric_limits<double>::quiet_NaN();  // NaN for no points
  /// With AnalysisOptions::radius: that radius, whether every pair is at
  /// least that far apart, and maximality at it.
  std::optional<double> radius;
  bool min_distance_holds = false;
  std::optional<MaximalityReport> maximality;
  std::string maximality_note;  // why maximality was not checked at the radius (past kMaxDim)

  // Over all the sets.
  std::size_t sets = 0;
  double rho_min = std::numeric_limits<double>::quiet_NaN();   // mean; NaN unless every set has two points
  double rho_mean = std::numeric_limits<double>::quiet_NaN();  // mean; NaN unless every set has two points
  std::optional<double> l2_star_discrepancy;                   // mean; absent beyond kMaxL2StarPoints
  std::optional<double> star_discrepancy;                      // mean; absent where star_discrepancy_feasible is false
  /// Means of SciPy's qmc.discrepancy methods "CD", "WD", "MD" (squares,
  /// analysis/discrepancy.h) on the sets scaled into the unit cube; absent
  /// beyond AnalysisOptions::discrepancy_points.
  std::optional<double> centered_discrepancy, wrap_around_discrepancy, mixture_discrepancy;
  std::optional<SpectrumSummary> spectrum;
  std::string spectrum_note;      // why the spectrum was skipped, when it was
  std::optional<PcfSummary> pcf;  // absent unless every set has two points (and outside 2D and 3D)
  std::string pcf_note;           // why the pair correlation was not computed, outside 2D and 3D
};

/// The curves behind the summaries, for pictures and tables.
struct AnalysisCurves {
  std::optional<Periodogram> periodogram;
  std::optional<RadialSpectrum> radial;
  std::optional<PairCorrelation> pcf;
};

/// Measures the sets (at least one, all in `domain`). Fills `curves`, if
/// given, with what the summaries were taken from. Throws InvalidArgument for
/// no sets, a point outside the domain, a radius outside [kMinRadius,
/// kMaxRadius] (pds/limits.h), or options the measures reject (analysis/spectrum.h,
/// analysis/pair_correlation.h).
template <int D>
AnalysisReport analyze(std::span<const PointSet<D>> sets, const Domain<D>& domain, const AnalysisOptions& options = {},
                       AnalysisCurves* curves = nullptr);

/// The same for sets whose dimension is known at run time, any dim >= 1, in
/// the box [lo, hi) or the torus over it. From 1 to kMaxDim this is
/// analyze<D>; past it the report holds the count, the minimum and mean
/// nearest-neighbour distances and the discrepancies (relative radius NaN,
/// maximality not checked, no spectrum or PCF, each with a note saying so).
AnalysisReport analyze(std::span<const PointCloud> sets, std::span<const double> lo, std::span<const double> hi,
                       bool periodic, const AnalysisOptions& options = {});

/// The same for one set.
template <int D>
AnalysisReport analyze(const PointSet<D>& points, const Domain<D>& domain, const AnalysisOptions& options = {}) {
  return analyze<D>(std::span<const PointSet<D>>(&points, 1), domain, options);
}

}  // namespace pds
