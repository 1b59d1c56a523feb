#include "viewer/view_controls.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "robot/drive/diff_drive_kinematics.h"

namespace plywood::viewer {
namespace {

TEST(ViewControlsTest, ArrowsTakeOverWithinTheRobotsLimitsAndHBandsBack) {
  robot::DiffDriveSpec spec;
  ViewControls controls(spec, {.speed_m_s = 0.4, .turn_deg_s = 60.0});
  EXPECT_FALSE(controls.Teleop());
  controls.HandleKey(GLFW_KEY_UP, GLFW_PRESS);
  ASSERT_TRUE(controls.Teleop());
  const robot::BodyTwist forward = robot::WheelSpeedsToTwist(spec, *controls.Teleop());
  EXPECT_NEAR(forward.linear_m_s, 0.4, 1e-12);
  EXPECT_NEAR(forward.angular_rad_s, 0.0, 1e-12);
  controls.HandleKey(GLFW_KEY_UP, GLFW_RELEASE);
  const robot::BodyTwist stopped = robot::WheelSpeedsToTwist(spec, *controls.Teleop());
  EXPECT_EQ(stopped.linear_m_s, 0.0);  // still teleoperating: released keys stop the robot
  controls.HandleKey(GLFW_KEY_H, GLFW_PRESS);
  EXPECT_FALSE(controls.Teleop());

  // A teleop speed beyond the wheels' limit is scaled down to it.
  ViewControls fast(spec, {.speed_m_s = 2.0, .turn_deg_s = 60.0});
  fast.HandleKey(GLFW_KEY_UP, GLFW_PRESS);
  EXPECT_LE(std::abs(fast.Teleop()->left_rad_s), spec.max_wheel_speed_rad_s + 1e-12);
}

TEST(ViewControlsTest, KeysToggleOverlaysPauseStepAndSpeed) {
  ViewControls controls(robot::DiffDriveSpec{});
  EXPECT_TRUE(controls.overlay(Overlay::kLaser));
  controls.HandleKey(GLFW_KEY_L, GLFW_PRESS);
  EXPECT_FALSE(controls.overlay(Overlay::kLaser));
  controls.HandleKey(GLFW_KEY_L, GLFW_REPEAT);  // holding a key does not toggle again
  EXPECT_FALSE(controls.overlay(Overlay::kLaser));
  controls.HandleKey(GLFW_KEY_N, GLFW_PRESS);
  EXPECT_TRUE(controls.paused());
  EXPECT_TRUE(controls.TakeStepRequest());
  EXPECT_FALSE(controls.TakeStepRequest());
  controls.HandleKey(GLFW_KEY_3, GLFW_PRESS);
  EXPECT_EQ(controls.SpeedFactor(), 0.0);
  controls.HandleKey(GLFW_KEY_2, GLFW_PRESS);
  EXPECT_EQ(controls.SpeedFactor(), 10.0);
}

TEST(ViewControlsTest, TeleopOptionsAreValidated) {
  EXPECT_THROW(ViewControls(robot::DiffDriveSpec{}, {.speed_m_s = 0.0}), std::invalid_argument);
  EXPECT_THROW(ViewControls(robot::DiffDriveSpec{}, {.speed_m_s = 0.4, .turn_deg_s = 1000.0}),
               std::invalid_argument);
}

}  // namespace
}  // namespace plywood::viewer
