// Pictures with Cairo. Each picture is drawn by panel functions that paint
// into a rectangle of a cairo_t, whatever surface is behind it, so PNG, SVG
// and PDF share one code path and the comparison sheet reuses the panels of
// the single pictures. Scales and units are documented in plot.h.

#include "pds/io/plot.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

#include "pds/error.h"

namespace pds {
namespace {

struct Rect {
  double x, y, w, h;
};

/// A surface of the format of `path`; finish() writes it and reports failure.
class Canvas {
 public:
  Canvas(const std::string& path, int width, int height) : path_(path), format_(image_format_for(path)) {
    if (width < 16 || height < 16 || width > 16384 || height > 16384)
      throw InvalidArgument("picture size must be within 16..16384, got " + std::to_string(width) + " x " +
                            std::to_string(height));
    switch (format_) {
      case ImageFormat::Png:
        surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
        break;
      case ImageFormat::Svg:
        surface_ = cairo_svg_surface_create(path.c_str(), width, height);
        break;
      case ImageFormat::Pdf:
        surface_ = cairo_pdf_surface_create(path.c_str(), width, height);
        break;
    }
    if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
      const cairo_status_t status = cairo_surface_status(surface_);
      cairo_surface_destroy(surface_);
      check(status);
    }
    cr_ = cairo_create(surface_);
    cairo_set_source_rgb(cr_, 1, 1, 1);
    cairo_paint(cr_);
  }
  ~Canvas() {
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
  }
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  cairo_t* cr() const { return cr_; }

  void finish() {
    check(cairo_status(cr_));
    if (format_ == ImageFormat::Png) check(cairo_surface_write_to_png(surface_, path_.c_str()));
    cairo_surface_finish(surface_);
    check(cairo_surface_status(surface_));
  }

 private:
  void check(cairo_status_t status) const {
    if (status != CAIRO_STATUS_SUCCESS)
      throw Failure("cannot write picture '" + path_ + "': " + cairo_status_to_string(status));
  }
  std::string path_;
  ImageFormat format_;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

void text(cairo_t* cr, const std::string& s, double x, double y, double size, double align_x = 0.0,
          double align_y = 0.0, bool bold = false) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  cairo_move_to(cr, x - align_x * e.width - e.x_bearing, y + align_y * size);
  cairo_show_text(cr, s.c_str());
}

void vertical_text(cairo_t* cr, const std::string& s, double x, double y, double size) {
  cairo_save(cr);
  cairo_translate(cr, x, y);
  cairo_rotate(cr, -M_PI / 2);
  text(cr, s, 0, 0, size, 0.5, 0.0);
  cairo_restore(cr);
}

std::string format_tick(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

/// A step of 1, 2 or 5 times a power of ten giving about `target` ticks.
double nice_step(double range, int target) {
  const double raw = range / target;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) return m * p;
  return 10.0 * p;
}

struct Series {
  std::vector<double> x, y;
  double r, g, b;
  bool dashed = false;
};

/// A line chart with labelled axes in `area` (which includes the margins).
void chart(cairo_t* cr, Rect area, double x0, double x1, double y0, double y1, const std::vector<Series>& series,
           const std::string& x_label, const std::string& y_label, const std::string& title) {
  const double font = std::clamp(std::min(area.h, area.w) * 0.04, 9.0, 16.0);
  const Rect plot{area.x + 4.2 * font, area.y + (title.empty() ? 1.0 : 2.2) * font, area.w - 5.2 * font,
                  area.h - (title.empty() ? 4.0 : 5.2) * font};
  auto px = [&](double x) { return plot.x + (x - x0) / (x1 - x0) * plot.w; };
  auto py = [&](double y) { return plot.y + plot.h - (y - y0) / (y1 - y0) * plot.h; };
  cairo_set_source_rgb(cr, 0, 0, 0);
  if (!title.empty()) text(cr, title, plot.x + plot.w / 2, area.y + 1.3 * font, font, 0.5, 0.0, true);
  // Grid and ticks.
  cairo_set_line_width(cr, 1.0);
  const double sx = nice_step(x1 - x0, 6), sy = nice_step(y1 - y0, 5);
  for (double t = std::ceil(x0 / sx) * sx; t <= x1 + 1e-9 * sx; t += sx) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, px(t), plot.y);
    cairo_line_to(cr, px(t), plot.y + plot.h);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    text(cr, format_tick(t), px(t), plot.y + plot.h + 1.2 * font, 0.85 * font, 0.5);
  }
  for (double t = std::ceil(y0 / sy) * sy; t <= y1 + 1e-9 * sy; t += sy) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, plot.x, py(t));
    cairo_line_to(cr, plot.x + plot.w, py(t));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    text(cr, format_tick(t), plot.x - 0.4 * font, py(t), 0.85 * font, 1.0, 0.35);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_rectangle(cr, plot.x, plot.y, plot.w, plot.h);
  cairo_stroke(cr);
  text(cr, x_label, plot.x + plot.w / 2, plot.y + plot.h + 2.6 * font, font, 0.5);
  vertical_text(cr, y_label, area.x + 1.2 * font, plot.y + plot.h / 2, font);
  // Curves, clipped to the plot.
  cairo_save(cr);
  cairo_rectangle(cr, plot.x, plot.y, plot.w, plot.h);
  cairo_clip(cr);
  for (const Series& s : series) {
    cairo_set_source_rgb(cr, s.r, s.g, s.b);
    cairo_set_line_width(cr, s.dashed ? 1.2 : 1.6);
    const double dash[] = {6.0, 4.0};
    cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0);
    bool started = false;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.y[i])) {
        started = false;
        continue;
      }
      const double y = std::clamp(s.y[i], y0 - (y1 - y0), y1 + (y1 - y0));
      if (started)
        cairo_line_to(cr, px(s.x[i]), py(y));
      else
        cairo_move_to(cr, px(s.x[i]), py(y));
      started = true;
    }
    cairo_stroke(cr);
  }
  cairo_set_dash(cr, nullptr, 0, 0);
  cairo_restore(cr);
}

void points_panel(cairo_t* cr, Rect area, const PointSet<2>& points, const Domain<2>& domain, double disk_radius,
                  double dot_radius = 0, const std::vector<double>& dot_radii = {}) {
  const double scale = std::min(area.w / domain.extent(0), area.h / domain.extent(1));
  const double w = domain.extent(0) * scale, h = domain.extent(1) * scale;
  const double ox = area.x + (area.w - w) / 2, oy = area.y + (area.h - h) / 2;
  auto px = [&](double x) { return ox + (x - domain.lo[0]) * scale; };
  auto py = [&](double y) { return oy + h - (y - domain.lo[1]) * scale; };
  cairo_save(cr);
  cairo_rectangle(cr, ox, oy, w, h);
  cairo_clip(cr);
  if (disk_radius > 0) {
    cairo_set_source_rgba(cr, 0.2, 0.45, 0.85, 0.25);
    for (const auto& p : points) {
      cairo_new_sub_path(cr);
      cairo_arc(cr, px(p[0]), py(p[1]), disk_radius * scale, 0, 2 * M_PI);
    }
    cairo_fill(cr);
  }
  // Dots about a tenth of the mean spacing, readable from 100 to 100k points.
  const double spacing = points.empty() ? 0.0 : std::sqrt(w * h / static_cast<double>(points.size()));
  const double dot = dot_radius > 0 ? dot_radius * scale : std::clamp(0.12 * spacing, 0.5, 4.0);
  cairo_set_source_rgb(cr, 0, 0, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    cairo_new_sub_path(cr);
    cairo_arc(cr, px(p[0]), py(p[1]), dot_radii.empty() ? dot : dot_radii[i] * scale, 0, 2 * M_PI);
  }
  cairo_fill(cr);
  cairo_restore(cr);
  cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, ox, oy, w, h);
  cairo_stroke(cr);
}

void spectrum_panel(cairo_t* cr, Rect area, const Periodogram& p, SpectrumScale scale) {
  if (p.dim != 2) throw InvalidArgument("spectrum picture: needs a 2D periodogram, got " + std::to_string(p.dim) + "D");
  const int side = p.side(), K = p.max_frequency;
  cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_RGB24, side, side);
  cairo_surface_flush(image);
  unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  for (int row = 0; row < side; ++row) {
    const int ky = K - row;  // +k_y at the top
    auto* line = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(row) * stride);
    for (int col = 0; col < side; ++col) {
      const double v = p.at(col - K, ky);
      const double t = scale == SpectrumScale::Log ? (10.0 * std::log10(std::max(v, 1e-30)) + 20.0) / 30.0 : v / 2.0;
      const auto g = static_cast<std::uint32_t>(std::lround(255.0 * std::clamp(t, 0.0, 1.0)));
      line[col] = (g << 16) | (g << 8) | g;
    }
  }
  cairo_surface_mark_dirty(image);
  const double s = std::min(area.w, area.h) / side;
  cairo_save(cr);
  cairo_translate(cr, area.x + (area.w - s * side) / 2, area.y + (area.h - s * side) / 2);
  cairo_scale(cr, s, s);
  cairo_set_source_surface(cr, image, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
  cairo_rectangle(cr, 0, 0, side, side);
  cairo_fill(cr);
  cairo_restore(cr);
  cairo_surface_destroy(image);
}

double top_of(const std::vector<double>& y, double floor_value, double cap) {
  double top = floor_value;
  for (double v : y)
    if (std::isfinite(v)) top = std::max(top, v);
  return std::min(1.1 * top, cap);
}

double range_end(const std::vector<double>& x) { return x.empty() ? 1.0 : x.back(); }

void radial_power_panel(cairo_t* cr, Rect area, const RadialSpectrum& r, const std::string& title,
                        const std::string& x_label = "frequency (1 / mean inter-point distance)") {
  const double x1 = range_end(r.frequency);
  chart(cr, area, 0, x1, 0, top_of(r.power, 2.0, 8.0),
        {{{0, x1}, {1, 1}, 0.5, 0.5, 0.5, true}, {r.frequency, r.power, 0.1, 0.2, 0.7}}, x_label, "radial power",
        title);
}

void anisotropy_panel(cairo_t* cr, Rect area, const RadialSpectrum& r) {
  const double x1 = range_end(r.frequency);
  const double white = 10.0 * std::log10(1.0 / std::max<std::size_t>(r.sets, 1));
  chart(cr, area, 0, x1, std::min(-20.0, white - 5.0), 10,
        {{{0, x1}, {white, white}, 0.5, 0.5, 0.5, true}, {r.frequency, r.anisotropy_db, 0.7, 0.15, 0.1}},
        "frequency (1 / mean inter-point distance)", "anisotropy (dB)", "");
}

int checked_size(int size, const char* what) {
  if (size < 64 || size > 8192)
    throw InvalidArgument(std::string(what) + ": size must be in [64, 8192], got " + std::to_string(size));
  return size;
}

}  // namespace

ImageFormat image_format_for(const std::string& path) {
  const auto dot = path.rfind('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "png") return ImageFormat::Png;
  if (ext == "svg") return ImageFormat::Svg;
  if (ext == "pdf") return ImageFormat::Pdf;
  throw InvalidArgument("picture '" + path + "': the name must end in .png, .svg or .pdf");
}

void plot_points(const PointSet<2>& points, const Domain<2>& domain, const std::string& path,
                 const PointPlotOptions& options) {
  domain.validate();
  const int size = checked_size(options.size, "point picture");
  const double aspect = domain.extent(1) / domain.extent(0);
  const int width = aspect <= 1 ? size : std::max(16, static_cast<int>(std::lround(size / aspect)));
  const int height = aspect <= 1 ? std::max(16, static_cast<int>(std::lround(size * aspect))) : size;
  const double title_height = options.title.empty() ? 0 : 28;
  const double margin = 8;
  Canvas canvas(path, width + 2 * static_cast<int>(margin),
                height + 2 * static_cast<int>(margin) + static_cast<int>(title_height));
  if (!options.title.empty()) {
    cairo_set_source_rgb(canvas.cr(), 0, 0, 0);
    text(canvas.cr(), options.title, margin + width / 2.0, margin + 18, 16, 0.5, 0.0, true);
  }
  if (!options.dot_radii.empty() && options.dot_radii.size() != points.size())
    throw InvalidArgument("point picture: " + std::to_string(options.dot_radii.size()) + " dot radii for " +
                          std::to_string(points.size()) + " points");
  points_panel(canvas.cr(), {margin, margin + title_height, double(width), double(height)}, points, domain,
               options.disk_radius, options.dot_radius, options.dot_radii);
  canvas.finish();
}

void plot_spectrum(const Periodogram& periodogram, const std::string& path, const SpectrumPlotOptions& options) {
  const int side = periodogram.side();
  const int size = options.size > 0 ? checked_size(options.size, "spectrum picture") : side * ((511 + side) / side);
  Canvas canvas(path, size, size);
  spectrum_panel(canvas.cr(), {0, 0, double(size), double(size)}, periodogram, options.scale);
  canvas.finish();
}

void plot_radial(const RadialSpectrum& radial, const std::string& path, const ChartOptions& options) {
  Canvas canvas(path, options.width, options.height);
  const double w = options.width, h = options.height;
  radial_power_panel(canvas.cr(), {0, 0, w, h / 2}, radial, options.title);
  anisotropy_panel(canvas.cr(), {0, h / 2, w, h / 2}, radial);
  canvas.finish();
}

void plot_pair_correlation(const PairCorrelation& pcf, const std::string& path, const ChartOptions& options) {
  Canvas canvas(path, options.width, options.height);
  std::vector<double> x(pcf.r.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = pcf.r[i] / pcf.mean_spacing;
  const double x1 = range_end(x);
  chart(canvas.cr(), {0, 0, double(options.width), double(options.height)}, 0, x1, 0, top_of(pcf.g, 2.0, 6.0),
        {{{0, x1}, {1, 1}, 0.5, 0.5, 0.5, true}, {x, pcf.g, 0.1, 0.2, 0.7}}, "r (mean inter-point distances)", "g(r)",
        options.title);
  canvas.finish();
}

void plot_comparison(std::span<const ComparisonRow> rows, const std::string& path, int panel_size) {
  if (rows.empty()) throw InvalidArgument("comparison sheet: no methods given");
  const double p = checked_size(panel_size, "comparison sheet");
  const double gap = 12, label = 28, header = 30;
  const double width = 3 * p + 4 * gap;
  const double height = header + rows.size() * (label + p + gap);
  Canvas canvas(path, static_cast<int>(width), static_cast<int>(height));
  cairo_t* cr = canvas.cr();
  cairo_set_source_rgb(cr, 0, 0, 0);
  const char* headers[] = {"spatial domain", "Fourier domain (periodogram)", "radial power"};
  for (int c = 0; c < 3; ++c) text(cr, headers[c], gap + c * (p + gap) + p / 2, 20, 15, 0.5, 0.0, true);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ComparisonRow& row = rows[i];
    const double y = header + i * (label + p + gap);
    cairo_set_source_rgb(cr, 0, 0, 0);
    char caption[160];
    std::snprintf(caption, sizeof caption, "%s: %zu points, %zu set%s", row.name.c_str(), row.points.size(),
                  row.spectrum.sets, row.spectrum.sets == 1 ? "" : "s");
    text(cr, caption, gap, y + 19, 14, 0.0, 0.0, true);
    points_panel(cr, {gap, y + label, p, p}, row.points, row.domain, 0);
    spectrum_panel(cr, {2 * gap + p, y + label, p, p}, row.spectrum, SpectrumScale::Log);
    radial_power_panel(cr, {3 * gap + 2 * p, y + label, p, p}, row.radial, "", "frequency (1 / mean spacing)");
  }
  canvas.finish();
}

}  // namespace pds
