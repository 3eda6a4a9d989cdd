#pragma once
// PNG pictures of grey images, through Cairo (its PNG writer is libpng).

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "pds/render/render.h"

namespace pds {

/// How grey values map to 8-bit levels: `lo` to 0 and `hi` to 255, clamped.
struct GreyMapping {
  double lo = 0.0, hi = 1.0;
};

/// Writes the image as an RGB PNG with equal channels. Throws Failure when the
/// file cannot be written.
void write_png(const std::string& path, const Image& image, GreyMapping mapping = {});

/// The largest PNG read_png accepts: 32767 pixels a side (Cairo's own
/// limit) and 2^26 pixels in all (half a GiB of grey levels as doubles).
inline constexpr std::uint64_t kMaxReadSide = 32767, kMaxReadPixels = std::uint64_t{1} << 26;

/// Reads a PNG (any format Cairo reads) as grey levels in [0, 1] from its
/// green channel. Throws InvalidArgument when the file is missing, not a PNG,
/// damaged, or larger than the limits above (checked from its header before
/// any pixel is decoded). The stream form names the input `name` in errors.
Image read_png(const std::string& path);
Image read_png(std::istream& in, const std::string& name);

/// Spectra span many decades: log10(power), mapped from its 1st to its 99.9th
/// percentile (frequency 0 excluded) to black..white.
Image log_spectrum(const Image& spectrum);

/// One labelled panel of a comparison sheet.
struct SheetPanel {
  Image image;
  std::string label;
};

/// Panels laid out `columns` to a row, each with its label in a strip
/// underneath; a title across the top when not empty.
void write_sheet(const std::string& path, const std::vector<SheetPanel>& panels, int columns,
                 const std::string& title = "");

}  // namespace pds
