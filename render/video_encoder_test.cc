#include "render/video_encoder.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

#include "tests/support/file_size_limit.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::render {
namespace {

// Noise compresses badly, so a few frames make a file of some hundred kilobytes.
RgbImage NoiseFrame(std::mt19937& rng) {
  RgbImage frame(320, 240);
  for (std::uint8_t& byte : frame.pixels) byte = static_cast<std::uint8_t>(rng());
  return frame;
}

// Encodes 30 noise frames to `video` under a file-size limit of 8 kB (SIGXFSZ ignored, as plywood's
// main() does), so ffmpeg runs out of room; returns the error Close or AddFrame threw ("" if none).
std::string EncodeOntoAFullDisk(const std::filesystem::path& video, std::mt19937& rng) {
  const testing::FileSizeLimit limit(8192);
  if (!limit.active()) return "the file-size limit could not be set";
  try {
    VideoEncoder encoder(video, 10.0);
    for (int i = 0; i < 30; ++i) encoder.AddFrame(NoiseFrame(rng));
    encoder.Close();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// ffmpeg exits 0 after "Error writing trailer of v.mp4: File too large" (or "No space left on
// device"), leaving a broken 8 kB file: its error line must fail Close, not pass unnoticed, and
// the broken file must go, so that no unplayable v.mp4 looks like a result. The
// disk is made full by a file-size limit of 8 kB, with SIGXFSZ ignored as plywood's main() does.
TEST(VideoEncoderTest, AVideoFfmpegCouldNotFinishIsAnErrorNamingItsReason) {
  if (std::system("command -v ffmpeg > /dev/null") != 0) GTEST_SKIP() << "no ffmpeg";
  const std::filesystem::path video = testing::MakeTempDir("video_encoder") / "v.mp4";
  std::mt19937 rng(3);
  const std::string error = EncodeOntoAFullDisk(video, rng);
  EXPECT_EQ(error.rfind(video.string() + ": ffmpeg", 0), 0u) << error;
  EXPECT_NE(error.find("File too large"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(video)) << "ffmpeg's broken file was left behind";
}

// ffmpeg writes a staged name that Close renames into place: a failed video leaves an earlier file
// at the path as it was (ffmpeg's -y used to overwrite it before failing), and a good one replaces
// it. Either way nothing but v.mp4 is left in the folder.
TEST(VideoEncoderTest, AFailedVideoKeepsTheEarlierFileAndAGoodOneReplacesIt) {
  if (std::system("command -v ffmpeg > /dev/null") != 0) GTEST_SKIP() << "no ffmpeg";
  const std::filesystem::path dir = testing::MakeTempDir("video_encoder_staged");
  const std::filesystem::path video = dir / "v.mp4";
  const std::string earlier = "an earlier video\n";
  { std::ofstream(video, std::ios::binary) << earlier; }
  std::mt19937 rng(5);
  const std::string error = EncodeOntoAFullDisk(video, rng);
  EXPECT_EQ(error.rfind(video.string() + ": ffmpeg", 0), 0u) << error;
  EXPECT_NE(error.find("File too large"), std::string::npos) << error;
  EXPECT_EQ(error.find(".partial-"), std::string::npos) << "the staged name is ours: " << error;
  std::stringstream kept;
  kept << std::ifstream(video, std::ios::binary).rdbuf();
  EXPECT_EQ(kept.str(), earlier);
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(entry.path(), video) << "left behind";
  }
  {
    VideoEncoder encoder(video, 10.0);
    for (int i = 0; i < 3; ++i) encoder.AddFrame(NoiseFrame(rng));
    encoder.Close();
  }
  EXPECT_GT(std::filesystem::file_size(video), earlier.size());
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(entry.path(), video) << "left behind";
  }
}

// A video unfinished when an exception unwinds (the run failed) is dropped, not finished into a
// short file that looks like the run's video; an earlier file stays.
TEST(VideoEncoderTest, AVideoAbandonedByAnExceptionLeavesTheEarlierFile) {
  if (std::system("command -v ffmpeg > /dev/null") != 0) GTEST_SKIP() << "no ffmpeg";
  const std::filesystem::path dir = testing::MakeTempDir("video_encoder_abandoned");
  const std::filesystem::path video = dir / "v.mp4";
  { std::ofstream(video, std::ios::binary) << "earlier"; }
  std::mt19937 rng(7);
  try {
    VideoEncoder encoder(video, 10.0);
    for (int i = 0; i < 3; ++i) encoder.AddFrame(NoiseFrame(rng));
    throw std::runtime_error("the run failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(std::filesystem::file_size(video), 7u);
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(entry.path(), video) << "left behind";
  }
}

}  // namespace
}  // namespace plywood::render
