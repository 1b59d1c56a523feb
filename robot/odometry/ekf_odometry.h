#pragma once

#include <Eigen/Dense>

#include "msgs/gyro_rate.h"
#include "msgs/pose2d.h"
#include "msgs/wheel_encoders.h"
#include "robot/odometry/odometry_estimator.h"
#include "robot/odometry/odometry_increments.h"

namespace plywood::robot {

// Noise model the filter assumes. Defaults suit a P3-DX with a MEMS yaw gyro (sim defaults).
struct EkfOdometryOptions {
  IncrementOptions increments;
  // White noise of one gyro sample (rad/s, 1 sigma).
  double gyro_noise_rad_s = 0.002;
  // Relative error of the gyro's heading change (scale factor uncertainty, 1 sigma).
  double gyro_scale_sigma = 0.005;
  // Prior on the gyro's turn-on bias (rad/s, 1 sigma) and its random walk.
  double gyro_bias_sigma_rad_s = 0.01;
  double gyro_bias_random_walk_rad_s_per_sqrt_s = 1e-4;
  // Relative error of each wheel's travel (slip, tyre compression; 1 sigma).
  double wheel_slip_sigma = 0.005;
  // Relative error of an encoder heading change (the effective track differs from the nominal one
  // by this much, 1 sigma): what makes encoders poor at spot turns and good on straight legs.
  double encoder_turn_sigma = 0.02;

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// An extended Kalman filter fusing wheel encoders and a yaw-rate gyro, with the gyro bias as a
// state. State s = [x, y, theta, b, theta_prev]: the prediction integrates the encoder distance and
// the bias-corrected gyro heading change (midpoint rule); the encoder heading change
// theta - theta_prev is then a measurement of the same interval (stochastic cloning, Roumeliotis &
// Burdick 2002, keeps the increment measurement consistent). On straight legs the encoders'
// near-zero heading change makes the gyro bias observable; in turns, where the encoders' error
// grows with the turn (encoder_turn_sigma), the gyro dominates. This is the usual "gyrodometry"
// division of labour (Borenstein & Feng 1996, "Gyrodometry") done by a filter instead of a switch.
class EkfOdometry final : public OdometryEstimator {
 public:
  // @throws std::invalid_argument when `options` or `geometry` is invalid.
  EkfOdometry(const OdometryGeometry& geometry, const EkfOdometryOptions& options,
              const msgs::Pose2D& X_WR_initial);

  void AddEncoders(const msgs::WheelEncoders& encoders) override;
  void AddGyro(const msgs::GyroRate& gyro) override;
  msgs::Pose2D pose() const override;

  // The estimated gyro bias (rad/s) and its standard deviation.
  double bias_rad_s() const { return state_(3); }
  double bias_sigma_rad_s() const;

 private:
  void Drain();
  void Step(const OdometryIncrement& increment);

  EkfOdometryOptions options_;
  IncrementSource source_;
  Eigen::Matrix<double, 5, 1> state_;
  Eigen::Matrix<double, 5, 5> covariance_;
};

}  // namespace plywood::robot
