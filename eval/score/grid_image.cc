#include "eval/score/grid_image.h"

#include <png.h>

#include <cctype>
#include <csetjmp>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "perception/logs/regular_file.h"
#include "sim/config/config_error.h"

namespace plywood::eval {
namespace {

// 4000 x 4000: 200 m square at 5 cm, far beyond any room; bounds the decode to ~200 MB however
// small a crafted file is.
constexpr long kMaxPixels = 16'000'000;

// libpng's error handler: keeps the message for the one-line error and jumps back to PngStep
// (the default one prints to stderr). Warnings (an unknown chunk, a bad CRC in an ancillary one)
// change nothing read here.
void PngError(png_structp png, png_const_charp message) {
  *static_cast<std::string*>(png_get_error_ptr(png)) = message ? message : "unknown error";
  png_longjmp(png, 1);
}
void PngWarning(png_structp, png_const_charp) {}

// Runs libpng calls; false when libpng failed (its message in the reader's error string). `step`
// holds no object with a destructor: libpng's longjmp leaves it without unwinding.
template <typename Step>
bool PngStep(png_structp png, const Step& step) {
  if (setjmp(png_jmpbuf(png)) != 0) return false;
  step();
  return true;
}

// The file and libpng's structures, released however ReadPng ends.
struct PngReader {
  std::FILE* in = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  std::string error;
  ~PngReader() {
    png_destroy_read_struct(&png, &info, nullptr);
    if (in) std::fclose(in);
  }
};

// The samples of a PNG as stored, through libpng's low-level reader with no transformation but
// expanding palettes, bit depths below 8 and tRNS transparency. The simplified reader
// (png_image_*) applied the file's gAMA or sRGB chunk: an 8-bit grey 0x80 tagged gamma 1.0 read
// as 0xBC, a 16-bit 0x8000 tagged sRGB as linear 0.21, so a threshold between them sorted the map
// the other way (e 0 where the stored samples give e 1, exit 0).
GridImage ReadPng(const std::filesystem::path& path) {
  const std::string file = path.string();
  PngReader r;
  r.in = std::fopen(path.c_str(), "rb");
  if (r.in == nullptr) throw sim::ConfigError(file, "", "cannot read the file");
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r.error, PngError, PngWarning);
  if (r.png) r.info = png_create_info_struct(r.png);
  if (r.png == nullptr || r.info == nullptr) {
    throw sim::ConfigError(file, "PNG", "libpng could not start");
  }
  const auto fail = [&](const char* what) {
    throw sim::ConfigError(file, "PNG", std::string(what) + " (libpng: " + r.error + ")");
  };
  if (!PngStep(r.png, [&] {
        png_init_io(r.png, r.in);
        png_read_info(r.png, r.info);
      })) {
    fail("not a readable PNG");
  }
  const png_uint_32 width = png_get_image_width(r.png, r.info);
  const png_uint_32 height = png_get_image_height(r.png, r.info);
  if (static_cast<long>(width) * height > kMaxPixels) {
    throw sim::ConfigError(file, "size", "more than 1.6e7 pixels (4000 x 4000)");
  }
  if (!PngStep(r.png, [&] {
        png_set_expand(r.png);  // palette to RGB, 1-4 bit grey to 8 bits, tRNS to alpha
        png_read_update_info(r.png, r.info);
      })) {
    fail("not a readable PNG");
  }
  const int channels = png_get_channels(r.png, r.info);
  const bool sixteen = png_get_bit_depth(r.png, r.info) == 16;
  const bool alpha = (png_get_color_type(r.png, r.info) & PNG_COLOR_MASK_ALPHA) != 0;
  if (sixteen && alpha) {
    throw sim::ConfigError(file, "PNG",
                           "16-bit with an alpha channel is not supported (save it without "
                           "alpha, or with 8 bits)");
  }
  const std::size_t row_bytes = png_get_rowbytes(r.png, r.info);
  std::vector<png_byte> data(row_bytes * height);
  std::vector<png_bytep> rows(height);
  for (png_uint_32 y = 0; y < height; ++y) rows[y] = data.data() + y * row_bytes;
  if (!PngStep(r.png, [&] {
        png_read_image(r.png, rows.data());
        png_read_end(r.png, nullptr);
      })) {
    fail("truncated or corrupt");
  }

  GridImage image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.brightness.resize(static_cast<std::size_t>(image.width) * image.height);
  const int colours = alpha ? channels - 1 : channels;  // grey or RGB
  const double full = sixteen ? 65535.0 : 255.0;
  const auto sample = [&](std::size_t i, int c) -> long {
    const std::size_t k = static_cast<std::size_t>(channels) * i + static_cast<std::size_t>(c);
    return sixteen ? 256L * data[2 * k] + data[2 * k + 1] : static_cast<long>(data[k]);
  };
  for (std::size_t i = 0; i < image.brightness.size(); ++i) {
    // A pixel's colour says free or occupied; a transparent one's shows whatever lies beneath. A
    // map tool writing unknown cells as transparent black had them scored occupied, e 1.0.
    if (alpha && sample(i, colours) != 255) {
      const int column = static_cast<int>(i % width);
      const int row = static_cast<int>(i / width);
      throw sim::ConfigError(
          file, "pixel " + std::to_string(i),
          "(column " + std::to_string(column) + ", row " + std::to_string(row) +
              ") is transparent (alpha " + std::to_string(sample(i, colours)) +
              " of 255): its colour alone does not say free or occupied; save the map without "
              "transparency, flattened onto the colour such pixels mean");
    }
    long sum = 0;
    for (int c = 0; c < colours; ++c) sum += sample(i, c);
    image.brightness[i] = static_cast<double>(sum) / (colours * full);
  }
  return image;
}

// The PGM header and the plain format's samples: whitespace-separated words, '#' comments.
class PgmWords {
 public:
  PgmWords(const std::string& file, const std::string& bytes) : file_(file), bytes_(bytes) {}

  // The next word, with its line in line(). Empty at the end of the data.
  std::string Next() {
    for (;;) {
      while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) {
        if (bytes_[pos_++] == '\n') ++line_;
      }
      if (pos_ < bytes_.size() && bytes_[pos_] == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
        continue;
      }
      break;
    }
    if (pos_ < bytes_.size()) word_line_ = line_;  // at the end: the last word's line
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
    return bytes_.substr(start, pos_ - start);
  }

  // A whole number in [low, high]; `field` names it in errors.
  long Number(const std::string& field, long low, long high) {
    const std::string word = Next();
    if (word.empty()) Fail(field, "missing: the file ends here");
    long value = 0;
    for (char c : word) {
      if (!std::isdigit(static_cast<unsigned char>(c)) || value > high) {
        Fail(field, "expected a whole number in " + std::to_string(low) + ".." +
                        std::to_string(high) + ", got '" + word + "'");
      }
      value = 10 * value + (c - '0');
    }
    if (value < low || value > high) {
      Fail(field, "expected a whole number in " + std::to_string(low) + ".." +
                      std::to_string(high) + ", got " + word);
    }
    return value;
  }

  [[noreturn]] void Fail(const std::string& field, const std::string& what) const {
    throw sim::ConfigError(file_ + ":" + std::to_string(word_line_), field, what);
  }
  std::size_t pos() const { return pos_; }

 private:
  const std::string& file_;
  const std::string& bytes_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1, word_line_ = 1;
};

GridImage ReadPgm(const std::string& file, const std::string& bytes) {
  PgmWords words(file, bytes);
  const std::string magic = words.Next();
  if (magic != "P2" && magic != "P5") words.Fail("magic", "expected P2 or P5, got '" + magic + "'");
  GridImage image;
  image.width = static_cast<int>(words.Number("width", 1, kMaxPixels));
  image.height = static_cast<int>(words.Number("height", 1, kMaxPixels));
  if (static_cast<long>(image.width) * image.height > kMaxPixels) {
    words.Fail("height", "more than 1.6e7 pixels (4000 x 4000)");
  }
  const long maxval = words.Number("maxval", 1, 65535);
  const std::size_t count = static_cast<std::size_t>(image.width) * image.height;
  image.brightness.resize(count);
  if (magic == "P2") {
    for (std::size_t i = 0; i < count; ++i) {
      image.brightness[i] =
          static_cast<double>(words.Number("pixel " + std::to_string(i), 0, maxval)) / maxval;
    }
    if (!words.Next().empty()) words.Fail("pixels", "more samples than width x height");
    return image;
  }
  // P5: one whitespace byte after maxval, then big-endian samples of 1 or 2 bytes.
  const std::size_t start = words.pos() + 1;
  const std::size_t sample_bytes = maxval < 256 ? 1 : 2;
  const std::size_t have = bytes.size() > start ? bytes.size() - start : 0;
  if (have < count * sample_bytes) {
    throw sim::ConfigError(file, "pixels",
                           "truncated: " + std::to_string(have / sample_bytes) + " of " +
                               std::to_string(count) + " samples");
  }
  for (std::size_t i = 0; i < count; ++i) {
    const auto byte = [&](std::size_t k) {
      return static_cast<long>(static_cast<unsigned char>(bytes[start + k]));
    };
    const long sample = sample_bytes == 1 ? byte(i) : 256 * byte(2 * i) + byte(2 * i + 1);
    if (sample > maxval) {
      throw sim::ConfigError(file, "pixel " + std::to_string(i),
                             std::to_string(sample) + " exceeds maxval " + std::to_string(maxval));
    }
    image.brightness[i] = static_cast<double>(sample) / maxval;
  }
  // Bytes after the samples were ignored: a map tool padding each row to a 4-byte stride, or a
  // header whose width, height or maxval (1 or 2 bytes a sample) is wrong, gave a sheared or
  // garbled map, scored with exit 0. Trailing whitespace (a final line break) is harmless.
  const std::size_t end = start + count * sample_bytes;
  const std::size_t extra = bytes.find_first_not_of(" \t\r\n", end);
  if (extra != std::string::npos) {
    throw sim::ConfigError(
        file, "pixels",
        std::to_string(bytes.size() - end) + " bytes follow the " + std::to_string(image.width) +
            " x " + std::to_string(image.height) + " samples of " + std::to_string(sample_bytes) +
            (sample_bytes == 1 ? " byte" : " bytes") + " (maxval " + std::to_string(maxval) +
            "): rows padded to a stride, a wrong width, height or maxval, or a second image? "
            "Write exactly width x height samples");
  }
  return image;
}

}  // namespace

GridImage ReadGridImage(const std::filesystem::path& path) {
  const std::string file = path.string();
  if (!perception::IsRegularFile(path)) {
    throw sim::ConfigError(file, "", perception::WhyNotARegularFile(path));
  }
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty()) throw sim::ConfigError(file, "", "empty file");
  if (bytes.rfind("\x89PNG", 0) == 0) return ReadPng(path);
  if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '2' || bytes[1] == '5')) {
    return ReadPgm(file, bytes);
  }
  throw sim::ConfigError(file, "", "not a PNG or PGM (P2/P5) image");
}

}  // namespace plywood::eval
