#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "robot/control/controller.h"
#include "robot/drive/diff_drive_kinematics.h"
#include "robot/drive/diff_drive_spec.h"

namespace plywood::robot {

struct Waypoint {
  double x_m = 0.0;
  double y_m = 0.0;
};

struct WaypointOptions {
  std::vector<Waypoint> waypoints;  // in the frame of the pose estimate, visited in order
  double speed_m_s = 0.3;
  double max_turn_rate_rad_s = 1.0;
  double accel_m_s2 = 0.3;
  double heading_gain_per_s = 2.0;  // yaw rate per radian of bearing error
  // Bearing errors above this make the robot stop and turn on the spot until the error is below
  // half of it (hysteresis), so it never circles a waypoint it cannot turn tightly enough to hit.
  double turn_in_place_above_rad = 0.8;
  double reach_tolerance_m = 0.05;  // a waypoint counts as visited once the estimate is this close
  bool loop = false;  // after the last waypoint start again at the first; never finishes

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// Goes to a list of waypoints by turn-then-drive: within the turn-in-place threshold it drives
// towards the current waypoint with a proportional heading correction and forward speed scaled by
// cos(bearing error); beyond it, it turns on the spot. It slows down only for the last waypoint
// (unless looping), where it stops with the same braking profile as the square path.
class WaypointController final : public Controller {
 public:
  // @throws std::invalid_argument when the spec or options are invalid.
  WaypointController(const DiffDriveSpec& spec, const WaypointOptions& options);

  msgs::WheelSpeedCommand Update(const ControllerInput& input) override;
  bool Finished() const override { return finished_; }

  // Index of the waypoint currently steered to.
  std::size_t target_index() const { return target_; }
  // Number of waypoints reached so far (counts on past the list size when looping).
  std::size_t reached_count() const { return reached_; }

 private:
  const DiffDriveSpec spec_;
  const WaypointOptions options_;
  std::size_t target_ = 0;
  std::size_t reached_ = 0;
  bool finished_ = false;
  bool turning_in_place_ = false;
  double speed_m_s_ = 0.0;
  std::optional<double> last_time_s_;
};

}  // namespace plywood::robot
