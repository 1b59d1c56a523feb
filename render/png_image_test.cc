#include "render/png_image.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

#include "tests/support/file_size_limit.h"
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

// A write past a file-size limit (as a full disk) left the picture cut at the limit in place of
// the earlier one: a PNG is staged beside its path and renamed into place, so the earlier picture
// stays whole and no staged copy is left (s63 fiftieth pass).
TEST(PngImageTest, AFailedWriteKeepsTheEarlierPictureAndLeavesNoCutFile) {
  const std::filesystem::path dir = testing::MakeTempDir("png_image_limit");
  const std::filesystem::path path = dir / "picture.png";
  const RgbImage earlier = TestPicture(7, 3);
  WritePng(earlier, path);
  const auto earlier_size = std::filesystem::file_size(path);
  {
    const testing::FileSizeLimit limit(16 * 1024);  // the 1024 x 653 picture is about 1.3 MB
    if (!limit.active()) GTEST_SKIP() << "cannot lower the file-size limit";
    try {
      WritePng(TestPicture(1024, 653), path);
      ADD_FAILURE() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), path.string() + ": cannot write: File too large");
    }
  }
  EXPECT_EQ(std::filesystem::file_size(path), earlier_size);
  EXPECT_TRUE(ReadPng(path).pixels == earlier.pixels);
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    ++files;
    EXPECT_EQ(entry.path(), path);
  }
  EXPECT_EQ(files, 1);
}

}  // namespace
}  // namespace plywood::render
