// PNG output of raster pictures (io/svg3.hpp's raster views): an 8-bit RGB image encoded with libpng.
//
// Conventions (owned here): rows top to bottom, pixels left to right, three bytes (red, green, blue) each. The
// encoding is deterministic: no time or text chunk, no interlacing, libpng's default filters and compression
// level, so one image gives the same bytes on every run with one libpng and zlib.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace hsx {

/// An 8-bit RGB image (see the conventions).
struct RgbImage {
  int width = 0;                    ///< in pixels, >= 1
  int height = 0;                   ///< in pixels, >= 1
  std::vector<std::uint8_t> pixels; ///< width * height * 3 bytes, row by row from the top

  /// A width x height image filled with one colour. Throws std::invalid_argument when a side is below 1 or the
  /// image would exceed 2^28 pixels.
  RgbImage(int width, int height, std::uint8_t red = 255, std::uint8_t green = 255, std::uint8_t blue = 255);
  RgbImage() = default;
  /// The first of pixel (x, y)'s three bytes; (x, y) must be inside the image.
  std::uint8_t* at(int x, int y) { return pixels.data() + 3 * (static_cast<std::size_t>(y) * width + x); }
  const std::uint8_t* at(int x, int y) const { return pixels.data() + 3 * (static_cast<std::size_t>(y) * width + x); }
};

/// `image` as a PNG file's bytes. Throws std::invalid_argument when `pixels` does not hold width * height * 3
/// bytes or a side is below 1, std::runtime_error when libpng fails.
std::string png_bytes(const RgbImage& image);

}  // namespace hsx
