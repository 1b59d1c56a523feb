#pragma once

#include <cstdint>
#include <random>

#include "msgs/gyro_rate.h"
#include "sim/sensors/noise_draws.h"

namespace plywood::sim {

class Scene;

// A single-axis yaw-rate gyro with the classic error budget (IEEE Std 952 terms): a constant bias,
// a bias random walk (rate random walk), a scale-factor error, white rate noise and output
// quantisation.
struct GyroSensorOptions {
  double rate_hz = 10.0;
  // White noise on each output sample (rad/s, 1 sigma). The default is a common MEMS yaw gyro
  // (ADXRS6xx class, about 0.04 deg/s/sqrt(Hz) over a 10 Hz bandwidth: ~0.13 deg/s). A sample
  // taken less than a period after the previous one (off the schedule) averages over less time and
  // gets sigma * sqrt(period / dt).
  double noise_sigma_rad_s = 0.002;
  // Constant (turn-on) bias added to every sample (rad/s).
  double bias_rad_s = 0.0;
  // The bias drifts as a Wiener process: after t seconds its variance has grown by
  // bias_random_walk_rad_s_per_sqrt_s^2 * t. Stepped once per sample with sigma * sqrt(dt).
  double bias_random_walk_rad_s_per_sqrt_s = 0.0;
  // Relative scale-factor error: 0.01 reads 1% high.
  double scale_factor_error = 0.0;
  // Output resolution (rad/s); the reading is rounded to the nearest multiple. 0 turns it off.
  double quantisation_rad_s = 0.0;
  // Turns off the random parts (white noise and bias walk); bias, scale factor and quantisation are
  // deterministic and stay.
  bool noise_free = false;

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// Reads the robot's yaw rate. A real rate gyro's output is band-limited, and odometry integrates it
// sample by sample, so each sample reports the true rate averaged over the interval since the
// previous sample (true heading change / dt) rather than the instantaneous rate at the sampling
// instant: a 10 Hz gyro is then not aliased by a 100 Hz physics step, and integrating noise-free
// samples reproduces the true heading change exactly. The first sample has no interval and reports
// the instantaneous rate.
class GyroSensor {
 public:
  // @throws std::invalid_argument when `options` is invalid.
  GyroSensor(const GyroSensorOptions& options, std::uint64_t seed);

  GyroSensor(const GyroSensor&) = delete;
  GyroSensor& operator=(const GyroSensor&) = delete;

  // The caller samples every period_s() of simulated time.
  double period_s() const { return 1.0 / options_.rate_hz; }

  msgs::GyroRate Sample(const Scene& scene);

  // Applies the error model to a true rate (rad/s) averaged over the interval since the previous
  // call; exposed for tests.
  msgs::GyroRate Measure(double time_s, double true_rate_rad_s);

  // The current bias, constant part plus random walk (rad/s).
  double bias_rad_s() const { return options_.bias_rad_s + bias_walk_rad_s_; }
  const GyroSensorOptions& options() const { return options_; }

 private:
  GyroSensorOptions options_;
  std::mt19937_64 rng_;
  NormalDraws unit_normal_;
  double bias_walk_rad_s_ = 0.0;
  bool started_ = false;
  double last_time_s_ = 0.0;
  double last_yaw_rad_ = 0.0;
};

}  // namespace plywood::sim
