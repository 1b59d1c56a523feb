// The EKF's gyro-bias state converges to an injected constant bias, and the filter's heading then
// beats both sensors alone when the encoders' track is off and the gyro is biased.

#include "robot/odometry/ekf_odometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "robot/odometry/encoder_odometry.h"
#include "robot/odometry/gyro_odometry.h"

namespace plywood::robot {
namespace {

constexpr double kPi = std::numbers::pi;

// A kinematic robot (r = 0.1 m, b = 0.4 m, 1000 ticks/rev) driving 10 s legs at 0.2 m/s with
// 90 deg spot turns in 4 s and 2 s stops, at 10 Hz, its gyro reading true rate + bias + noise.
// `true_track_m` may differ from the 0.4 m the odometry believes.
template <typename Visitor>
void DriveSquares(double duration_s, double bias_rad_s, double noise_rad_s, double true_track_m,
                  Visitor&& visit) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double dt = 0.1, r = 0.1;
  double left_rad = 0.0, right_rad = 0.0, theta = 0.0;
  double w_prev = 0.0;  // the gyro reports the mean rate of the interval that just ended
  for (int k = 0; k * dt <= duration_s; ++k) {
    const double t = k * dt;
    const double phase = std::fmod(t, 18.0);
    double v = 0.0, w = 0.0;
    if (phase < 10.0) {
      v = 0.2;
    } else if (phase >= 12.0 && phase < 16.0) {
      w = (kPi / 2.0) / 4.0;
    }
    const double ticks_per_rad = 1000.0 / (2.0 * kPi);
    visit(msgs::WheelEncoders{t, std::llround(std::floor(left_rad * ticks_per_rad)),
                              std::llround(std::floor(right_rad * ticks_per_rad))},
          msgs::GyroRate{t, w_prev + bias_rad_s + noise_rad_s * normal(rng)}, theta);
    // Advance one interval at constant (v, w) (true kinematics with the true track).
    left_rad += (v - w * true_track_m / 2.0) * dt / r;
    right_rad += (v + w * true_track_m / 2.0) * dt / r;
    theta += w * dt;
    w_prev = w;
  }
}

TEST(EkfOdometryTest, BiasConvergesToAnInjectedConstantBias) {
  const double bias = 0.01;  // 0.57 deg/s: a poor, uncompensated MEMS gyro
  const OdometryGeometry g{.left_wheel_radius_m = 0.1,
                           .right_wheel_radius_m = 0.1,
                           .track_m = 0.4,
                           .ticks_per_rev = 1000};
  EkfOdometry ekf(g,
                  {.increments = {},
                   .gyro_noise_rad_s = 0.002,
                   .gyro_scale_sigma = 0.005,
                   .gyro_bias_sigma_rad_s = 0.05},
                  {});
  GyroOdometry gyro(g, {}, {});
  double true_theta = 0.0;
  DriveSquares(180.0, bias, 0.002, 0.4,
               [&](const msgs::WheelEncoders& e, const msgs::GyroRate& w, double theta) {
                 ekf.AddEncoders(e);
                 ekf.AddGyro(w);
                 gyro.AddEncoders(e);
                 gyro.AddGyro(w);
                 true_theta = theta;
               });
  EXPECT_NEAR(ekf.bias_rad_s(), bias, 5e-4) << "sigma " << ekf.bias_sigma_rad_s();
  EXPECT_LT(ekf.bias_sigma_rad_s(), 5e-4);
  // The bias alone costs the gyro-only heading 1.8 rad over 180 s; the filter keeps it small.
  EXPECT_GT(std::abs(msgs::WrapAngle(gyro.pose().theta_rad - true_theta)), 1.0);
  EXPECT_LT(std::abs(msgs::WrapAngle(ekf.pose().theta_rad - true_theta)), 0.02);
}

TEST(EkfOdometryTest, TrustsTheGyroInTurnsWhenTheTrackIsWrong) {
  // The real track is 3% wider: the encoders report each 90 deg turn 2.7 deg too large. The gyro
  // (biased but otherwise exact) sees the true turn; the filter should follow it, not the encoders.
  const OdometryGeometry g{.left_wheel_radius_m = 0.1,
                           .right_wheel_radius_m = 0.1,
                           .track_m = 0.4,
                           .ticks_per_rev = 1000};
  EkfOdometry ekf(g,
                  {.increments = {},
                   .gyro_noise_rad_s = 0.002,
                   .gyro_scale_sigma = 0.005,
                   .gyro_bias_sigma_rad_s = 0.05,
                   .encoder_turn_sigma = 0.05},
                  {});
  EncoderOdometry encoder(g, EncoderOdometryOptions{}, {});
  double true_theta = 0.0;
  DriveSquares(72.0, 0.005, 0.002, 0.412,
               [&](const msgs::WheelEncoders& e, const msgs::GyroRate& w, double theta) {
                 ekf.AddEncoders(e);
                 ekf.AddGyro(w);
                 encoder.AddEncoders(e);
                 true_theta = theta;
               });
  const double encoder_error = std::abs(msgs::WrapAngle(encoder.pose().theta_rad - true_theta));
  const double ekf_error = std::abs(msgs::WrapAngle(ekf.pose().theta_rad - true_theta));
  EXPECT_GT(encoder_error, 0.15);  // four turns of 2.7 deg
  EXPECT_LT(ekf_error, encoder_error / 4.0);
}

}  // namespace
}  // namespace plywood::robot
