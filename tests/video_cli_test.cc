// `plywood run --video`: a playable MP4 with one frame per 1 / fps of simulated time from t = 0.
// Exits 77 (a visible skip in ctest) where ffmpeg / ffprobe are not installed.

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>

#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

using testing::MakeTempDir;
using testing::RunPlywood;
using testing::Slurp;
using testing::SourceRoot;

TEST(VideoCliTest, RunWritesAnMp4WithTheExpectedFramesAndSize) {
  if (std::system("ffprobe -version > /dev/null 2>&1") != 0 ||
      std::system("ffmpeg -version > /dev/null 2>&1") != 0) {
    std::printf("SKIPPED: ffmpeg / ffprobe not installed (Debian package ffmpeg)\n");
    std::exit(77);
  }
  const std::filesystem::path dir = MakeTempDir("video_cli");
  const std::filesystem::path video = dir / "run.mp4";
  const testing::CliResult result =
      RunPlywood("run " + (SourceRoot() / "experiments/default.yaml").string() +
                     " --set duration_s=2.5 --quiet --no-snapshot --video " + video.string() +
                     " --video-fps 8 --out " + (dir / "run").string(),
                 dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::filesystem::path probe = dir / "probe.txt";
  ASSERT_EQ(std::system(("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                         "stream=codec_name,width,height,nb_read_frames -of csv=p=0 " +
                         video.string() + " > " + probe.string())
                            .c_str()),
            0);
  // floor(2.5 s x 8) + 1 frames; 640 px along the office's longer side (x), its height even.
  char codec[16] = {};
  int width = 0, height = 0, frames = 0;
  ASSERT_EQ(std::sscanf(Slurp(probe).c_str(), "%15[^,],%d,%d,%d", codec, &width, &height, &frames),
            4)
      << Slurp(probe);
  EXPECT_STREQ(codec, "h264");
  EXPECT_EQ(frames, 21);
  EXPECT_EQ(width, 640);
  EXPECT_EQ(height % 2, 0);
  EXPECT_GT(height, 300);
  EXPECT_LT(height, 640);
}

TEST(VideoCliTest, RefusesAFileThatIsNotMp4) {
  const std::filesystem::path dir = MakeTempDir("video_cli_bad");
  const testing::CliResult result =
      RunPlywood("run " + (SourceRoot() / "experiments/default.yaml").string() +
                     " --video out.avi --out " + (dir / "run").string(),
                 dir);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--video"), std::string::npos) << result.err;
}

// s61: the run is written into OUT.partial-PID and moved to OUT at its end, so a video inside OUT
// (or OUT itself) made the move fail after the whole run: exit 2, "cannot move the finished run
// into place (...: did another run finish there meanwhile?)", the results left in the .partial
// folder. Refused before the run, nothing written.
TEST(VideoCliTest, RefusesAVideoInsideTheRunsFolder) {
  const std::filesystem::path dir = MakeTempDir("video_cli_inside");
  std::filesystem::create_directories(dir / "run");
  for (const auto& [out, video] :
       {std::pair{dir / "run", dir / "run" / "v.mp4"}, std::pair{dir / "v.mp4", dir / "v.mp4"}}) {
    SCOPED_TRACE(video.string());
    const testing::CliResult result =
        RunPlywood("run " + (SourceRoot() / "experiments/default.yaml").string() +
                       " --set duration_s=0.5 --quiet --no-snapshot --video " + video.string() +
                       " --out " + out.string(),
                   dir);
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_EQ(result.err, "plywood: --video: " + video.string() + " is inside the run's folder " +
                              out.string() +
                              " (--out), which the run writes whole when it ends: write the "
                              "video elsewhere\n");
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir / "run"));
  EXPECT_FALSE(std::filesystem::exists(dir / "v.mp4"));
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << entry.path();
  }
}

// s61: ffmpeg read its output name as a protocol URL or an option: `file:a.mp4` was written as
// a.partial-PID.mp4 and the rename failed, `pipe:1.mp4` was no file, `-y.mp4` an unknown option;
// each exit 1 after the whole run. Each is now the file it names.
TEST(VideoCliTest, NamesFfmpegWouldReadAsAProtocolOrAnOptionAreFiles) {
  if (std::system("ffmpeg -version > /dev/null 2>&1") != 0) {
    std::printf("SKIPPED: ffmpeg not installed (Debian package ffmpeg)\n");
    std::exit(77);
  }
  const std::filesystem::path dir = MakeTempDir("video_cli_names");
  int runs = 0;
  for (const std::string name : {"file:a.mp4", "pipe:1.mp4", "-y.mp4"}) {
    SCOPED_TRACE(name);
    const testing::CliResult result =
        RunPlywood("run " + (SourceRoot() / "experiments/default.yaml").string() +
                       " --set duration_s=0.5 --quiet --no-snapshot --video " + name +
                       " --out run-" + std::to_string(++runs),
                   dir, dir);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    std::error_code error;
    EXPECT_GT(std::filesystem::file_size(dir / name, error), 0u) << error.message();
  }
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << entry.path();
  }
}

// s61: --video-fps without --video ran, exit 0, no video and no word that the rate was dropped.
TEST(VideoCliTest, AFrameRateWithoutAVideoIsRefused) {
  const std::filesystem::path dir = MakeTempDir("video_cli_fps_alone");
  const testing::CliResult result =
      RunPlywood("run " + (SourceRoot() / "experiments/default.yaml").string() +
                     " --set duration_s=0.5 --quiet --no-snapshot --video-fps 30 --out " +
                     (dir / "run").string(),
                 dir);
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(result.err, "plywood: run: --video-fps requires --video (see plywood run --help)\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "run"));
}

}  // namespace
}  // namespace plywood
