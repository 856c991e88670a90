// PNG encoding with libpng: see png.hpp.
#include <hsx/io/png.hpp>

#include <png.h>

#include <csetjmp>
#include <stdexcept>

namespace hsx {

RgbImage::RgbImage(int w, int h, std::uint8_t red, std::uint8_t green, std::uint8_t blue) : width(w), height(h) {
  if (w < 1 || h < 1 || static_cast<long long>(w) * h > (1LL << 28))
    throw std::invalid_argument("RgbImage: sides must be at least 1 and the image at most 2^28 pixels");
  pixels.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
  for (std::size_t k = 0; k < pixels.size(); k += 3) {
    pixels[k] = red;
    pixels[k + 1] = green;
    pixels[k + 2] = blue;
  }
}

namespace {

/// Where libpng's output goes, and whether appending to it failed (an exception must not cross libpng's C code).
struct Sink {
  std::string* bytes;
  bool failed = false;
};

void write_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* sink = static_cast<Sink*>(png_get_io_ptr(png));
  try {
    sink->bytes->append(reinterpret_cast<const char*>(data), length);
  } catch (...) {
    sink->failed = true;
    png_error(png, "out of memory");
  }
}

void flush_nothing(png_structp) {}

/// libpng's error path: longjmp back to encode (set up by png_jmpbuf), so nothing but plain data lives in its frame.
bool encode(png_structp png, png_infop info, const RgbImage& image, png_bytep* rows, Sink* sink) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, sink, write_bytes, flush_nothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

std::string png_bytes(const RgbImage& image) {
  if (image.width < 1 || image.height < 1 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3)
    throw std::invalid_argument("png_bytes: the pixels do not make a width x height RGB image");
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y)
    rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(image.at(0, y));  // libpng reads them only
  std::string bytes;
  Sink sink{&bytes};
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) throw std::runtime_error("png_bytes: libpng could not start");
  png_infop info = png_create_info_struct(png);
  const bool done = info && encode(png, info, image, rows.data(), &sink);
  png_destroy_write_struct(&png, info ? &info : nullptr);
  if (!done) throw std::runtime_error(sink.failed ? "png_bytes: out of memory" : "png_bytes: libpng failed");
  return bytes;
}

}  // namespace hsx
