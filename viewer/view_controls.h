#pragma once

#include <array>
#include <optional>
#include <string>

#include "msgs/wheel_speed_command.h"
#include "robot/drive/diff_drive_spec.h"

namespace plywood::viewer {

// What the viewer can draw over the world; each toggled by a key (ViewControls::HelpText).
enum class Overlay {
  kLaser,     // beams and hit points of the latest scan
  kSonar,     // cones of the latest ring: echo, specular miss, multipath
  kIr,        // IR ring beams and IR scanner points
  kPaths,     // ground-truth path and every odometry estimate
  kLines,     // lines extracted from the latest scan: matched green, unmatched red
  kMap,       // seed 001's partitions and graph (sonar explorer runs), seed 003's geometric map
  kGrid,      // seed 001's occupancy grid cells (sonar explorer runs)
  kScaleBar,  // scale bar and simulated clock
  kCount
};

enum class Speed { kRealTime, kTenTimes, kUnlimited };

// Teleoperation limits; wheel speeds are further capped by the robot's max_wheel_speed_rad_s.
struct TeleopOptions {
  double speed_m_s = 0.4;    // forward / backward while an arrow is held, in (0, 2]
  double turn_deg_s = 60.0;  // left / right, in (0, 360]

  // @throws std::invalid_argument whose message starts with the offending field's name.
  void Validate() const;
};

// The viewer's state driven by keys (GLFW key codes): pause, single step, speed, overlays, help and
// teleoperation. No GL: the same object serves live runs, replays and tests.
class ViewControls {
 public:
  ViewControls(const robot::DiffDriveSpec& nominal, const TeleopOptions& teleop = {});

  void HandleKey(int key, int action);

  bool paused() const { return paused_; }
  void set_paused(bool paused) { paused_ = paused; }
  // True once per press of the single-step key (the caller advances one step while paused).
  bool TakeStepRequest();
  Speed speed() const { return speed_; }
  void set_speed(Speed speed) { speed_ = speed; }
  double SpeedFactor() const;  // 1, 10, or 0 for as fast as possible
  bool overlay(Overlay o) const { return overlays_[static_cast<int>(o)]; }
  void set_overlay(Overlay o, bool on) { overlays_[static_cast<int>(o)] = on; }
  void SetAllOverlays(bool on) { overlays_.fill(on); }
  bool help() const { return help_; }
  bool TakeRecordToggle();
  bool TakeFollowRequest();

  // Wheel speeds while teleoperating (an arrow key took over and H has not handed back yet);
  // nullopt: the controller drives.
  std::optional<msgs::WheelSpeedCommand> Teleop() const;
  bool teleoperating() const { return teleop_; }

  // Lines "key\twhat it does" for the on-screen help.
  static std::string HelpText();

 private:
  robot::DiffDriveSpec nominal_;
  TeleopOptions teleop_options_;
  bool paused_ = false;
  bool step_ = false;
  bool record_ = false;
  bool follow_ = false;
  Speed speed_ = Speed::kRealTime;
  std::array<bool, static_cast<int>(Overlay::kCount)> overlays_{};
  bool help_ = false;
  bool teleop_ = false;
  bool up_ = false, down_ = false, left_ = false, right_ = false;
};

}  // namespace plywood::viewer
