#pragma once
// Pixel reconstruction filters. Each is separable, w(dx, dy) = f(dx) f(dy),
// with dx, dy the offsets from the pixel centre to the sample in pixels, and
// zero when |dx| or |dy| reaches its radius. The renderer divides the
// weighted sum of a pixel's samples by the sum of their weights, so a filter
// needs no normalisation.
//
//  box       radius 0.5  f = 1 on (-0.5, 0.5]: each sample counts for exactly
//                        the pixel it falls in (the half-open side keeps that
//                        true on pixel edges)
//  tent      radius 1    f = 1 - |d|
//  gaussian  radius 1.5  f = exp(-d^2 / (2 sigma^2)) - exp(-r^2 / (2 sigma^2)),
//                        sigma 0.5 (pbrt's defaults)
//  mitchell  radius 2    Mitchell & Netravali (1988) cubic with B = C = 1/3,
//                        over |d| in [0, 2); negative lobes at 1 < |d| < 2

#include <string>
#include <vector>

namespace pds {

enum class FilterKind { Box, Tent, Gaussian, Mitchell };

struct Filter {
  FilterKind kind = FilterKind::Gaussian;

  double radius() const;
  /// f(d): the 1D weight at offset d (pixel centre minus sample position).
  double weight(double d) const;
  /// weight(d0 + k) for k = 0 .. n-1, what a renderer needs for one sample and
  /// a row of pixels; the Gaussian's exponentials by a recurrence (two exp()
  /// calls instead of n), equal to weight() within a few ulps.
  void weights(double d0, int n, double* out) const;
};

/// Names for parse_filter: "box", "tent", "gaussian", "mitchell".
std::vector<std::string> filter_names();
/// The filter called `name`; throws InvalidArgument naming the known ones.
Filter parse_filter(const std::string& name);
std::string filter_name(const Filter& filter);

}  // namespace pds
