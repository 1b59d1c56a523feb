// `plywood view` as a user runs it, under Xvfb (started by the test; the program exits 77, a
// visible skip, without it).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "render/png_image.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"
#include "tests/support/xvfb_display.h"

namespace plywood {
namespace {

using testing::MakeTempDir;
using testing::RunPlywood;
using testing::Slurp;
using testing::SourceRoot;

class ViewCliTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { testing::RequireXvfbOrSkip(); }
};

TEST_F(ViewCliTest, AnUntouchedViewedRunWritesTheSameBytesAsPlywoodRun) {
  const std::filesystem::path dir = MakeTempDir("view_cli_identity");
  const std::string experiment = (SourceRoot() / "experiments/default.yaml").string();
  const std::string common = experiment + " --seed 3 --set duration_s=6 --quiet";
  const testing::CliResult viewed =
      RunPlywood("view " + common + " --speed max --exit-at-end --size 320x240 --out " +
                     (dir / "viewed").string(),
                 dir);
  ASSERT_EQ(viewed.exit_code, 0) << viewed.err;
  const testing::CliResult run =
      RunPlywood("run " + common + " --out " + (dir / "run").string(), dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* file :
       {"metrics.json", "trajectory.csv", "laser.log", "sonar.csv", "config.yaml"}) {
    const std::string expected = Slurp(dir / "run" / file);
    EXPECT_FALSE(expected.empty()) << file;
    EXPECT_EQ(Slurp(dir / "viewed" / file), expected) << file;
  }
}

// The command that made docs/viewer.png (README): the office after 20 s, every overlay on.
TEST_F(ViewCliTest, ScreenshotCommandOfTheReadme) {
  const std::filesystem::path dir = MakeTempDir("view_cli_screenshot");
  const testing::CliResult result =
      RunPlywood("view " + (SourceRoot() / "experiments/default.yaml").string() +
                     " --set duration_s=20 --speed max --size 960x600 --quiet --out " +
                     (dir / "run").string() + " --screenshot " + (dir / "viewer.png").string(),
                 dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const render::RgbImage picture = render::ReadPng(dir / "viewer.png");
  EXPECT_EQ(picture.width, 960);
  EXPECT_EQ(picture.height, 600);
  EXPECT_FALSE(Slurp(dir / "run" / "metrics.json").empty());
}

TEST_F(ViewCliTest, RefusesARunDirectoryThatDidNotFinishInOneLine) {
  const std::filesystem::path dir = MakeTempDir("view_cli_refusal");
  const std::filesystem::path run = dir / "run";
  ASSERT_EQ(RunPlywood("run " + (SourceRoot() / "experiments/default.yaml").string() +
                           " --set duration_s=1 --quiet --no-snapshot --out " + run.string(),
                       dir)
                .exit_code,
            0);
  std::filesystem::remove(run / "metrics.json");
  const testing::CliResult result = RunPlywood("view " + run.string() + " --screenshot x.png", dir);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("metrics.json"), std::string::npos) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

// audit s34: these were read silently (--time nan showed t = 0, a live run ignored --time,
// --bench-seconds nan "drew 29.6 frames/s" in a run of 0 s, exit 0) or failed after the whole run
// (a screenshot into a missing folder or onto a folder, exit 1). Each is refused before a window
// opens: one line naming the flag, exit 2, nothing written.
TEST_F(ViewCliTest, FlagsThatCannotBeHonouredAreRefusedBeforeAnythingRuns) {
  const std::filesystem::path dir = MakeTempDir("view_cli_flags");
  const std::string experiment = (SourceRoot() / "experiments/default.yaml").string();
  const std::filesystem::path run = dir / "run";
  ASSERT_EQ(RunPlywood("run " + experiment + " --set duration_s=1 --quiet --no-snapshot --out " +
                           run.string(),
                       dir)
                .exit_code,
            0);
  const std::string live =
      experiment + " --set duration_s=1 --speed max --exit-at-end --out " + (dir / "live").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {run.string() + " --time nan --screenshot x.png",
       "view: --time: must be a finite number of simulated seconds >= 0, got nan"},
      {run.string() + " --time -5 --screenshot x.png", "view: --time: must be a finite number"},
      {run.string() + " --time 1e999 --screenshot x.png",
       "view: --time: must be a finite number of simulated seconds >= 0, got inf"},
      {live + " --time 5", "view: --time: only a replay (TARGET a run directory)"},
      {"--bench --bench-seconds nan", "view: --bench-seconds: must be in [1, 600]"},
      {run.string() + " --screenshot " + dir.string(),
       "view: --screenshot: " + dir.string() + " is a folder"},
      {live + " --screenshot " + (dir / "no_folder" / "x.png").string(),
       "view: --screenshot: " + (dir / "no_folder" / "x.png").string() + ": no folder"},
      {run.string() + " --size 640x480x3 --screenshot x.png",
       "--size: expected WIDTHxHEIGHT, got '640x480x3'"},
      {run.string() + " --size ' 640x480' --screenshot x.png",
       "--size: expected WIDTHxHEIGHT, got ' 640x480'"},
      {run.string() + " --size 99999999999x100 --screenshot x.png",
       "--size: width_px: must be in [64, 8192], got 99999999999"},
      {run.string() + " --size 640x-480 --screenshot x.png",
       "--size: height_px: must be in [64, 8192], got -480"},
  };
  for (const auto& [args, culprit] : cases) {
    SCOPED_TRACE(args);
    const testing::CliResult result = RunPlywood("view " + args, dir);
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_EQ(result.err.rfind("plywood: " + culprit, 0), 0u) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "live"));
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

}  // namespace
}  // namespace plywood
