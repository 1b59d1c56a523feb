#include "sim/sensors/gyro_sensor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/pose2d.h"
#include "msgs/shortest_number.h"
#include "sim/world/scene.h"

namespace plywood::sim {
namespace {

void Require(bool ok, const char* field, const char* what, double value) {
  if (!ok) {
    throw std::invalid_argument(std::string(field) + ": must be " + what + ", got " +
                                msgs::ShortestNumber(value));
  }
}

}  // namespace

void GyroSensorOptions::Validate() const {
  // Rates are bounded by 35 rad/s (2000 deg/s, the widest range of a MEMS rate gyro): a bias or a
  // noise of 1e300 rad/s drove the EKF to NaN and metrics.json to null, exit 0 (fuzz30).
  constexpr double kMaxRadS = 35.0;
  const auto rate = [](double value) {
    return std::isfinite(value) && std::abs(value) <= kMaxRadS;
  };
  Require(std::isfinite(rate_hz) && rate_hz > 0.0, "rate_hz", "a finite number > 0", rate_hz);
  Require(rate(noise_sigma_rad_s) && noise_sigma_rad_s >= 0.0, "noise_sigma_rad_s",
          "in [0, 35] rad/s", noise_sigma_rad_s);
  Require(rate(bias_rad_s), "bias_rad_s", "in [-35, 35] rad/s", bias_rad_s);
  Require(rate(bias_random_walk_rad_s_per_sqrt_s) && bias_random_walk_rad_s_per_sqrt_s >= 0.0,
          "bias_random_walk_rad_s_per_sqrt_s", "in [0, 35] rad/s per sqrt(s)",
          bias_random_walk_rad_s_per_sqrt_s);
  Require(
      std::isfinite(scale_factor_error) && scale_factor_error > -1.0 && scale_factor_error <= 1.0,
      "scale_factor_error", "in (-1, 1]", scale_factor_error);
  // 0 is off; a step below 1e-9 rad/s (finer than any gyro's least significant bit, ~1e-5) made
  // rate / step infinite at 1e-320 (subnormal): every gyro reading NaN, every figure null.
  constexpr double kMinQuantisationRadS = 1e-9;
  Require(rate(quantisation_rad_s) &&
              (quantisation_rad_s == 0.0 || quantisation_rad_s >= kMinQuantisationRadS),
          "quantisation_rad_s", "in [0, 35] rad/s, either 0 (off) or at least 1e-09",
          quantisation_rad_s);
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
