#include "render/png_image.h"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>

#include "sim/runner/text_file.h"

namespace plywood::render {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

// What went wrong while encoding, kept for the one error line: libpng's default handler would
// print "libpng error: Write Error" on stderr as a line of its own.
struct PngWriteState {
  std::FILE* file = nullptr;
  std::string error;  // "cannot write: No space left on device" or libpng's message
};

[[noreturn]] void OnPngError(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngWriteState*>(png_get_error_ptr(png));
  if (state->error.empty()) state->error = std::string("PNG encoding failed: ") + message;
  png_longjmp(png, 1);
}

void OnPngWarning(png_structp, png_const_charp) {}

void WritePngBytes(png_structp png, png_bytep data, png_size_t size) {
  auto* state = static_cast<PngWriteState*>(png_get_io_ptr(png));
  if (std::fwrite(data, 1, size, state->file) != size) {
    state->error = std::string("cannot write: ") + std::strerror(errno);
    png_error(png, "write failed");
  }
}

void FlushPngBytes(png_structp) {}

// Encodes `image` into `target`; errors name `path`, the file the caller asked for.
void EncodePng(const RgbImage& image, const std::filesystem::path& target,
               const std::filesystem::path& path) {
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(target.c_str(), "wb"));
  if (!file) throw std::runtime_error(path.string() + ": cannot open for writing");
  PngWriteState state{.file = file.get(), .error = {}};
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, OnPngError, OnPngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error(path.string() + ": " +
                             (state.error.empty() ? "PNG encoding failed" : state.error));
  }
  png_set_write_fn(png, &state, WritePngBytes, FlushPngBytes);
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
  // The stdio buffer's last bytes are written on closing: a full disk may show only here.
  if (std::fclose(file.release()) != 0) {
    throw std::runtime_error(path.string() + ": cannot write: " + std::strerror(errno));
  }
}

}  // namespace

void WritePng(const RgbImage& image, const std::filesystem::path& path) {
  // Staged and renamed into place: a failed write (a full disk, a file-size limit) left a cut PNG
  // where a whole one was expected, in place of an earlier picture (s63 fiftieth pass).
  const std::error_code error = sim::WriteStagedThenRename(
      path, [&](const std::filesystem::path& target) { EncodePng(image, target, path); });
  if (error) throw std::runtime_error(path.string() + ": cannot write: " + error.message());
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
