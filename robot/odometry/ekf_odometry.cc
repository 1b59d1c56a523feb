#include "robot/odometry/ekf_odometry.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"
#include "robot/drive/diff_drive_kinematics.h"

namespace plywood::robot {
namespace {

void RequireNonNegative(const char* field, double value) {
  if (!std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(std::string(field) + ": must be a finite number >= 0, got " +
                                msgs::ShortestNumber(value));
  }
}

void RequirePositive(const char* field, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(std::string(field) + ": must be a finite number > 0, got " +
                                msgs::ShortestNumber(value));
  }
}

enum Index { kX = 0, kY = 1, kTheta = 2, kBias = 3, kThetaPrev = 4 };

}  // namespace

void EkfOdometryOptions::Validate() const {
  increments.Validate();
  RequirePositive("gyro_noise_rad_s", gyro_noise_rad_s);
  RequireNonNegative("gyro_scale_sigma", gyro_scale_sigma);
  RequireNonNegative("gyro_bias_sigma_rad_s", gyro_bias_sigma_rad_s);
  RequireNonNegative("gyro_bias_random_walk_rad_s_per_sqrt_s",
                     gyro_bias_random_walk_rad_s_per_sqrt_s);
  RequireNonNegative("wheel_slip_sigma", wheel_slip_sigma);
  RequireNonNegative("encoder_turn_sigma", encoder_turn_sigma);
}

EkfOdometry::EkfOdometry(const OdometryGeometry& geometry, const EkfOdometryOptions& options,
                         const msgs::Pose2D& X_WR_initial)
    : options_((options.Validate(), options)),
      source_(geometry, options.increments, /*uses_gyro=*/true) {
  state_ << X_WR_initial.x_m, X_WR_initial.y_m, X_WR_initial.theta_rad, 0.0, X_WR_initial.theta_rad;
  covariance_.setZero();
  covariance_(kBias, kBias) = options_.gyro_bias_sigma_rad_s * options_.gyro_bias_sigma_rad_s;
}

void EkfOdometry::AddEncoders(const msgs::WheelEncoders& encoders) {
  source_.AddEncoders(encoders);
  Drain();
}

void EkfOdometry::AddGyro(const msgs::GyroRate& gyro) {
  source_.AddGyro(gyro);
  Drain();
}

void EkfOdometry::Drain() {
  while (const auto increment = source_.Next()) Step(*increment);
}

msgs::Pose2D EkfOdometry::pose() const {
  return {state_(kX), state_(kY), msgs::WrapAngle(state_(kTheta))};
}

double EkfOdometry::bias_sigma_rad_s() const { return std::sqrt(covariance_(kBias, kBias)); }

void EkfOdometry::Step(const OdometryIncrement& increment) {
  using Matrix5 = Eigen::Matrix<double, 5, 5>;
  using Vector5 = Eigen::Matrix<double, 5, 1>;
  const double dt = increment.end_s - increment.start_s;
  if (!(dt > 0.0)) return;

  // Clone theta: the start of this interval.
  state_(kThetaPrev) = state_(kTheta);
  covariance_.row(kThetaPrev) = covariance_.row(kTheta);
  covariance_.col(kThetaPrev) = covariance_.col(kTheta);
  covariance_(kThetaPrev, kThetaPrev) = covariance_(kTheta, kTheta);

  // Prediction: encoder distance, bias-corrected gyro heading change.
  const double ds = increment.ds_m;
  // The raw gyro angle: a dead band before removing the bias would hide the bias itself.
  const double dtheta = increment.dtheta_gyro_raw_rad - state_(kBias) * dt;
  const double mid = state_(kTheta) + dtheta / 2.0;
  const double c = std::cos(mid), s = std::sin(mid);
  double chord = ds;
  if (options_.increments.integration == Integration::kArc && std::abs(dtheta) > 1e-9) {
    chord = ds * std::sin(dtheta / 2.0) / (dtheta / 2.0);
  }
  state_(kX) += chord * c;
  state_(kY) += chord * s;
  state_(kTheta) += dtheta;

  Matrix5 F = Matrix5::Identity();
  F(kX, kTheta) = -chord * s;
  F(kY, kTheta) = chord * c;
  F(kX, kBias) = chord * s * dt / 2.0;
  F(kY, kBias) = -chord * c * dt / 2.0;
  F(kTheta, kBias) = -dt;

  // Gyro heading-change noise: white noise summed over the samples in the interval (variance
  // sigma^2 tau dt for samples tau apart) plus the scale-factor uncertainty.
  const double tau = increment.gyro_sample_period_s > 0.0 ? increment.gyro_sample_period_s : dt;
  const double q_gyro = options_.gyro_noise_rad_s * options_.gyro_noise_rad_s * tau * dt +
                        std::pow(options_.gyro_scale_sigma * increment.dtheta_gyro_raw_rad, 2);
  const double q_ds =
      std::pow(options_.wheel_slip_sigma, 2) *
      (increment.left_m * increment.left_m + increment.right_m * increment.right_m) / 4.0;
  Vector5 g_gyro = Vector5::Zero();
  g_gyro << -chord * s / 2.0, chord * c / 2.0, 1.0, 0.0, 0.0;
  Vector5 g_ds = Vector5::Zero();
  g_ds << c, s, 0.0, 0.0, 0.0;
  Matrix5 Q = q_gyro * g_gyro * g_gyro.transpose() + q_ds * g_ds * g_ds.transpose();
  Q(kBias, kBias) += std::pow(options_.gyro_bias_random_walk_rad_s_per_sqrt_s, 2) * dt;
  covariance_ = F * covariance_ * F.transpose() + Q;

  // Measurement: the encoders' heading change over the interval, theta - theta_prev. Its noise is
  // the two wheels' independent slip over the track plus the track uncertainty times the turn;
  // quantisation (one tick over the track) keeps it from vanishing at rest.
  const OdometryGeometry& g = source_.geometry();
  const double tick_m = 2.0 * std::numbers::pi * (g.left_wheel_radius_m + g.right_wheel_radius_m) /
                        2.0 / g.ticks_per_rev;
  const double r_encoder =
      std::pow(options_.wheel_slip_sigma, 2) *
          (increment.left_m * increment.left_m + increment.right_m * increment.right_m) /
          (g.track_m * g.track_m) +
      std::pow(options_.encoder_turn_sigma * increment.dtheta_encoder_rad, 2) +
      2.0 * std::pow(tick_m / g.track_m, 2) / 12.0;
  Eigen::Matrix<double, 1, 5> H = Eigen::Matrix<double, 1, 5>::Zero();
  H(kTheta) = 1.0;
  H(kThetaPrev) = -1.0;
  const double innovation = increment.dtheta_encoder_rad - (state_(kTheta) - state_(kThetaPrev));
  const double innovation_variance = (H * covariance_ * H.transpose())(0, 0) + r_encoder;
  const Vector5 gain = covariance_ * H.transpose() / innovation_variance;
  state_ += gain * innovation;
  // Joseph form keeps the covariance symmetric and positive over very long runs.
  const Matrix5 I_KH = Matrix5::Identity() - gain * H;
  covariance_ = I_KH * covariance_ * I_KH.transpose() + gain * r_encoder * gain.transpose();
}

}  // namespace plywood::robot
