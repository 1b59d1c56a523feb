#include "sim/physical_deviation.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace plywood::sim {
namespace {

void RequireRatio(const char* field, double value) {
  // A ratio far from 1 is no longer a "deviation" the diff-drive model can carry (a wheel would
  // shrink to nothing or the track would exceed the chassis); 0.5..2 is generous.
  if (!std::isfinite(value) || value < 0.5 || value > 2.0) {
    throw std::invalid_argument(std::string(field) + ": must be a ratio in [0.5, 2], got " +
                                std::to_string(value));
  }
}

}  // namespace

void PhysicalDeviation::Validate() const {
  RequireRatio("wheel_diameter_ratio", wheel_diameter_ratio);
  RequireRatio("track_ratio", track_ratio);
}

WheelGeometry DeviatedWheelGeometry(const robot::DiffDriveSpec& nominal,
                                    const PhysicalDeviation& deviation) {
  nominal.Validate();
  deviation.Validate();
  const double e_d = deviation.wheel_diameter_ratio;
  const double r = nominal.wheel_radius_m;
  return {.left_radius_m = 2.0 * r / (e_d + 1.0),
          .right_radius_m = 2.0 * r * e_d / (e_d + 1.0),
          .track_m = deviation.track_ratio * nominal.track_m};
}

}  // namespace plywood::sim
