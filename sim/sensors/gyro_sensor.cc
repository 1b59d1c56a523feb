#include "sim/sensors/gyro_sensor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/pose2d.h"
#include "sim/world/scene.h"

namespace plywood::sim {
namespace {

void Require(bool ok, const char* field, const char* what, double value) {
  if (!ok) {
    throw std::invalid_argument(std::string(field) + ": must be " + what + ", got " +
                                std::to_string(value));
  }
}

}  // namespace

void GyroSensorOptions::Validate() const {
  Require(std::isfinite(rate_hz) && rate_hz > 0.0, "rate_hz", "a finite number > 0", rate_hz);
  Require(std::isfinite(noise_sigma_rad_s) && noise_sigma_rad_s >= 0.0, "noise_sigma_rad_s",
          "a finite number >= 0", noise_sigma_rad_s);
  Require(std::isfinite(bias_rad_s), "bias_rad_s", "finite", bias_rad_s);
  Require(
      std::isfinite(bias_random_walk_rad_s_per_sqrt_s) && bias_random_walk_rad_s_per_sqrt_s >= 0.0,
      "bias_random_walk_rad_s_per_sqrt_s", "a finite number >= 0",
      bias_random_walk_rad_s_per_sqrt_s);
  Require(std::isfinite(scale_factor_error) && scale_factor_error > -1.0, "scale_factor_error",
          "a finite number > -1", scale_factor_error);
  Require(std::isfinite(quantisation_rad_s) && quantisation_rad_s >= 0.0, "quantisation_rad_s",
          "a finite number >= 0", quantisation_rad_s);
}

GyroSensor::GyroSensor(const GyroSensorOptions& options, std::uint64_t seed)
    : options_(options), rng_(seed) {
  options_.Validate();
}

msgs::GyroRate GyroSensor::Sample(const Scene& scene) {
  const double time_s = scene.time_s();
  const double yaw_rad = scene.TruePose().theta_rad;
  const double dt_s = time_s - last_time_s_;
  // The heading change over one interval is far below pi for any wheeled robot, so wrapping the
  // difference recovers it unambiguously.
  const double true_rate_rad_s = started_ && dt_s > 0.0
                                     ? msgs::WrapAngle(yaw_rad - last_yaw_rad_) / dt_s
                                     : scene.TrueYawRateRadS();
  last_yaw_rad_ = yaw_rad;
  return Measure(time_s, true_rate_rad_s);
}

msgs::GyroRate GyroSensor::Measure(double time_s, double true_rate_rad_s) {
  const double dt_s = started_ ? std::max(0.0, time_s - last_time_s_) : 0.0;
  started_ = true;
  last_time_s_ = time_s;
  double noise_rad_s = 0.0;
  if (!options_.noise_free) {
    bias_walk_rad_s_ +=
        options_.bias_random_walk_rad_s_per_sqrt_s * std::sqrt(dt_s) * unit_normal_(rng_);
    // noise_sigma_rad_s is the white noise of a mean over one full period. A shorter interval (a
    // read off the schedule, as when the robot stops between two samples) averages the same noise
    // density over less time: sigma * sqrt(period / dt), so the integrated angle's variance stays
    // sigma^2 * period * dt. Intervals of a full period or more (within the clock's rounding) keep
    // sigma.
    const double period_s = 1.0 / options_.rate_hz;
    const double partial = dt_s > 0.0 && dt_s < (1.0 - 1e-6) * period_s ? period_s / dt_s : 1.0;
    noise_rad_s = options_.noise_sigma_rad_s * std::sqrt(partial) * unit_normal_(rng_);
  }
  double rate_rad_s =
      (1.0 + options_.scale_factor_error) * true_rate_rad_s + bias_rad_s() + noise_rad_s;
  if (options_.quantisation_rad_s > 0.0) {
    rate_rad_s = std::round(rate_rad_s / options_.quantisation_rad_s) * options_.quantisation_rad_s;
  }
  return {.time_s = time_s, .yaw_rate_rad_s = rate_rad_s};
}

}  // namespace plywood::sim
