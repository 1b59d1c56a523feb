#pragma once

#include <cstdint>
#include <random>

#include "msgs/wheel_encoders.h"
#include "robot/drive/diff_drive_spec.h"
#include "sim/sensors/noise_draws.h"

namespace plywood::sim {

class Scene;

struct EncoderSensorOptions {
  // Counts per wheel revolution after quadrature decoding (P3-DX: 500 lines x 19.5:1 x 4).
  int ticks_per_rev = robot::DiffDriveSpec{}.encoder_ticks_per_rev;
  double rate_hz = 10.0;
  // Stochastic wheel slip: in each sample, each wheel turns (1 + s) times as far as it rolled,
  // s ~ N(0, slip_sigma^2) drawn per sample and per wheel. s > 0 is spin (the tire turns faster
  // than the ground passes, as when accelerating on a slick floor), s < 0 is skid (braking). The
  // encoder sees the extra rotation; the ground, and so the true pose, does not.
  double slip_sigma = 0.0;
  // Turns off the random parts (slip). Quantisation stays: it is deterministic and part of what an
  // encoder is.
  bool noise_free = false;

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// Quadrature wheel encoders: cumulative integer ticks of each wheel, counted from the wheel angles
// at the first sample (the counter is zeroed at power-on). Ticks are the floor of the continuous
// count; the fractional remainder is kept, so quantisation never accumulates into drift.
class EncoderSensor {
 public:
  // @throws std::invalid_argument when `options` is invalid.
  EncoderSensor(const EncoderSensorOptions& options, std::uint64_t seed);

  EncoderSensor(const EncoderSensor&) = delete;
  EncoderSensor& operator=(const EncoderSensor&) = delete;

  // The caller samples every period_s() of simulated time.
  double period_s() const { return 1.0 / options_.rate_hz; }

  // Reads the scene's wheel joint angles at scene.time_s().
  msgs::WheelEncoders Sample(const Scene& scene);

  // The same from explicit true wheel angles (rad, positive forward); exposed for tests.
  msgs::WheelEncoders Measure(double time_s, double left_angle_rad, double right_angle_rad);

  const EncoderSensorOptions& options() const { return options_; }

 private:
  // One wheel's counter: count = (angle - angle0) / (2 pi) * ticks_per_rev + slip_ticks.
  struct Wheel {
    double angle0_rad = 0.0;
    double last_angle_rad = 0.0;
    double slip_ticks = 0.0;  // extra (or missing) counts from slip, accumulated exactly
    std::int64_t Update(double angle_rad, double slip, int ticks_per_rev);
  };

  EncoderSensorOptions options_;
  std::mt19937_64 rng_;
  NormalDraws unit_normal_;
  bool started_ = false;
  Wheel left_, right_;
};

}  // namespace plywood::sim
