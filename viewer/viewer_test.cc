// The viewer under Xvfb (started by the test; the program exits 77, a visible skip, without it):
// what it shows is checked against ground truth, and keys drive the robot.

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "eval/protocol.h"
#include "render/png_image.h"
#include "sim/config/config_error.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"
#include "tests/support/mujoco_test_support.h"
#include "tests/support/xvfb_display.h"
#include "viewer/gl_driver_pin.h"
#include "viewer/live_viewer.h"
#include "viewer/run_replay.h"
#include "viewer/scene_overlays.h"
#include "viewer/viewer_window.h"

namespace plywood::viewer {
namespace {

using testing::MakeTempDir;
using testing::SourceRoot;

sim::ExperimentConfig Office(double duration_s, std::vector<std::string> overrides = {}) {
  overrides.push_back("duration_s=" + std::to_string(duration_s));
  return sim::LoadExperimentConfig(SourceRoot() / "experiments/default.yaml", overrides);
}

LiveViewerOptions TestViewer() {
  LiveViewerOptions options;
  options.window.width_px = 480;
  options.window.height_px = 320;
  options.window.panel = false;
  options.speed = Speed::kUnlimited;
  options.max_fps = 4.0;  // a few frames: the tests look at the final one
  options.hold_at_end = false;
  return options;
}

// The P3-DX seen from above at its base frame's origin: the laser housing, blue.
bool IsRobotBlue(const render::RgbImage& image, const Eigen::Vector2d& uv) {
  const std::uint8_t* p = image.At(static_cast<int>(uv.x()), static_cast<int>(uv.y()));
  return p[2] > p[0] + 25 && p[2] > p[1] + 25;
}

long CountColour(const render::RgbImage& image, const float rgba[4]) {
  long count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.At(x, y);
      bool near = true;
      for (int c = 0; c < 3; ++c) near &= std::abs(p[c] - 255.0 * rgba[c]) < 24.0;
      count += near;
    }
  }
  return count;
}

class ViewerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { testing::RequireXvfbOrSkip(); }
};

// First, so that no earlier window has pinned the driver. Mesa's GLX unloads its DRI driver when
// the display closes, losing what the driver's globals held (a leak under LeakSanitizer); the
// viewer keeps the driver loaded.
TEST_F(ViewerTest, TheGlDriverStaysLoadedAfterTheWindowCloses) {
  sim::ExperimentRunner runner(Office(1.0));
  WindowOptions options;
  options.width_px = 128;
  options.height_px = 128;
  options.panel = false;
  {
    ViewerWindow window(runner.scene().model(), options);
    ASSERT_FALSE(LoadedGlDrivers().empty()) << "no *_dri.so loaded while a GL window is open";
  }
  EXPECT_FALSE(LoadedGlDrivers().empty());
}

TEST_F(ViewerTest, ScreenshotShowsTheRobotAtItsGroundTruthPoseAndTheLaserOnlyWhenOn) {
  sim::ExperimentRunner runner(Office(4.0));
  LiveViewer live(TestViewer());
  live.Open(runner);
  runner.SetObserver(&live);
  runner.Run();
  const std::filesystem::path dir = MakeTempDir("viewer_screenshot");

  live.controls().SetAllOverlays(false);
  live.WriteFinalScreenshot(dir / "plain.png");
  const render::RgbImage plain = render::ReadPng(dir / "plain.png");
  const render::WorldToPixel map = live.window().TopDownMapping();
  const msgs::Pose2D truth = runner.record().trajectory.back().truth;
  const Eigen::Vector2d spawn(-6.5, 0.0);  // experiments/default.yaml
  ASSERT_GT((Eigen::Vector2d(truth.x_m, truth.y_m) - spawn).norm(), 0.8) << "the robot must move";
  EXPECT_TRUE(IsRobotBlue(plain, map.ToPixel({truth.x_m, truth.y_m})));
  EXPECT_FALSE(IsRobotBlue(plain, map.ToPixel(spawn)));
  EXPECT_EQ(CountColour(plain, overlay_colours::kLaserBeam), 0);

  live.controls().set_overlay(Overlay::kLaser, true);
  live.WriteFinalScreenshot(dir / "laser.png");
  const render::RgbImage laser = render::ReadPng(dir / "laser.png");
  // 361 beams of up to 8 m: thousands of pixels; the robot itself stays drawn under them.
  EXPECT_GT(CountColour(laser, overlay_colours::kLaserBeam), 1000);
}

long DifferingPixels(const render::RgbImage& a, const render::RgbImage& b) {
  long n = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) n += std::memcmp(a.At(x, y), b.At(x, y), 3) != 0;
  }
  return n;
}

TEST_F(ViewerTest, SeedOnesGridAndMapAreDrawnOnlyWhenOn) {
  sim::ExperimentRunner runner(sim::LoadExperimentConfig(
      SourceRoot() / "experiments/seed001_room_1.yaml", {"duration_s=6"}));
  LiveViewer live(TestViewer());
  live.Open(runner);
  runner.SetObserver(&live);
  runner.Run();
  const std::filesystem::path dir = MakeTempDir("viewer_grid");
  live.controls().SetAllOverlays(false);
  live.WriteFinalScreenshot(dir / "plain.png");
  live.WriteFinalScreenshot(dir / "plain_again.png");
  live.controls().set_overlay(Overlay::kGrid, true);
  live.WriteFinalScreenshot(dir / "grid.png");
  live.controls().set_overlay(Overlay::kGrid, false);
  live.controls().set_overlay(Overlay::kMap, true);
  live.WriteFinalScreenshot(dir / "map.png");
  const render::RgbImage plain = render::ReadPng(dir / "plain.png");
  EXPECT_EQ(DifferingPixels(plain, render::ReadPng(dir / "plain_again.png")), 0);
  // The room is 3 x 3.5 m in a 480 x 320 window: thousands of cells, tens of partition edges.
  EXPECT_GT(DifferingPixels(plain, render::ReadPng(dir / "grid.png")), 5000);
  EXPECT_GT(DifferingPixels(plain, render::ReadPng(dir / "map.png")), 300);
}

// Holds the up arrow from press_s to release_s through the window's key entry point (the one
// GLFW's callback calls), recording the true x at the press.
class UpArrowScript : public sim::RunObserver {
 public:
  UpArrowScript(LiveViewer& live, double press_s, double release_s)
      : live_(live), press_s_(press_s), release_s_(release_s) {}

  bool AfterStep(const sim::ExperimentRunner& runner) override {
    live_.Open(runner);
    const double t = runner.scene().time_s();
    if (!x_at_press_ && t >= press_s_ - 1e-9) {
      x_at_press_ = runner.scene().TruePose().x_m;
      live_.window().HandleKey(GLFW_KEY_UP, GLFW_PRESS, 0);
    }
    if (!released_ && t >= release_s_ - 1e-9) {
      released_ = true;
      live_.window().HandleKey(GLFW_KEY_UP, GLFW_RELEASE, 0);
    }
    return live_.AfterStep(runner);
  }
  std::optional<msgs::WheelSpeedCommand> WheelOverride() override { return live_.WheelOverride(); }
  double x_at_press() const { return *x_at_press_; }

 private:
  LiveViewer& live_;
  double press_s_, release_s_;
  std::optional<double> x_at_press_;
  bool released_ = false;
};

TEST_F(ViewerTest, HoldingTheUpArrowDrivesTheRobotForwardByTheExpectedDistance) {
  // An idle controller: only the keyboard moves the robot (spawned facing +x).
  sim::ExperimentRunner runner(Office(4.5, {"controller={type: idle}"}));
  LiveViewerOptions options = TestViewer();
  options.teleop.speed_m_s = 0.4;
  LiveViewer live(options);
  UpArrowScript script(live, 0.5, 3.5);
  runner.SetObserver(&script);
  runner.Run();
  const double expected_m = 0.4 * (3.5 - 0.5);
  const double moved_m = runner.scene().TruePose().x_m - script.x_at_press();
  std::printf("teleop: moved %.4f m, expected %.4f m\n", moved_m, expected_m);
  EXPECT_NEAR(moved_m, expected_m, 0.05 * expected_m);
  EXPECT_NEAR(runner.scene().TruePose().y_m, 0.0, 0.05);
  // Before the press the idle robot stood still.
  EXPECT_NEAR(script.x_at_press(), -6.5, 1e-3);
}

// trajectory.csv's truth row at `time_s` (written with shortest round-trip numbers).
msgs::Pose2D TruthRow(const std::filesystem::path& csv, double time_s) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header: time_s,truth_x_m,truth_y_m,truth_theta_rad,...
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string t, x, y, theta;
    std::getline(fields, t, ',');
    std::getline(fields, x, ',');
    std::getline(fields, y, ',');
    std::getline(fields, theta, ',');
    if (std::abs(std::stod(t) - time_s) < 1e-9)
      return {std::stod(x), std::stod(y), std::stod(theta)};
  }
  ADD_FAILURE() << "no row at t = " << time_s << " in " << csv;
  return {};
}

TEST_F(ViewerTest, ReplayShowsThePoseOfTrajectoryCsvAtTimeT) {
  const std::filesystem::path run_dir = MakeTempDir("viewer_replay") / "run";
  const sim::ExperimentConfig config = Office(4.0);
  // No pictures: they would load OSMesa into this process (see ViewerWindow).
  ASSERT_EQ(eval::RunProtocol({config, run_dir, true, false}), 0);

  ReplayViewer replay(LoadRunReplay(run_dir), TestViewer().window);
  replay.controls().SetAllOverlays(false);
  replay.window().SetCapture(true);
  const double t = 2.5;
  replay.ShowAt(t);
  const msgs::Pose2D row = TruthRow(run_dir / "trajectory.csv", t);
  const msgs::Pose2D shown = replay.scene().TruePose();
  EXPECT_NEAR(shown.x_m, row.x_m, 1e-9);
  EXPECT_NEAR(shown.y_m, row.y_m, 1e-9);
  EXPECT_NEAR(shown.theta_rad, row.theta_rad, 1e-9);
  const render::WorldToPixel map = replay.window().TopDownMapping();
  EXPECT_TRUE(IsRobotBlue(replay.window().Screenshot(), map.ToPixel({row.x_m, row.y_m})));
  EXPECT_FALSE(IsRobotBlue(replay.window().Screenshot(), map.ToPixel({-6.5, 0.0})));

  // The laser of the scan logged at t is drawn when on.
  replay.controls().set_overlay(Overlay::kLaser, true);
  replay.ShowAt(t);
  EXPECT_GT(CountColour(replay.window().Screenshot(), overlay_colours::kLaserBeam), 1000);
}

TEST_F(ViewerTest, ReplayRefusesADirectoryThatIsNotACompleteRun) {
  const std::filesystem::path dir = MakeTempDir("viewer_replay_refusals");
  EXPECT_THROW(LoadRunReplay(dir / "absent"), sim::ConfigError);
  const std::filesystem::path run_dir = dir / "run";
  ASSERT_EQ(eval::RunProtocol({Office(1.0), run_dir, true, false}), 0);
  std::filesystem::remove(run_dir / "metrics.json");  // as a run stopped before its end
  try {
    LoadRunReplay(run_dir);
    FAIL() << "an unfinished run was accepted";
  } catch (const sim::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("metrics.json"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plywood::viewer
