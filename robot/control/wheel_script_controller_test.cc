#include "robot/control/wheel_script_controller.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "robot/drive/diff_drive_kinematics.h"

namespace plywood::robot {
namespace {

WheelScriptOptions Script() {
  WheelScriptOptions options;
  options.segments = {{1.0, 5, 5},  {0.5, -3, 3},  {2.0, 4, 6},
                      {0.25, 0, 0}, {1.5, -2, -2}, {0.75, 12.3, -12.3}};
  return options;
}

class WheelScriptTest : public ::testing::TestWithParam<double> {};

TEST_P(WheelScriptTest, PlaysEachSegmentForExactlyItsDuration) {
  const double dt = GetParam();
  const double t0 = 12.34;  // script time starts at the first Update, whatever the clock says
  const DiffDriveSpec spec = P3dxSpec();
  const WheelScriptOptions options = Script();
  WheelScriptController controller(spec, options);
  EXPECT_DOUBLE_EQ(controller.total_duration_s(), 6.0);

  std::vector<msgs::WheelSpeedCommand> commands;
  msgs::Pose2D X_WR{1, 2, 3};
  for (int i = 0; i < 10000; ++i) {
    const msgs::WheelSpeedCommand command = controller.Update({t0 + i * dt, {}});
    if (controller.Finished()) {
      EXPECT_EQ(command.left_rad_s, 0.0);
      EXPECT_EQ(command.right_rad_s, 0.0);
      break;
    }
    commands.push_back(command);
    const BodyTwist twist = WheelSpeedsToTwist(spec, command);
    X_WR = IntegrateArc(X_WR, twist.linear_m_s * dt, twist.angular_rad_s * dt);
  }
  ASSERT_TRUE(controller.Finished());
  ASSERT_EQ(commands.size(), std::lround(6.0 / dt));

  // Segment by segment: exactly duration / dt ticks with the scripted speeds.
  std::size_t tick = 0;
  msgs::Pose2D X_WR_expected{1, 2, 3};
  for (const WheelSegment& segment : options.segments) {
    const long n = std::lround(segment.duration_s / dt);
    for (long k = 0; k < n; ++k, ++tick) {
      ASSERT_EQ(commands[tick].left_rad_s, segment.left_rad_s) << "tick " << tick;
      ASSERT_EQ(commands[tick].right_rad_s, segment.right_rad_s) << "tick " << tick;
    }
    // Closed form of the whole segment: one arc.
    const BodyTwist twist = WheelSpeedsToTwist(spec, {segment.left_rad_s, segment.right_rad_s});
    X_WR_expected = IntegrateArc(X_WR_expected, twist.linear_m_s * segment.duration_s,
                                 twist.angular_rad_s * segment.duration_s);
  }
  EXPECT_NEAR(X_WR.x_m, X_WR_expected.x_m, 1e-9);
  EXPECT_NEAR(X_WR.y_m, X_WR_expected.y_m, 1e-9);
  EXPECT_NEAR(msgs::WrapAngle(X_WR.theta_rad - X_WR_expected.theta_rad), 0.0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Periods, WheelScriptTest, ::testing::Values(0.01, 0.05, 0.25));

TEST(WheelScriptControllerTest, SegmentsSwitchAtTheFirstTickAtOrAfterTheirEnd) {
  WheelScriptOptions options;
  options.segments = {{0.25, 1, 1}, {0.25, 2, 2}};
  WheelScriptController controller(P3dxSpec(), options);
  EXPECT_EQ(controller.Update({0.0, {}}).left_rad_s, 1.0);
  EXPECT_EQ(controller.Update({0.2, {}}).left_rad_s, 1.0);
  EXPECT_EQ(controller.Update({0.4, {}}).left_rad_s, 2.0);
  EXPECT_FALSE(controller.Finished());
  EXPECT_EQ(controller.Update({0.6, {}}).left_rad_s, 0.0);
  EXPECT_TRUE(controller.Finished());
}

void ExpectThrowsNaming(const WheelScriptOptions& options, const std::string& field) {
  try {
    WheelScriptController controller(P3dxSpec(), options);
    ADD_FAILURE() << "no exception for " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
  }
}

TEST(WheelScriptControllerTest, InvalidOptionsThrowNamingTheField) {
  auto with = [](auto change) {
    WheelScriptOptions options = Script();
    change(options);
    return options;
  };
  ExpectThrowsNaming(with([](auto& o) { o.segments.clear(); }), "segments");
  ExpectThrowsNaming(with([](auto& o) { o.segments[2].duration_s = 0; }), "segments[2].duration_s");
  ExpectThrowsNaming(with([](auto& o) { o.segments[1].left_rad_s = NAN; }),
                     "segments[1].left_rad_s");
  // Faster than the P3-DX's 12.3 rad/s.
  ExpectThrowsNaming(with([](auto& o) { o.segments[4].right_rad_s = -12.4; }),
                     "segments[4].right_rad_s");
}

}  // namespace
}  // namespace plywood::robot
