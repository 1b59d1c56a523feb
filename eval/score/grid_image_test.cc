#include "eval/score/grid_image.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "sim/config/config_error.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::eval {
namespace {

namespace fs = std::filesystem;

fs::path Dir() {
  static const fs::path dir = testing::MakeTempDir("grid_image_test");
  return dir;
}

fs::path WritePng(const std::string& name, png_uint_32 format, int width, int height,
                  const void* pixels) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = width;
  image.height = height;
  image.format = format;
  const fs::path path = Dir() / name;
  EXPECT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, pixels, 0, nullptr));
  return path;
}

std::string ErrorOf(const fs::path& path) {
  try {
    ReadGridImage(path);
  } catch (const sim::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(GridImageTest, PngValuesAreReadAsStored) {
  const std::uint8_t grey[] = {0, 128, 255, 205};  // 2 x 2
  GridImage image = ReadGridImage(WritePng("grey.png", PNG_FORMAT_GRAY, 2, 2, grey));
  ASSERT_EQ(image.width, 2);
  ASSERT_EQ(image.height, 2);
  EXPECT_EQ(image.At(0, 0), 0.0);
  EXPECT_EQ(image.At(1, 0), 128 / 255.0);
  EXPECT_EQ(image.At(0, 1), 1.0);
  EXPECT_EQ(image.At(1, 1), 205 / 255.0);
  // Opaque pixels of an image with an alpha channel read by their colour, averaged.
  const std::uint8_t rgba[] = {255, 255, 255, 255, 30, 60, 90, 255};
  image = ReadGridImage(WritePng("rgba.png", PNG_FORMAT_RGBA, 2, 1, rgba));
  EXPECT_EQ(image.At(0, 0), 1.0);
  EXPECT_EQ(image.At(1, 0), 60 / 255.0);
  // 16 bits, no gamma curve on the way.
  const std::uint16_t wide[] = {0, 32768, 65535};
  image = ReadGridImage(WritePng("wide.png", PNG_FORMAT_LINEAR_Y, 3, 1, wide));
  EXPECT_EQ(image.At(1, 0), 32768 / 65535.0);
  EXPECT_EQ(image.At(2, 0), 1.0);
}

// A 1-row grey PNG of `samples` at `bit_depth` (8 or 16), written with libpng's low-level writer so
// that it can carry a gAMA chunk (`gamma` > 0) or an sRGB one (`srgb`), as image editors write.
fs::path WriteTaggedGreyPng(const std::string& name, int bit_depth,
                            const std::vector<std::uint16_t>& samples, double gamma, bool srgb) {
  const fs::path path = Dir() / name;
  std::FILE* out = std::fopen(path.c_str(), "wb");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, out);
  png_set_IHDR(png, info, static_cast<png_uint_32>(samples.size()), 1, bit_depth,
               PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  if (gamma > 0.0) png_set_gAMA(png, info, gamma);
  if (srgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  std::vector<png_byte> row;
  for (const std::uint16_t v : samples) {
    if (bit_depth == 16) row.push_back(static_cast<png_byte>(v >> 8));
    row.push_back(static_cast<png_byte>(v & 0xff));
  }
  png_write_row(png, row.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(out);
  return path;
}

// audit s47: libpng's simplified reader applied a file's gAMA or sRGB chunk, so the samples were
// not read as stored: an 8-bit grey 0x80 tagged gamma 1.0 read as 0xBC (0.737), a 16-bit 0x8000
// tagged sRGB as linear 0.214; `score grid --threshold 0.3` (0.6) then scored an all-unknown map
// e 0 instead of 1 (1 instead of 0), exit 0.
TEST(GridImageTest, PngSamplesAreReadAsStoredWhateverGammaTheFileNames) {
  // No chunk, gAMA alone (linear, sRGB's 1/2.2, 2.2) and sRGB alone.
  for (const auto& [gamma, srgb] : std::vector<std::pair<double, bool>>{
           {0.0, false}, {1.0, false}, {0.45455, false}, {2.2, false}, {0.0, true}}) {
    {
      SCOPED_TRACE(std::to_string(gamma) + (srgb ? " sRGB" : ""));
      const GridImage eight =
          ReadGridImage(WriteTaggedGreyPng("g8.png", 8, {0, 0x80, 205, 255}, gamma, srgb));
      EXPECT_EQ(eight.brightness, (std::vector<double>{0.0, 0x80 / 255.0, 205 / 255.0, 1.0}));
      const GridImage wide =
          ReadGridImage(WriteTaggedGreyPng("g16.png", 16, {0, 0x8000, 65535}, gamma, srgb));
      EXPECT_EQ(wide.brightness, (std::vector<double>{0.0, 0x8000 / 65535.0, 1.0}));
    }
  }
}

// An Adam7-interlaced PNG (as some editors save maps) reads pixel for pixel as stored: libpng's
// low-level reader must be told to de-interlace, or png_read_image returns the first pass's rows.
TEST(GridImageTest, AnInterlacedPngReadsAsTheSamePixels) {
  constexpr int kSide = 9;  // not a multiple of 8: every Adam7 pass is partial
  std::vector<png_byte> pixels(kSide * kSide);
  for (int i = 0; i < kSide * kSide; ++i) pixels[i] = static_cast<png_byte>((37 * i) % 256);
  const fs::path path = Dir() / "interlaced.png";
  std::FILE* out = std::fopen(path.c_str(), "wb");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, out);
  png_set_IHDR(png, info, kSide, kSide, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_ADAM7,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  std::vector<png_bytep> rows(kSide);
  for (int y = 0; y < kSide; ++y) rows[y] = pixels.data() + y * kSide;
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(out);

  const GridImage image = ReadGridImage(path);
  ASSERT_EQ(image.width, kSide);
  ASSERT_EQ(image.height, kSide);
  for (int i = 0; i < kSide * kSide; ++i) {
    EXPECT_EQ(image.brightness[i], pixels[i] / 255.0) << "pixel " << i;
  }
}

// audit s41: an 8-bit alpha channel was ignored, so a pixel was read by the colour beneath its
// transparency: a map tool writing unknown cells as transparent black had them scored occupied
// (e 1.0 for an all-unknown map), as transparent white free. Any pixel not opaque is refused.
TEST(GridImageTest, APngPixelThatIsNotOpaqueIsRefusedNamingIt) {
  const std::uint8_t clear_black[] = {255, 255, 255, 255, 255, 255, 255, 255,
                                      255, 255, 255, 255, 0,   0,   0,   0};  // 2 x 2
  EXPECT_NE(ErrorOf(WritePng("clear.png", PNG_FORMAT_RGBA, 2, 2, clear_black))
                .find("clear.png: pixel 3: (column 1, row 1) is transparent (alpha 0 of 255)"),
            std::string::npos)
      << ErrorOf(Dir() / "clear.png");
  const std::uint8_t grey_alpha[] = {255, 255, 255, 128};  // grey + alpha, half transparent
  EXPECT_NE(ErrorOf(WritePng("half.png", PNG_FORMAT_GA, 2, 1, grey_alpha))
                .find("half.png: pixel 1: (column 1, row 0) is transparent (alpha 128 of 255)"),
            std::string::npos)
      << ErrorOf(Dir() / "half.png");
}

TEST(GridImageTest, PgmPlainAndRawWithCommentsAndWideSamples) {
  std::ofstream(Dir() / "plain.pgm") << "P2\n# made by hand\n3 1 # width height\n4\n0 2\n4\n";
  GridImage image = ReadGridImage(Dir() / "plain.pgm");
  EXPECT_EQ(image.brightness, (std::vector<double>{0.0, 0.5, 1.0}));
  {
    std::ofstream raw(Dir() / "raw.pgm", std::ios::binary);
    raw << "P5 2 1 65535\n";
    raw.put('\x80').put('\x00').put('\xff').put('\xff');
  }
  image = ReadGridImage(Dir() / "raw.pgm");
  EXPECT_EQ(image.brightness, (std::vector<double>{32768 / 65535.0, 1.0}));
}

// s42 thirteenth pass: bytes after a P5 image's samples were ignored. A map tool that pads each
// row to a 4-byte stride, or writes 16-bit samples under maxval 255, gave a sheared or garbled
// map, scored with exit 0.
TEST(GridImageTest, BytesAfterARawPgmsSamplesAreRefused) {
  const auto write = [](const std::string& name, const std::string& header,
                        const std::string& data) {
    std::ofstream(Dir() / name, std::ios::binary) << header << data;
    return Dir() / name;
  };
  // 3 x 2, each row padded with one zero byte to a stride of 4.
  const fs::path padded =
      write("padded.pgm", "P5\n3 2\n255\n", std::string("\xff\x00\xff\0\x00\xff\x00\0", 8));
  EXPECT_NE(ErrorOf(padded).find("padded.pgm: pixels: 2 bytes follow the 3 x 2 samples of 1 byte "
                                 "(maxval 255): rows padded to a stride"),
            std::string::npos)
      << ErrorOf(padded);
  // 16-bit samples under a maxval that says 8 bits.
  const fs::path wide = write("wide.pgm", "P5\n2 1\n255\n", std::string("\xff\xff\x00\x00", 4));
  EXPECT_NE(ErrorOf(wide).find("wide.pgm: pixels: 2 bytes follow the 2 x 1 samples"),
            std::string::npos)
      << ErrorOf(wide);
  // A second image after the first (a netpbm sequence): only one is a map.
  const fs::path two = write("two.pgm", "P5\n1 1\n255\n\xff", "P5\n1 1\n255\n\x7f");
  EXPECT_NE(ErrorOf(two).find("two.pgm: pixels: 12 bytes follow"), std::string::npos)
      << ErrorOf(two);
  // A final line break (or other whitespace) after the samples still reads.
  const fs::path newline = write("newline.pgm", "P5\n2 1\n255\n", std::string("\xff\x00\n", 3));
  EXPECT_EQ(ReadGridImage(newline).brightness, (std::vector<double>{1.0, 0.0}));
}

TEST(GridImageTest, BrokenImagesAreNamed) {
  const std::vector<std::uint8_t> grey(64 * 64, 200);
  const fs::path good = WritePng("cut.png", PNG_FORMAT_GRAY, 64, 64, grey.data());
  const auto size = fs::file_size(good);
  fs::resize_file(good, size - 30);  // the image data and the end are gone
  EXPECT_NE(ErrorOf(good).find("cut.png: PNG: truncated or corrupt (libpng: "), std::string::npos)
      << ErrorOf(good);
  const std::uint16_t rgba16[] = {0, 0, 0, 65535};
  const fs::path alpha16 = WritePng("alpha16.png", PNG_FORMAT_LINEAR_RGB_ALPHA, 1, 1, rgba16);
  EXPECT_NE(ErrorOf(alpha16).find("alpha16.png: PNG: 16-bit with an alpha channel"),
            std::string::npos);
  std::ofstream(Dir() / "zero.pgm") << "P2\n0 3\n255\n";
  EXPECT_NE(ErrorOf(Dir() / "zero.pgm").find("zero.pgm:2: width: expected a whole number in 1.."),
            std::string::npos);
  std::ofstream(Dir() / "short.pgm") << "P2\n2 2\n255\n1 2 3\n";
  EXPECT_NE(ErrorOf(Dir() / "short.pgm").find("short.pgm:4: pixel 3: missing"), std::string::npos)
      << ErrorOf(Dir() / "short.pgm");
  std::ofstream(Dir() / "long.pgm") << "P2\n1 1\n255\n1 2\n";
  EXPECT_NE(ErrorOf(Dir() / "long.pgm").find("long.pgm:4: pixels: more samples"),
            std::string::npos);
  std::ofstream(Dir() / "empty.pgm") << "";
  EXPECT_NE(ErrorOf(Dir() / "empty.pgm").find("empty.pgm: empty file"), std::string::npos);
  EXPECT_NE(ErrorOf(Dir() / "absent.pgm").find("absent.pgm: no such file"), std::string::npos);
}

}  // namespace
}  // namespace plywood::eval
