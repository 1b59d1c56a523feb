#include "viewer/view_controls.h"

#include <GLFW/glfw3.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "robot/drive/diff_drive_kinematics.h"

namespace plywood::viewer {

void TeleopOptions::Validate() const {
  if (!(speed_m_s > 0.0 && speed_m_s <= 2.0)) {
    throw std::invalid_argument("speed_m_s: must be in (0, 2], got " + std::to_string(speed_m_s));
  }
  if (!(turn_deg_s > 0.0 && turn_deg_s <= 360.0)) {
    throw std::invalid_argument("turn_deg_s: must be in (0, 360], got " +
                                std::to_string(turn_deg_s));
  }
}

ViewControls::ViewControls(const robot::DiffDriveSpec& nominal, const TeleopOptions& teleop)
    : nominal_(nominal), teleop_options_(teleop) {
  teleop.Validate();
  overlays_.fill(true);
}

void ViewControls::HandleKey(int key, int action) {
  const bool down = action != GLFW_RELEASE;
  // Held keys: the arrows steer while held, and the first press takes over from the controller.
  switch (key) {
    case GLFW_KEY_UP:
      up_ = down;
      break;
    case GLFW_KEY_DOWN:
      down_ = down;
      break;
    case GLFW_KEY_LEFT:
      left_ = down;
      break;
    case GLFW_KEY_RIGHT:
      right_ = down;
      break;
    default:
      break;
  }
  if (action != GLFW_PRESS) return;
  const auto toggle = [&](Overlay o) { set_overlay(o, !overlay(o)); };
  switch (key) {
    case GLFW_KEY_UP:
    case GLFW_KEY_DOWN:
    case GLFW_KEY_LEFT:
    case GLFW_KEY_RIGHT:
      teleop_ = true;
      break;
    case GLFW_KEY_H:
      teleop_ = false;
      break;
    case GLFW_KEY_SPACE:
      paused_ = !paused_;
      break;
    case GLFW_KEY_N:
      paused_ = true;
      step_ = true;
      break;
    case GLFW_KEY_1:
      speed_ = Speed::kRealTime;
      break;
    case GLFW_KEY_2:
      speed_ = Speed::kTenTimes;
      break;
    case GLFW_KEY_3:
      speed_ = Speed::kUnlimited;
      break;
    case GLFW_KEY_F1:
      help_ = !help_;
      break;
    case GLFW_KEY_L:
      toggle(Overlay::kLaser);
      break;
    case GLFW_KEY_S:
      toggle(Overlay::kSonar);
      break;
    case GLFW_KEY_I:
      toggle(Overlay::kIr);
      break;
    case GLFW_KEY_P:
      toggle(Overlay::kPaths);
      break;
    case GLFW_KEY_E:
      toggle(Overlay::kLines);
      break;
    case GLFW_KEY_M:
      toggle(Overlay::kMap);
      break;
    case GLFW_KEY_G:
      toggle(Overlay::kGrid);
      break;
    case GLFW_KEY_B:
      toggle(Overlay::kScaleBar);
      break;
    case GLFW_KEY_V:
      record_ = true;
      break;
    case GLFW_KEY_F:
      follow_ = true;
      break;
    default:
      break;
  }
}

bool ViewControls::TakeStepRequest() { return std::exchange(step_, false); }
bool ViewControls::TakeRecordToggle() { return std::exchange(record_, false); }
bool ViewControls::TakeFollowRequest() { return std::exchange(follow_, false); }

double ViewControls::SpeedFactor() const {
  switch (speed_) {
    case Speed::kRealTime:
      return 1.0;
    case Speed::kTenTimes:
      return 10.0;
    case Speed::kUnlimited:
      return 0.0;
  }
  return 1.0;
}

std::optional<msgs::WheelSpeedCommand> ViewControls::Teleop() const {
  if (!teleop_) return std::nullopt;
  robot::BodyTwist twist;
  twist.linear_m_s = teleop_options_.speed_m_s * ((up_ ? 1.0 : 0.0) - (down_ ? 1.0 : 0.0));
  twist.angular_rad_s = teleop_options_.turn_deg_s * std::numbers::pi / 180.0 *
                        ((left_ ? 1.0 : 0.0) - (right_ ? 1.0 : 0.0));
  return robot::TwistToWheelSpeeds(nominal_, twist);
}

std::string ViewControls::HelpText() {
  return "F1\tthis help\n"
         "Space\tpause / resume\n"
         "N\tsingle step (pauses)\n"
         "1 2 3\tspeed 1x, 10x, as fast as possible\n"
         "Arrows\tdrive (takes over from the controller)\n"
         "H\thand the robot back to the controller\n"
         "L S I\tlaser, sonar, IR overlays\n"
         "P\tground-truth path and odometry estimates\n"
         "E\textracted lines (matched green, unmatched red)\n"
         "M\tmaps: seed 001 partitions and graph, seed 003 segments\n"
         "G\tseed 001 occupancy grid (dark occupied, light free)\n"
         "B\tscale bar and clock\n"
         "T F\ttop-down / follow camera\n"
         "V\tstart / stop recording video\n"
         "Mouse\tleft: orbit, right: pan, wheel: zoom";
}

}  // namespace plywood::viewer
