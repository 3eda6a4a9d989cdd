// Reconstruction filters (see include/pds/render/filter.h). The Mitchell-
// Netravali cubic: D. P. Mitchell and A. N. Netravali, "Reconstruction filters
// in computer graphics", SIGGRAPH 1988.

#include "pds/render/filter.h"

#include <cmath>

#include "pds/error.h"

namespace pds {

namespace {
constexpr double kGaussianSigma = 0.5;
constexpr double kMitchellB = 1.0 / 3.0, kMitchellC = 1.0 / 3.0;

double mitchell(double d) {
  const double x = std::abs(d), x2 = x * x, x3 = x2 * x;
  constexpr double B = kMitchellB, C = kMitchellC;
  if (x < 1.0) return ((12 - 9 * B - 6 * C) * x3 + (-18 + 12 * B + 6 * C) * x2 + (6 - 2 * B)) / 6.0;
  if (x < 2.0) return ((-B - 6 * C) * x3 + (6 * B + 30 * C) * x2 + (-12 * B - 48 * C) * x + (8 * B + 24 * C)) / 6.0;
  return 0.0;
}
}  // namespace

double Filter::radius() const {
  switch (kind) {
    case FilterKind::Box:
      return 0.5;
    case FilterKind::Tent:
      return 1.0;
    case FilterKind::Gaussian:
      return 1.5;
    case FilterKind::Mitchell:
      return 2.0;
  }
  return 0.0;
}

double Filter::weight(double d) const {
  switch (kind) {
    case FilterKind::Box:
      return d > -0.5 && d <= 0.5 ? 1.0 : 0.0;
    case FilterKind::Tent:
      return std::max(0.0, 1.0 - std::abs(d));
    case FilterKind::Gaussian: {
      const double r = radius();
      if (std::abs(d) >= r) return 0.0;
      const double s2 = 2.0 * kGaussianSigma * kGaussianSigma;
      return std::exp(-d * d / s2) - std::exp(-r * r / s2);
    }
    case FilterKind::Mitchell:
      return mitchell(d);
  }
  return 0.0;
}

void Filter::weights(double d0, int n, double* out) const {
  if (kind != FilterKind::Gaussian) {
    for (int k = 0; k < n; ++k) out[k] = weight(d0 + k);
    return;
  }
  // exp(-a (d + 1)^2) = exp(-a d^2) * exp(-a (2d + 1)), and the second factor
  // shrinks by exp(-2a) per step.
  const double r = radius(), a = 1.0 / (2.0 * kGaussianSigma * kGaussianSigma);
  const double edge = std::exp(-a * r * r), step = std::exp(-2.0 * a);
  double e = std::exp(-a * d0 * d0), m = std::exp(-a * (2.0 * d0 + 1.0));
  for (int k = 0; k < n; ++k) {
    const double d = d0 + k;
    out[k] = std::abs(d) < r ? e - edge : 0.0;
    e *= m;
    m *= step;
  }
}

std::vector<std::string> filter_names() { return {"box", "tent", "gaussian", "mitchell"}; }

Filter parse_filter(const std::string& name) {
  if (name == "box") return {FilterKind::Box};
  if (name == "tent") return {FilterKind::Tent};
  if (name == "gaussian") return {FilterKind::Gaussian};
  if (name == "mitchell") return {FilterKind::Mitchell};
  throw InvalidArgument("unknown filter '" + name + "' (known: box, tent, gaussian, mitchell)");
}

std::string filter_name(const Filter& filter) {
  switch (filter.kind) {
    case FilterKind::Box:
      return "box";
    case FilterKind::Tent:
      return "tent";
    case FilterKind::Gaussian:
      return "gaussian";
    case FilterKind::Mitchell:
      return "mitchell";
  }
  return "?";
}

}  // namespace pds
