#include "sim/world/physical_deviation.h"

#include "robot/odometry/odometry_increments.h"

namespace plywood::sim {

// The same two ratios describe how a robot is really built (here) and the calibration its odometry
// applies (robot::OdometryCalibration), so one implementation of Borenstein & Feng's formulas and
// of the ratio checks serves both.
void PhysicalDeviation::Validate() const {
  robot::OdometryCalibration{.wheel_diameter_ratio = wheel_diameter_ratio,
                             .track_ratio = track_ratio}
      .Validate();
}

WheelGeometry DeviatedWheelGeometry(const robot::DiffDriveSpec& nominal,
                                    const PhysicalDeviation& deviation) {
  deviation.Validate();
  const robot::OdometryGeometry built =
      robot::CalibratedGeometry(nominal, {.wheel_diameter_ratio = deviation.wheel_diameter_ratio,
                                          .track_ratio = deviation.track_ratio});
  return {.left_radius_m = built.left_wheel_radius_m,
          .right_radius_m = built.right_wheel_radius_m,
          .track_m = built.track_m};
}

}  // namespace plywood::sim
