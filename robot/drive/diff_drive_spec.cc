#include "robot/drive/diff_drive_spec.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"
#include "robot/number_checks.h"

namespace plywood::robot {
namespace {

using internal::RequirePositive;

// A length the odometry divides by: beyond these bounds no wheeled robot exists, and a tiny one
// (1e-320 m, a subnormal) makes wheel speeds and heading changes infinite, so the run would end
// on a non-finite command or report every odometry figure as null.
void RequireLength(const char* field, double value, double min_m, double max_m) {
  RequirePositive(field, value);
  if (value < min_m || value > max_m) {
    throw std::invalid_argument(std::string(field) + ": must be in [" +
                                msgs::ShortestNumber(min_m) + ", " + msgs::ShortestNumber(max_m) +
                                "] m, got " + msgs::ShortestNumber(value));
  }
}

}  // namespace

void DiffDriveSpec::Validate() const {
  RequireLength("wheel_radius_m", wheel_radius_m, 0.001, 10.0);
  RequireLength("track_m", track_m, 0.01, 100.0);
  RequirePositive("max_wheel_speed_rad_s", max_wheel_speed_rad_s);
  RequirePositive("encoder_ticks_per_rev", encoder_ticks_per_rev);
}

DiffDriveSpec P3dxSpec() { return DiffDriveSpec{}; }

DiffDriveSpec MagellanProSpec() {
  // Assumed: 3-inch-radius wheels under a 0.406 m round body, track 0.32 m, and stepper-driven
  // wheels read at 800 steps per revolution (half-stepped 400-step motors behind no gearbox).
  DiffDriveSpec spec;
  spec.wheel_radius_m = 0.0762;
  spec.track_m = 0.32;
  spec.max_wheel_speed_rad_s = 13.0;
  spec.encoder_ticks_per_rev = 800;
  return spec;
}

}  // namespace plywood::robot
