#include "robot/odometry/ekf_odometry.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "msgs/shortest_number.h"
#include "robot/drive/diff_drive_kinematics.h"
#include "robot/number_checks.h"

namespace plywood::robot {
namespace {

using internal::RequireNonNegative;
using internal::RequirePositive;

enum Index {
  kX = 0,
  kY = 1,
  kTheta = 2,
  kBias = 3,
  kWheelRatio = 4,
  kTrackRatio = 5,
  kThetaPrev = 6
};

// The stop-into-turn test (EkfOdometryOptions::stop_displacement_*): the previous interval moved at
// least this fast, this one at less than this fraction of it while turning at least this fast.
constexpr double kStopFromSpeedMS = 0.05;
constexpr double kStopSpeedFraction = 0.25;
constexpr double kStopTurnRadS = 0.2;
// The braking test (EkfOdometryOptions::braking_window_s): a deceleration above this (m/s^2).
constexpr double kBrakingMS2 = 0.5;

}  // namespace

void EkfOdometryOptions::Validate() const {
  increments.Validate();
  RequirePositive("gyro_noise_rad_s", gyro_noise_rad_s);
  if (gyro_noise_rad_s > 35.0) {  // the bound of sensors.gyro; see the loop below
    throw std::invalid_argument("gyro_noise_rad_s: must be in (0, 35] rad/s, got " +
                                msgs::ShortestNumber(gyro_noise_rad_s));
  }
  if (!std::isfinite(gyro_gain) || gyro_gain < 0.5 || gyro_gain > 2.0) {
    throw std::invalid_argument("gyro_gain: must be in [0.5, 2], got " +
                                msgs::ShortestNumber(gyro_gain));
  }
  RequireNonNegative("gyro_scale_sigma", gyro_scale_sigma);
  RequireNonNegative("gyro_bias_sigma_rad_s", gyro_bias_sigma_rad_s);
  RequireNonNegative("gyro_bias_random_walk_rad_s_per_sqrt_s",
                     gyro_bias_random_walk_rad_s_per_sqrt_s);
  RequireNonNegative("wheel_slip_sigma", wheel_slip_sigma);
  RequireNonNegative("encoder_turn_sigma", encoder_turn_sigma);
  RequirePositive("zero_velocity_turn_sigma_rad", zero_velocity_turn_sigma_rad);
  for (const auto& [field, value] :
       {std::pair{"stop_displacement_along_m", stop_displacement_along_m},
        std::pair{"stop_displacement_outward_m", stop_displacement_outward_m}}) {
    if (!std::isfinite(value) || std::abs(value) > 0.1) {
      throw std::invalid_argument(std::string(field) + ": must be in [-0.1, 0.1] m, got " +
                                  msgs::ShortestNumber(value));
    }
  }
  RequireNonNegative("stop_displacement_sigma_m", stop_displacement_sigma_m);
  RequireNonNegative("braking_window_s", braking_window_s);
  RequireNonNegative("wheel_speed_change_sigma_s", wheel_speed_change_sigma_s);
  // Any of these at 1e300 (squared past the largest double) made the filter's covariance inf and
  // every odometry.ekf figure null, exit 0 (fuzz30; the gyro and slip ones at s43). The bounds:
  // 10x the largest stop displacement, a 10 s lead of the wheels, the widest gyro (35 rad/s, the
  // bound of sensors.gyro), a scale or turn error of 100 % and the encoders' largest slip_sigma.
  for (const auto& [field, value, limit, unit] :
       {std::tuple{"stop_displacement_sigma_m", stop_displacement_sigma_m, 1.0, " m"},
        std::tuple{"wheel_speed_change_sigma_s", wheel_speed_change_sigma_s, 10.0, " s"},
        std::tuple{"gyro_bias_sigma_rad_s", gyro_bias_sigma_rad_s, 35.0, " rad/s"},
        std::tuple{"gyro_bias_random_walk_rad_s_per_sqrt_s", gyro_bias_random_walk_rad_s_per_sqrt_s,
                   35.0, " rad/s per sqrt(s)"},
        std::tuple{"gyro_scale_sigma", gyro_scale_sigma, 1.0, ""},
        std::tuple{"encoder_turn_sigma", encoder_turn_sigma, 1.0, ""},
        std::tuple{"wheel_slip_sigma", wheel_slip_sigma, 0.5, ""}}) {
    if (value > limit) {
      throw std::invalid_argument(std::string(field) + ": must be in [0, " +
                                  msgs::ShortestNumber(limit) + "]" + unit + ", got " +
                                  msgs::ShortestNumber(value));
    }
  }
  for (const auto& [field, value] :
       {std::pair{"wheel_diameter_ratio_prior", wheel_diameter_ratio_prior},
        std::pair{"track_ratio_prior", track_ratio_prior}}) {
    if (!std::isfinite(value) || value < 0.8 || value > 1.2) {
      throw std::invalid_argument(std::string(field) + ": must be in [0.8, 1.2], got " +
                                  msgs::ShortestNumber(value));
    }
  }
  // A ratio's prior must leave it well inside (0, 2): the measurement divides by E_d + 1.
  for (const auto& [field, value] :
       {std::pair{"wheel_diameter_ratio_sigma", wheel_diameter_ratio_sigma},
        std::pair{"track_ratio_sigma", track_ratio_sigma}}) {
    if (!std::isfinite(value) || value < 0.0 || value > 0.2) {
      throw std::invalid_argument(std::string(field) + ": must be in [0, 0.2], got " +
                                  msgs::ShortestNumber(value));
    }
  }
}

EkfOdometry::EkfOdometry(const OdometryGeometry& geometry, const EkfOdometryOptions& options,
                         const msgs::Pose2D& X_WR_initial)
    : options_((options.Validate(), options)),
      source_(geometry, options.increments, /*uses_gyro=*/true) {
  state_ << X_WR_initial.x_m, X_WR_initial.y_m, X_WR_initial.theta_rad, 0.0,
      options_.wheel_diameter_ratio_prior, options_.track_ratio_prior, X_WR_initial.theta_rad;
  covariance_.setZero();
  covariance_(kBias, kBias) = options_.gyro_bias_sigma_rad_s * options_.gyro_bias_sigma_rad_s;
  covariance_(kWheelRatio, kWheelRatio) =
      options_.wheel_diameter_ratio_sigma * options_.wheel_diameter_ratio_sigma;
  covariance_(kTrackRatio, kTrackRatio) = options_.track_ratio_sigma * options_.track_ratio_sigma;
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
  using Matrix7 = Eigen::Matrix<double, 7, 7>;
  using Vector7 = Eigen::Matrix<double, 7, 1>;
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
  const double dtheta = options_.gyro_gain * increment.dtheta_gyro_raw_rad - state_(kBias) * dt;
  const double mid = state_(kTheta) + dtheta / 2.0;
  const double c = std::cos(mid), s = std::sin(mid);
  double chord = ds;
  if (options_.increments.integration == Integration::kArc && std::abs(dtheta) > 1e-9) {
    chord = ds * std::sin(dtheta / 2.0) / (dtheta / 2.0);
  }
  // A stop from speed into a turn on the spot: the displacement the encoders miss, in the frame of
  // the approach heading (theta before this interval), outward = away from the turn's centre.
  const double speed_m_s = std::abs(ds) / dt;
  const bool stop_into_turn = previous_speed_m_s_ >= kStopFromSpeedMS &&
                              speed_m_s < kStopSpeedFraction * previous_speed_m_s_ &&
                              std::abs(increment.dtheta_encoder_rad) / dt >= kStopTurnRadS;
  if (options_.braking_window_s > 0.0 && previous_speed_m_s_ - ds / dt > kBrakingMS2 * dt) {
    braking_until_s_ = increment.start_s + options_.braking_window_s;
  }
  previous_speed_m_s_ = ds / dt;
  double stop_x = 0.0, stop_y = 0.0;  // in the world frame
  const double approach = state_(kTheta);
  if (stop_into_turn &&
      (options_.stop_displacement_along_m != 0.0 || options_.stop_displacement_outward_m != 0.0 ||
       options_.stop_displacement_sigma_m != 0.0)) {
    ++stops_;
    // The outside of a left turn (positive) is the robot's right (-y).
    const double lateral =
        (increment.dtheta_encoder_rad > 0.0 ? -1.0 : 1.0) * options_.stop_displacement_outward_m;
    const double along = options_.stop_displacement_along_m;
    stop_x = along * std::cos(approach) - lateral * std::sin(approach);
    stop_y = along * std::sin(approach) + lateral * std::cos(approach);
  }
  state_(kX) += chord * c + stop_x;
  state_(kY) += chord * s + stop_y;
  state_(kTheta) += dtheta;

  Matrix7 F = Matrix7::Identity();
  F(kX, kTheta) = -chord * s - stop_y;
  F(kY, kTheta) = chord * c + stop_x;
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
  Vector7 g_gyro = Vector7::Zero();
  g_gyro << -chord * s / 2.0, chord * c / 2.0, 1.0, 0.0, 0.0, 0.0, 0.0;
  Vector7 g_ds = Vector7::Zero();
  g_ds << c, s, 0.0, 0.0, 0.0, 0.0, 0.0;
  Matrix7 Q = q_gyro * g_gyro * g_gyro.transpose() + q_ds * g_ds * g_ds.transpose();
  Q(kBias, kBias) += std::pow(options_.gyro_bias_random_walk_rad_s_per_sqrt_s, 2) * dt;
  if (stop_into_turn) {
    const double q_stop = options_.stop_displacement_sigma_m * options_.stop_displacement_sigma_m;
    Q(kX, kX) += q_stop;
    Q(kY, kY) += q_stop;
  }
  covariance_ = F * covariance_ * F.transpose() + Q;

  // Measurement: the encoders' heading change over the interval, predicted from theta - theta_prev
  // through the drive's error model (see the class comment). Its noise is the two wheels'
  // independent slip over the track plus a white share of the turn and quantisation (one tick over
  // the track). When no wheel moved, the robot stands still: the zero-velocity update, whose noise
  // is not quantisation (nothing turned) but zero_velocity_turn_sigma_rad.
  const OdometryGeometry& g = source_.geometry();
  const double tick_m = 2.0 * std::numbers::pi * (g.left_wheel_radius_m + g.right_wheel_radius_m) /
                        2.0 / g.ticks_per_rev;
  const bool stands_still = increment.left_m == 0.0 && increment.right_m == 0.0;
  // The wheels' speed changes since the previous interval (EkfOdometryOptions::
  // wheel_speed_change_sigma_s): each adds a travel error of sigma x its change.
  const double left_m_s = increment.left_m / dt, right_m_s = increment.right_m / dt;
  const double left_change = options_.wheel_speed_change_sigma_s * (left_m_s - previous_left_m_s_);
  const double right_change =
      options_.wheel_speed_change_sigma_s * (right_m_s - previous_right_m_s_);
  previous_left_m_s_ = left_m_s;
  previous_right_m_s_ = right_m_s;
  const double r_encoder =
      stands_still
          ? std::pow(options_.zero_velocity_turn_sigma_rad, 2)
          : std::pow(options_.wheel_slip_sigma, 2) *
                    (increment.left_m * increment.left_m + increment.right_m * increment.right_m) /
                    (g.track_m * g.track_m) +
                (left_change * left_change + right_change * right_change) /
                    (g.track_m * g.track_m) +
                std::pow(options_.encoder_turn_sigma * increment.dtheta_encoder_rad, 2) +
                2.0 * std::pow(tick_m / g.track_m, 2) / 12.0;
  const double turn = state_(kTheta) - state_(kThetaPrev);
  const double e_d = state_(kWheelRatio), e_b = state_(kTrackRatio);
  const double travel_over_track = 2.0 * ds / g.track_m;
  Eigen::Matrix<double, 1, 7> H = Eigen::Matrix<double, 1, 7>::Zero();
  H(kTheta) = e_b;
  H(kThetaPrev) = -e_b;
  H(kTrackRatio) = turn;
  H(kWheelRatio) = -travel_over_track * 2.0 / ((e_d + 1.0) * (e_d + 1.0));
  const double predicted = e_b * turn - travel_over_track * (e_d - 1.0) / (e_d + 1.0);
  const double innovation = increment.dtheta_encoder_rad - predicted;
  const double innovation_variance = (H * covariance_ * H.transpose())(0, 0) + r_encoder;
  if (!stands_still && increment.end_s <= braking_until_s_ + 1e-9) {
    ++gated_;  // a braking transient: the prediction (gyro) stands
    return;
  }
  const Vector7 gain = covariance_ * H.transpose() / innovation_variance;
  state_ += gain * innovation;
  // Joseph form keeps the covariance symmetric and positive over very long runs.
  const Matrix7 I_KH = Matrix7::Identity() - gain * H;
  covariance_ = I_KH * covariance_ * I_KH.transpose() + gain * r_encoder * gain.transpose();
}

}  // namespace plywood::robot
