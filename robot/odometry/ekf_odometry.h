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
  // The gyro's scale-factor correction, multiplied into every heading change: a calibration of the
  // robot (like `gyro.gain`), found once on a calibration run with ground truth
  // (docs/odometry.md). Without an outside reference the filter cannot learn it: it only sees
  // the gyro's turns against the encoders', whose scale E_b is itself a state.
  double gyro_gain = 1.0;
  // Relative error of the gyro's heading change left after that calibration (1 sigma).
  double gyro_scale_sigma = 0.001;
  // Prior on the gyro's turn-on bias (rad/s, 1 sigma) and its random walk.
  double gyro_bias_sigma_rad_s = 0.01;
  double gyro_bias_random_walk_rad_s_per_sqrt_s = 1e-4;
  // Relative error of each wheel's travel (slip, tyre compression; 1 sigma).
  double wheel_slip_sigma = 0.005;
  // Relative white error of an encoder heading change beyond the systematic track ratio (uneven
  // floor, tyre contact patch; 1 sigma).
  double encoder_turn_sigma = 0.005;
  // Prior (1 sigma) on the drive's systematic errors left after `odometry.calibration`: the wheel
  // diameter ratio E_d and the track ratio E_b (Borenstein & Feng 1996 measured up to ~1 % and
  // ~5 % on uncalibrated robots). Both are filter states; 0 pins a ratio at its prior.
  double wheel_diameter_ratio_sigma = 0.001;
  double track_ratio_sigma = 0.005;
  // Prior means of E_d and E_b, relative to `odometry.calibration` (1: the calibration is right).
  // A UMBmark run of the same robot measures them (umbmark.ed / umbmark.eb) without changing the
  // geometry the other estimators use. Why they matter: on a run without stops that turns one way
  // only, bias, E_d and E_b are one unknown and the prior decides how the filter splits it.
  // In [0.8, 1.2].
  double wheel_diameter_ratio_prior = 1.0;
  double track_ratio_prior = 1.0;
  // Zero-velocity update: over an encoder interval in which neither wheel moved by a tick the
  // robot stands still, and its heading change is measured as 0 with this sigma (rad), far
  // tighter than one tick over the track, so stops pin the gyro bias.
  double zero_velocity_turn_sigma_rad = 1e-5;
  // Stop into a turn on the spot: when the robot brakes from speed (an encoder interval at
  // >= 0.05 m/s) into a turn on the spot (the next interval at < a quarter of that speed while the
  // encoders turn at >= 0.2 rad/s), it moves by this displacement that its encoders do not report,
  // in the frame of the approach heading: along it and towards the outside of the turn (m), with
  // this spread (1 sigma, m, each axis). A calibration of the robot and its controller's braking,
  // measured once on a run with ground truth (scripts/stop_displacement_calibration); it depends on
  // the approach speed, so measure it at the speed the robot drives. 0 / 0: off.
  double stop_displacement_along_m = 0.0;
  double stop_displacement_outward_m = 0.0;
  double stop_displacement_sigma_m = 0.0;
  // Braking transient: from an encoder interval whose speed fell by more than 0.5 m/s^2 x its
  // duration below the previous interval's (harder than a gentle stop), the encoder heading
  // changes of this long (s) are not used and the gyro carries the heading. Braking from speed into
  // a turn on the spot, the simulated P3-DX's wheels turn ~1 deg further than its body (0.6 deg in
  // the braking interval, 0.4 deg 0.3 s later as the body rocks back; docs/odometry.md): 15-20
  // sigma outliers of the slip model that the filter would otherwise put into E_b and the bias.
  // A calibration of the drive (how long its braking transient lasts); 0: off.
  double braking_window_s = 0.0;
  // Wheel speed changes: while a wheel changes speed (braking, slowing down, the onset or end of a
  // turn) its travel and the body's differ by more than the slip share of its travel, because the
  // tyre and the contact are compliant: the wheel leads, the body follows. Each wheel's travel over
  // an interval gets an extra error of this (s) x the change of its speed from the previous
  // interval (1 sigma), so the encoder heading change of an interval in which the wheels
  // accelerate weighs less. Without it the filter's encoder noise, which scales with the travel,
  // is smallest where the robot slows down and turns, and one such interval can move the estimate
  // by centimetres. A property of the drive, measured on the hall calibration run
  // (scripts/encoder_transient_calibration, docs/odometry.md); 0: off.
  double wheel_speed_change_sigma_s = 0.0;

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// An extended Kalman filter fusing wheel encoders and a yaw-rate gyro that estimates what makes
// each sensor wrong: the gyro bias b and the drive's wheel diameter ratio E_d and track ratio E_b.
// State s = [x, y, theta, b, E_d, E_b, theta_prev]: the prediction integrates the encoder distance
// and the bias-corrected gyro heading change; the encoder heading change of the same interval is
// then a measurement of theta - theta_prev (stochastic cloning, Roumeliotis & Burdick 2002):
//   z_enc = E_b (theta - theta_prev) - (2 ds / b) (E_d - 1) / (E_d + 1),
// the UMBmark error model (a robot with D_R / D_L = E_d and track E_b b turns by
// (d_R c_R - d_L c_L) / (E_b b)). Why E_d must be a state: on a straight leg at constant speed an
// unmodelled E_d makes the encoders turn at a steady rate, which a bias-only filter cannot tell
// from gyro bias. Bias acts per second and E_d per metre, so stops, spot turns (ds = 0) and speed
// changes separate them; left and right turns separate E_b (odd in the turn) from the bias. When
// neither wheel moved over an interval the robot stands still (zero-velocity update): the heading
// change is zero up to the gyro's noise, which pins the bias alone.
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
  // The estimated residual drive errors, relative to the calibrated geometry (1 = none).
  double wheel_diameter_ratio() const { return state_(4); }
  double track_ratio() const { return state_(5); }
  // How many stops into a turn on the spot got the stop displacement.
  int stops() const { return stops_; }
  // How many encoder heading changes the braking window left out.
  int gated() const { return gated_; }

 private:
  void Drain();
  void Step(const OdometryIncrement& increment);

  EkfOdometryOptions options_;
  IncrementSource source_;
  Eigen::Matrix<double, 7, 1> state_;
  Eigen::Matrix<double, 7, 7> covariance_;
  double previous_speed_m_s_ = 0.0;  // of the last encoder interval
  double previous_left_m_s_ = 0.0;   // its wheel speeds
  double previous_right_m_s_ = 0.0;
  int stops_ = 0;
  int gated_ = 0;
  double braking_until_s_ = -1.0;  // end of the current braking window
};

}  // namespace plywood::robot
