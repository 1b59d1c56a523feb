#include "eval/score/grid_image.h"

#include <png.h>

#include <cctype>
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

GridImage ReadPng(const std::filesystem::path& path) {
  const std::string file = path.string();
  png_image decoded{};
  decoded.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&decoded, path.c_str())) {
    throw sim::ConfigError(file, "PNG",
                           std::string("not a readable PNG (libpng: ") + decoded.message + ")");
  }
  if (static_cast<long>(decoded.width) * decoded.height > kMaxPixels) {
    png_image_free(&decoded);
    throw sim::ConfigError(file, "size", "more than 1.6e7 pixels (4000 x 4000)");
  }
  // Sample values as stored: libpng hands 8-bit files over unchanged as 8-bit sRGB (alpha kept
  // separate) and 16-bit files as 16-bit "linear"; any other pairing applies a gamma curve, and
  // dropping alpha composites onto black.
  const bool sixteen = (decoded.format & PNG_FORMAT_FLAG_LINEAR) != 0;
  if (sixteen && (decoded.format & PNG_FORMAT_FLAG_ALPHA) != 0) {
    png_image_free(&decoded);
    throw sim::ConfigError(file, "PNG",
                           "16-bit with an alpha channel is not supported (save it without "
                           "alpha, or with 8 bits)");
  }
  decoded.format = sixteen ? PNG_FORMAT_LINEAR_RGB : PNG_FORMAT_RGBA;
  const std::size_t channels = sixteen ? 3 : 4;
  std::vector<png_byte> buffer(PNG_IMAGE_SIZE(decoded));
  if (!png_image_finish_read(&decoded, nullptr, buffer.data(), 0, nullptr)) {
    const std::string message = decoded.message;
    png_image_free(&decoded);
    throw sim::ConfigError(file, "PNG", "truncated or corrupt (libpng: " + message + ")");
  }
  GridImage image;
  image.width = static_cast<int>(decoded.width);
  image.height = static_cast<int>(decoded.height);
  image.brightness.resize(static_cast<std::size_t>(image.width) * image.height);
  const auto* wide = reinterpret_cast<const png_uint_16*>(buffer.data());
  for (std::size_t i = 0; i < image.brightness.size(); ++i) {
    const std::size_t p = channels * i;
    // A pixel's colour says free or occupied; a transparent one's shows whatever lies beneath. A
    // map tool writing unknown cells as transparent black had them scored occupied, e 1.0.
    if (!sixteen && buffer[p + 3] != 255) {
      const int column = static_cast<int>(i % decoded.width);
      const int row = static_cast<int>(i / decoded.width);
      throw sim::ConfigError(
          file, "pixel " + std::to_string(i),
          "(column " + std::to_string(column) + ", row " + std::to_string(row) +
              ") is transparent (alpha " + std::to_string(buffer[p + 3]) +
              " of 255): its colour alone does not say free or occupied; save the map without "
              "transparency, flattened onto the colour such pixels mean");
    }
    image.brightness[i] = sixteen ? (wide[p] + wide[p + 1] + wide[p + 2]) / (3.0 * 65535.0)
                                  : (buffer[p] + buffer[p + 1] + buffer[p + 2]) / (3.0 * 255.0);
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
