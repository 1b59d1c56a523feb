#include "render/png_image.h"

#include <png.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace plywood::render {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

}  // namespace

void WritePng(const RgbImage& image, const std::filesystem::path& path) {
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "wb"));
  if (!file) throw std::runtime_error(path.string() + ": cannot open for writing");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error(path.string() + ": PNG encoding failed");
  }
  png_init_io(png, file.get());
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // Every row "Up"-filtered and zlib at level 3: libpng's default (each row tried with all five
  // filters, zlib level 6) cost 272M instructions for the default run's 1024 x 653 snapshot,
  // this 60M, for a file of 44 kB instead of 30 kB. PNG is lossless either way: the decoded pixels
  // are the same (docs/performance.md, fourth round; png_image_test).
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_compression_level(png, 3);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, const_cast<png_bytep>(image.At(0, y)));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
}

RgbImage ReadPng(const std::filesystem::path& path) {
  png_image decoded{};
  decoded.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&decoded, path.c_str())) {
    throw std::runtime_error(path.string() + ": not a readable PNG");
  }
  decoded.format = PNG_FORMAT_RGB;
  RgbImage image(static_cast<int>(decoded.width), static_cast<int>(decoded.height));
  if (!png_image_finish_read(&decoded, nullptr, image.pixels.data(), 0, nullptr)) {
    png_image_free(&decoded);
    throw std::runtime_error(path.string() + ": PNG decoding failed");
  }
  return image;
}

}  // namespace plywood::render
