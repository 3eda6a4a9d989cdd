#pragma once
// Pictures of point sets and of their analysis, drawn with Cairo. Every
// function writes PNG, SVG or PDF, chosen by the file's extension, through
// the same drawing code (a Cairo image, SVG or PDF surface). Sizes are in
// pixels for PNG and in points (1/72 inch) for SVG and PDF.
//
// Scales. The periodogram image puts DC at the centre and frequency +k_y at
// the top; its grey level is 10 log10 P mapped linearly from -20 dB (black)
// to +10 dB (white) on the log scale, or P from 0 (black) to 2 (white) on
// the linear scale, so white noise (P = 1) is mid-grey on the linear scale
// and a light grey (0 dB) on the log one. The radial plots draw the white
// noise reference (power 1, anisotropy 10 log10(1/M) dB) as a dashed line;
// frequency is in units of 1 / mean inter-point distance and the PCF's r in
// mean inter-point distances, as in spectrum.h and pair_correlation.h.

#include <span>
#include <string>
#include <vector>

#include "pds/analysis/pair_correlation.h"
#include "pds/analysis/spectrum.h"
#include "pds/domain.h"
#include "pds/point.h"

namespace pds {

enum class ImageFormat { Png, Svg, Pdf };

/// The format for a file name ending in .png, .svg or .pdf (any case);
/// throws InvalidArgument for anything else.
ImageFormat image_format_for(const std::string& path);

struct PointPlotOptions {
  int size = 800;                 // longer side of the picture, 64..8192
  double disk_radius = 0;         // > 0: also draw a disk of this radius (domain units) around each point
  double dot_radius = 0;          // > 0: dots of this radius (domain units), as stipplings draw them; 0: automatic
  std::vector<double> dot_radii;  // one a point (domain units, > 0), e.g. by class; empty: dot_radius
  std::string title;              // drawn above the points when not empty
};

/// The points of a 2D set as dots in the domain's frame (y up).
void plot_points(const PointSet<2>& points, const Domain<2>& domain, const std::string& path,
                 const PointPlotOptions& options = {});

enum class SpectrumScale { Log, Linear };

struct SpectrumPlotOptions {
  SpectrumScale scale = SpectrumScale::Log;
  int size = 0;  // picture side; 0: the frequency grid side times the smallest integer making it >= 512
};

/// The 2D averaged periodogram as a grey-level image, DC at the centre.
void plot_spectrum(const Periodogram& periodogram, const std::string& path, const SpectrumPlotOptions& options = {});

struct ChartOptions {
  int width = 800, height = 600;
  std::string title;
};

/// Radial power (top) and anisotropy in dB (bottom) against frequency.
void plot_radial(const RadialSpectrum& radial, const std::string& path, const ChartOptions& options = {});

/// g(r) against r in mean inter-point distances.
void plot_pair_correlation(const PairCorrelation& pcf, const std::string& path, const ChartOptions& options = {});

/// One row of a comparison sheet: a method's points and their spectrum.
struct ComparisonRow {
  std::string name;
  PointSet<2> points;  // one realisation, drawn as the spatial view
  Domain<2> domain;
  Periodogram spectrum;  // averaged over the realisations
  RadialSpectrum radial;
};

/// The comparison of Lagae & Dutre (2008), Fig. 4 style: for each row the spatial view beside the Fourier
/// view (periodogram image and radial power), one row per method, one sheet.
void plot_comparison(std::span<const ComparisonRow> rows, const std::string& path, int panel_size = 320);

}  // namespace pds
