// PNG output through Cairo's image surfaces (see include/pds/render/png.h).

#include "pds/render/png.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <istream>
#include <iterator>
#include <memory>
#include <string>

#include "pds/error.h"

namespace pds {

namespace {

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using Context = std::unique_ptr<cairo_t, ContextDeleter>;

std::uint8_t level(double v, const GreyMapping& m) {
  const double t = (v - m.lo) / (m.hi - m.lo);
  if (!(t > 0)) return 0;  // also NaN
  if (t >= 1) return 255;
  return static_cast<std::uint8_t>(std::lround(t * 255.0));
}

Surface make_surface(int width, int height) {
  Surface s(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height));
  if (cairo_surface_status(s.get()) != CAIRO_STATUS_SUCCESS)
    throw Failure("png: cannot create a " + std::to_string(width) + "x" + std::to_string(height) + " image");
  return s;
}

// Copies the image into the surface at (ox, oy).
void blit(cairo_surface_t* surface, const Image& image, int ox, int oy, GreyMapping mapping) {
  cairo_surface_flush(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < image.height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::size_t>(oy + y) * stride) + ox;
    for (int x = 0; x < image.width; ++x) {
      const std::uint32_t g = level(image.at(x, y), mapping);
      row[x] = 0xff000000u | (g << 16) | (g << 8) | g;
    }
  }
  cairo_surface_mark_dirty(surface);
}

void save(cairo_surface_t* surface, const std::string& path) {
  const cairo_status_t status = cairo_surface_write_to_png(surface, path.c_str());
  if (status != CAIRO_STATUS_SUCCESS) throw Failure("cannot write " + path + ": " + cairo_status_to_string(status));
}

}  // namespace

void write_png(const std::string& path, const Image& image, GreyMapping mapping) {
  if (image.width < 1 || image.height < 1) throw InvalidArgument("png: cannot write an empty image to " + path);
  if (!(mapping.hi > mapping.lo)) throw InvalidArgument("png: grey mapping needs hi > lo");
  Surface surface = make_surface(image.width, image.height);
  blit(surface.get(), image, 0, 0, mapping);
  save(surface.get(), path);
}

namespace {

// Cairo's reader takes bytes through a callback; this one serves a buffer.
struct PngBytes {
  const std::string* bytes;
  std::size_t at = 0;
};

cairo_status_t serve(void* closure, unsigned char* data, unsigned int length) {
  auto* in = static_cast<PngBytes*>(closure);
  if (in->bytes->size() - in->at < length) return CAIRO_STATUS_READ_ERROR;
  std::copy_n(in->bytes->data() + in->at, length, data);
  in->at += length;
  return CAIRO_STATUS_SUCCESS;
}

// The size the header declares, checked before Cairo allocates for it: a
// few hundred bytes of PNG can declare 2^31 x 2^31 pixels.
void check_header(const std::string& bytes, const std::string& name) {
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() < 24 || !std::equal(signature, signature + 8, b) || bytes.compare(12, 4, "IHDR") != 0)
    throw InvalidArgument("cannot read " + name + " as PNG: no PNG signature and header");
  const auto be32 = [&](std::size_t i) {
    return std::uint32_t{b[i]} << 24 | std::uint32_t{b[i + 1]} << 16 | std::uint32_t{b[i + 2]} << 8 | b[i + 3];
  };
  const std::uint64_t width = be32(16), height = be32(20);
  if (width == 0 || height == 0 || width > kMaxReadSide || height > kMaxReadSide || width * height > kMaxReadPixels)
    throw InvalidArgument("cannot read " + name + " as PNG: " + std::to_string(width) + "x" + std::to_string(height) +
                          " pixels, more than " + std::to_string(kMaxReadSide) + " a side or " +
                          std::to_string(kMaxReadPixels) + " in all");
}

}  // namespace

Image read_png(std::istream& in, const std::string& name) {
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  check_header(bytes, name);
  PngBytes source{&bytes};
  Surface s(cairo_image_surface_create_from_png_stream(serve, &source));
  if (cairo_surface_status(s.get()) != CAIRO_STATUS_SUCCESS)
    throw InvalidArgument("cannot read " + name + " as PNG: " + cairo_status_to_string(cairo_surface_status(s.get())));
  Surface rgb = make_surface(cairo_image_surface_get_width(s.get()), cairo_image_surface_get_height(s.get()));
  {
    Context cr(cairo_create(rgb.get()));
    cairo_set_source_surface(cr.get(), s.get(), 0, 0);
    cairo_paint(cr.get());
  }
  cairo_surface_flush(rgb.get());
  Image image(cairo_image_surface_get_width(rgb.get()), cairo_image_surface_get_height(rgb.get()));
  const unsigned char* data = cairo_image_surface_get_data(rgb.get());
  const int stride = cairo_image_surface_get_stride(rgb.get());
  for (int y = 0; y < image.height; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::size_t>(y) * stride);
    for (int x = 0; x < image.width; ++x) image.at(x, y) = ((row[x] >> 8) & 0xff) / 255.0;
  }
  return image;
}

Image read_png(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidArgument("cannot read " + path + " as PNG: cannot open the file");
  return read_png(in, path);
}

Image log_spectrum(const Image& spectrum) {
  Image out(spectrum.width, spectrum.height);
  std::vector<double> logs;
  logs.reserve(spectrum.pixels.size());
  const double floor_value = 1e-300;
  for (std::size_t i = 0; i < spectrum.pixels.size(); ++i) {
    out.pixels[i] = std::log10(std::max(spectrum.pixels[i], floor_value));
    if (i != static_cast<std::size_t>(spectrum.height / 2) * spectrum.width + spectrum.width / 2)
      logs.push_back(out.pixels[i]);
  }
  if (logs.empty()) return out;
  auto quantile = [&](double q) {
    auto it = logs.begin() + static_cast<std::ptrdiff_t>(q * (logs.size() - 1));
    std::nth_element(logs.begin(), it, logs.end());
    return *it;
  };
  const double lo = quantile(0.01), hi = quantile(0.999);
  for (double& v : out.pixels) v = hi > lo ? (v - lo) / (hi - lo) : 0.5;
  return out;
}

void write_sheet(const std::string& path, const std::vector<SheetPanel>& panels, int columns,
                 const std::string& title) {
  if (panels.empty()) throw InvalidArgument("sheet: no panels");
  if (columns < 1) throw InvalidArgument("sheet: columns must be at least 1, got " + std::to_string(columns));
  int pw = 0, ph = 0;
  for (const auto& p : panels) {
    pw = std::max(pw, p.image.width);
    ph = std::max(ph, p.image.height);
  }
  const int gap = 8, label = 22, header = title.empty() ? 0 : 28;
  const int rows = (static_cast<int>(panels.size()) + columns - 1) / columns;
  const int cols = std::min<int>(columns, static_cast<int>(panels.size()));
  const int width = gap + cols * (pw + gap), height = header + gap + rows * (ph + label + gap);
  Surface surface = make_surface(width, height);
  {
    Context cr(cairo_create(surface.get()));
    cairo_set_source_rgb(cr.get(), 1, 1, 1);
    cairo_paint(cr.get());
  }
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const int col = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
    blit(surface.get(), panels[i].image, gap + col * (pw + gap), header + gap + row * (ph + label + gap), {});
  }
  Context cr(cairo_create(surface.get()));
  cairo_select_font_face(cr.get(), "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_source_rgb(cr.get(), 0, 0, 0);
  cairo_set_font_size(cr.get(), 13);
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const int col = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
    cairo_move_to(cr.get(), gap + col * (pw + gap) + 2, header + gap + row * (ph + label + gap) + ph + 16);
    cairo_show_text(cr.get(), panels[i].label.c_str());
  }
  if (!title.empty()) {
    cairo_set_font_size(cr.get(), 16);
    cairo_move_to(cr.get(), gap, 20);
    cairo_show_text(cr.get(), title.c_str());
  }
  cr.reset();
  save(surface.get(), path);
}

}  // namespace pds
