#include "sim/sensors/encoder_sensor.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"
#include "sim/world/scene.h"

namespace plywood::sim {

void EncoderSensorOptions::Validate() const {
  if (ticks_per_rev <= 0) {
    throw std::invalid_argument("ticks_per_rev: must be > 0, got " + std::to_string(ticks_per_rev));
  }
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0) {
    throw std::invalid_argument("rate_hz: must be a finite number > 0, got " +
                                msgs::ShortestNumber(rate_hz));
  }
  // Beyond ~0.5 a Gaussian slip would regularly reverse a wheel's count.
  if (!std::isfinite(slip_sigma) || slip_sigma < 0.0 || slip_sigma > 0.5) {
    throw std::invalid_argument("slip_sigma: must be in [0, 0.5], got " +
                                msgs::ShortestNumber(slip_sigma));
  }
}

EncoderSensor::EncoderSensor(const EncoderSensorOptions& options, std::uint64_t seed)
    : options_(options), rng_(seed) {
  options_.Validate();
}

msgs::WheelEncoders EncoderSensor::Sample(const Scene& scene) {
  return Measure(scene.time_s(), scene.LeftWheelAngleRad(), scene.RightWheelAngleRad());
}

std::int64_t EncoderSensor::Wheel::Update(double angle_rad, double slip, int ticks_per_rev) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  slip_ticks += slip * (angle_rad - last_angle_rad) / kTwoPi * ticks_per_rev;
  last_angle_rad = angle_rad;
  // The rolled part is computed from the total angle, not summed per sample, so a noise-free count
  // is exactly floor((angle - angle0) / (2 pi) * ticks_per_rev) however often it is sampled.
  // Dividing by 2 pi first keeps whole revolutions exact (2 pi / 2 pi == 1).
  const double count = (angle_rad - angle0_rad) / kTwoPi * ticks_per_rev + slip_ticks;
  return static_cast<std::int64_t>(std::floor(count));
}

msgs::WheelEncoders EncoderSensor::Measure(double time_s, double left_angle_rad,
                                           double right_angle_rad) {
  if (!started_) {
    left_ = {left_angle_rad, left_angle_rad, 0.0};
    right_ = {right_angle_rad, right_angle_rad, 0.0};
    started_ = true;
  }
  const bool slips = !options_.noise_free && options_.slip_sigma > 0.0;
  // Both draws happen (or neither) so the left and right streams stay paired for a given seed.
  const double slip_left = slips ? options_.slip_sigma * unit_normal_(rng_) : 0.0;
  const double slip_right = slips ? options_.slip_sigma * unit_normal_(rng_) : 0.0;
  msgs::WheelEncoders out;
  out.time_s = time_s;
  out.left_ticks = left_.Update(left_angle_rad, slip_left, options_.ticks_per_rev);
  out.right_ticks = right_.Update(right_angle_rad, slip_right, options_.ticks_per_rev);
  return out;
}

}  // namespace plywood::sim
