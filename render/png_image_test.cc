#include "render/png_image.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

#include "tests/support/mujoco_test_support.h"

namespace plywood::render {
namespace {

// A picture like a snapshot's (flat areas, straight edges, a gradient) with a noisy patch, whose
// rows the "Up" filter cannot zero.
RgbImage TestPicture(int width, int height) {
  RgbImage image(width, height);
  std::mt19937 rng(17);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.At(x, y);
      if (x < width / 3) {
        p[0] = 200, p[1] = 200, p[2] = 200;  // flat floor
      } else if (x < 2 * width / 3) {
        p[0] = static_cast<std::uint8_t>(x), p[1] = static_cast<std::uint8_t>(y), p[2] = 255;
      } else {
        const auto noise = rng();
        p[0] = noise & 0xff, p[1] = (noise >> 8) & 0xff, p[2] = (noise >> 16) & 0xff;
      }
    }
  }
  return image;
}

// PNG is lossless whatever filter and zlib level the writer picks: what is read back is what
// was written, byte for byte, for sizes whose rows are not a multiple of any block size.
TEST(PngImageTest, ReadBackGivesTheWrittenPixels) {
  const std::filesystem::path dir = testing::MakeTempDir("png_image");
  for (const auto& [width, height] : {std::pair{1, 1}, {7, 3}, {1024, 653}, {333, 517}}) {
    const RgbImage written = TestPicture(width, height);
    const std::filesystem::path path = dir / "picture.png";
    WritePng(written, path);
    const RgbImage read = ReadPng(path);
    ASSERT_EQ(read.width, width);
    ASSERT_EQ(read.height, height);
    EXPECT_TRUE(read.pixels == written.pixels) << width << " x " << height;
  }
}

TEST(PngImageTest, UnwritablePathIsNamed) {
  const std::filesystem::path path =
      testing::MakeTempDir("png_image_bad") / "no_such_folder" / "x.png";
  try {
    WritePng(TestPicture(4, 4), path);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos);
  }
}

// A full disk (/dev/full: every write fails with ENOSPC) is one error naming the file and why,
// with nothing on stderr: libpng's own handler printed "libpng error: Write Error" as a line of
// its own, and a picture small enough to sit in stdio's buffer until fclose was "written" without
// a word.
TEST(PngImageTest, AFullDiskIsOneErrorNamingTheFileForBigAndSmallPictures) {
  const std::filesystem::path full = "/dev/full";
  if (!std::filesystem::exists(full)) GTEST_SKIP() << "no /dev/full";
  for (const auto& [width, height] : {std::pair{4, 4}, {1024, 653}}) {
    ::testing::internal::CaptureStderr();
    try {
      WritePng(TestPicture(width, height), full);
      ADD_FAILURE() << width << " x " << height << ": expected std::runtime_error";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "/dev/full: cannot write: No space left on device")
          << width << " x " << height;
    }
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << width << " x " << height;
  }
}

}  // namespace
}  // namespace plywood::render
