#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/bumpers.h"
#include "msgs/laser_scan.h"
#include "msgs/pose2d.h"
#include "msgs/range_ring.h"
#include "msgs/shortest_number.h"
#include "msgs/wheel_speed_command.h"
#include "robot/drive/diff_drive_spec.h"
#include "robot/number_checks.h"

namespace plywood::robot {

// What a motion controller sees at one control tick. The runner decides which pose to pass (ground
// truth, or an odometry estimate as on the real robot); the controller cannot tell which.
struct ControllerInput {
  double time_s = 0.0;
  msgs::Pose2D X_WR_estimate;              // the pose the controller steers by
  const msgs::RangeRing* sonar = nullptr;  // latest sonar ring; null before the first one
  const msgs::LaserScan* laser = nullptr;  // latest laser scan; null before the first one
  const msgs::Bumpers* bumpers = nullptr;  // latest bump panel states; null without bumpers
};

// A motion controller: called once per control tick, it returns the wheel speeds to hold until the
// next tick. Controllers are built from a DiffDriveSpec and their options struct, keep state
// between ticks (so they cannot be copied), and measure their control period from time_s.
class Controller {
 public:
  Controller() = default;
  Controller(const Controller&) = delete;
  Controller& operator=(const Controller&) = delete;
  virtual ~Controller() = default;

  // @pre input.time_s does not decrease from one call to the next.
  virtual msgs::WheelSpeedCommand Update(const ControllerInput& input) = 0;

  // True once the task is complete; Update then commands zero wheel speeds.
  virtual bool Finished() const = 0;
};

// Speed magnitude (m/s or rad/s) for a move that must come to rest after `remaining` more units
// (m or rad). It ramps up from `previous` at `accel`, caps at `cruise` and follows the braking
// curve sqrt(2 accel remaining). Once what would be left after this tick falls inside `tolerance`
// (where the move counts as done), it commands remaining / dt_s instead, still within the ramp and
// the cruise cap, so that an ideal drive lands on the target at the next tick rather than stopping
// anywhere inside the tolerance. dt_s is the expected control period; with dt_s <= 0 (unknown, i.e.
// the first tick) it returns 0, since no ramp step can be sized.
inline double StoppingSpeed(double previous, double cruise, double accel, double remaining,
                            double tolerance, double dt_s) {
  if (dt_s <= 0.0 || remaining <= 0.0) return 0.0;
  const double ramp_cap = std::min(cruise, std::max(previous, 0.0) + accel * dt_s);
  const double speed = std::min(ramp_cap, std::sqrt(2.0 * accel * remaining));
  if (remaining - speed * dt_s < tolerance) return std::min(ramp_cap, remaining / dt_s);
  return speed;
}

namespace internal {

// Option checks shared by the controllers' Validate(), beside robot/number_checks.h's; messages
// start with the field name.

// A forward speed the wheels can drive: beyond max_wheel_speed_rad_s x wheel_radius_m the wheel
// limits cap it, so the run would not be the one written (speed_m_s: 1e300 drove at 1.2 m/s).
// The limit prints with 6 significant digits (12.3 x 0.0975 reads 1.19925, 1e-9 rad/s 9.75e-11).
inline void RequireDrivableSpeed(const DiffDriveSpec& spec, const std::string& field,
                                 double speed_m_s) {
  const double max_rim_m_s = spec.max_wheel_speed_rad_s * spec.wheel_radius_m;
  if (speed_m_s > max_rim_m_s) {
    throw std::invalid_argument(field + ": " + msgs::ShortestNumber(speed_m_s) +
                                " needs more than max_wheel_speed_rad_s allows (" +
                                msgs::SixDigitNumber(max_rim_m_s) + " m/s)");
  }
}

}  // namespace internal
}  // namespace plywood::robot
