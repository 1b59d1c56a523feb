// The EKF's states converge to injected errors with closed-form values: a constant gyro bias, a
// wheel diameter ratio E_d, a track ratio E_b, the bias alone from a stop (zero-velocity update);
// and the filter's heading then beats both sensors alone.

#include "robot/odometry/ekf_odometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "robot/odometry/encoder_odometry.h"
#include "robot/odometry/gyro_odometry.h"

namespace plywood::robot {
namespace {

constexpr double kPi = std::numbers::pi;

// One phase of a scripted drive: forward speed and yaw rate held for a duration.
struct Phase {
  double duration_s;
  double v_m_s;
  double w_rad_s;
};

// The drive the robot really has: mean wheel radius 0.1 m, right/left diameter ratio e_d,
// track (the odometry believes 0.4 m and equal wheels).
struct TrueDrive {
  double e_d = 1.0;
  double track_m = 0.4;
  // Braking from speed into a turn on the spot, the wheels turn this much further (rad of encoder
  // heading, in the turn's direction) than the body, in the first interval of the turn.
  double stop_turn_excess_rad = 0.0;
};

// A kinematic robot (1000 ticks/rev) running `phases` in a loop for duration_s at 10 Hz; its gyro
// reads the true rate + bias + noise (the mean rate of the interval that just ended).
template <typename Visitor>
void DrivePhases(const std::vector<Phase>& phases, double duration_s, double bias_rad_s,
                 double noise_rad_s, const TrueDrive& drive, Visitor&& visit) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double dt = 0.1;
  const double r_left = 0.1 * 2.0 / (drive.e_d + 1.0), r_right = r_left * drive.e_d;
  double cycle_s = 0.0;
  for (const Phase& p : phases) cycle_s += p.duration_s;
  double left_rad = 0.0, right_rad = 0.0, theta = 0.0, w_prev = 0.0, v_prev = 0.0;
  for (int k = 0; k * dt <= duration_s; ++k) {
    const double t = k * dt;
    double phase_t = std::fmod(t + 1e-9, cycle_s);
    Phase now = phases.front();
    for (const Phase& p : phases) {
      now = p;
      if (phase_t < p.duration_s) break;
      phase_t -= p.duration_s;
    }
    const double ticks_per_rad = 1000.0 / (2.0 * kPi);
    visit(msgs::WheelEncoders{t, std::llround(std::floor(left_rad * ticks_per_rad)),
                              std::llround(std::floor(right_rad * ticks_per_rad))},
          msgs::GyroRate{t, w_prev + bias_rad_s + noise_rad_s * normal(rng)}, theta);
    left_rad += (now.v_m_s - now.w_rad_s * drive.track_m / 2.0) * dt / r_left;
    right_rad += (now.v_m_s + now.w_rad_s * drive.track_m / 2.0) * dt / r_right;
    if (now.v_m_s == 0.0 && now.w_rad_s != 0.0 && v_prev > 0.0) {
      const double wheel_m = std::copysign(drive.stop_turn_excess_rad, now.w_rad_s) * 0.4 / 2.0;
      left_rad -= wheel_m / r_left;
      right_rad += wheel_m / r_right;
    }
    theta += now.w_rad_s * dt;
    w_prev = now.w_rad_s;
    v_prev = now.v_m_s;
  }
}

// 10 s legs at 0.2 m/s with 90 deg spot turns in 4 s between 2 s stops; `true_track_m` may differ
// from the 0.4 m the odometry believes.
template <typename Visitor>
void DriveSquares(double duration_s, double bias_rad_s, double noise_rad_s, double true_track_m,
                  Visitor&& visit) {
  DrivePhases({{10.0, 0.2, 0.0}, {2.0, 0.0, 0.0}, {4.0, 0.0, (kPi / 2.0) / 4.0}, {2.0, 0.0, 0.0}},
              duration_s, bias_rad_s, noise_rad_s, {.track_m = true_track_m},
              std::forward<Visitor>(visit));
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

OdometryGeometry NominalGeometry() {
  return {.left_wheel_radius_m = 0.1,
          .right_wheel_radius_m = 0.1,
          .track_m = 0.4,
          .ticks_per_rev = 1000};
}

TEST(EkfOdometryTest, AGyroSampleSentTwiceCountsOnce) {
  // A driver that publishes every gyro message twice (or one whose clock repeats a stamp): the
  // repeat was dropped but counted, so the mean sample period the gyro noise scales with halved
  // and the filter trusted the gyro more. The filter now ends bit for bit where a clean feed ends.
  EkfOdometry once(NominalGeometry(), {}, {}), twice(NominalGeometry(), {}, {});
  for (EkfOdometry* ekf : {&once, &twice}) {
    ekf->AddEncoders({0.0, 0, 0});
    ekf->AddGyro({0.0, 0.01});
    for (int k = 1; k <= 100; ++k) {
      const msgs::GyroRate gyro{k * 0.1, 0.01 + (k % 20 < 10 ? 0.3 : -0.3)};
      ekf->AddGyro(gyro);
      if (ekf == &twice) ekf->AddGyro(gyro);
      ekf->AddEncoders({k * 0.1, 10 * k - (k % 20 < 10 ? 3 : -3) * (k % 10), 10 * k});
    }
  }
  EXPECT_EQ(twice.bias_sigma_rad_s(), once.bias_sigma_rad_s());
  EXPECT_EQ(twice.bias_rad_s(), once.bias_rad_s());
  EXPECT_EQ(twice.pose().theta_rad, once.pose().theta_rad);
  EXPECT_EQ(twice.pose().x_m, once.pose().x_m);
}

TEST(EkfOdometryTest, StopsPinTheBiasSoAStraightRunRecoversTheWheelDiameterRatio) {
  // A perfect gyro (no bias, no noise) and right wheels 1 % larger: on the 0.3 m/s straight legs
  // the encoders see a steady right turn of 0.3 * 0.01 / 0.4 = 0.0075 rad/s that a bias-only filter
  // would take for gyro bias. The 2 s stops show the bias is 0, so the filter must put it into E_d.
  const double e_d = 1.01;
  EkfOdometry ekf(
      NominalGeometry(),
      {.increments = {}, .gyro_bias_sigma_rad_s = 0.01, .wheel_diameter_ratio_sigma = 0.02}, {});
  EncoderOdometry encoder(NominalGeometry(), EncoderOdometryOptions{}, {});
  double true_theta = 0.0;
  DrivePhases({{8.0, 0.3, 0.0}, {2.0, 0.0, 0.0}}, 120.0, 0.0, 0.0, {.e_d = e_d},
              [&](const msgs::WheelEncoders& e, const msgs::GyroRate& w, double theta) {
                ekf.AddEncoders(e);
                ekf.AddGyro(w);
                encoder.AddEncoders(e);
                true_theta = theta;
              });
  EXPECT_NEAR(ekf.wheel_diameter_ratio(), e_d, 2e-4);
  EXPECT_NEAR(ekf.bias_rad_s(), 0.0, 2e-5);
  EXPECT_NEAR(ekf.track_ratio(), 1.0, 1e-3);  // no turn: little to learn about the track
  // 96 s of driving at 0.0075 rad/s: the encoders are 0.72 rad off; the filter's error is what the
  // first leg cost before the first stop told bias from E_d.
  EXPECT_NEAR(msgs::WrapAngle(encoder.pose().theta_rad - true_theta), -0.72, 0.01);
  EXPECT_LT(std::abs(msgs::WrapAngle(ekf.pose().theta_rad - true_theta)), 5e-3);
}

TEST(EkfOdometryTest, ACalibratedWheelDiameterPriorSplitsBiasFromEdWithoutStops) {
  // Straight at 0.3 m/s, never stopping, right wheels 1 % larger and a 0.005 rad/s gyro bias: the
  // encoders see a steady turn of -(2 v / b)(E_d - 1)/(E_d + 1) = -0.00746 rad/s, the gyro +0.005.
  // Bias acts per second and E_d per metre, so at constant speed nothing but the prior splits the
  // 0.01246 rad/s disagreement. With E_d held near the UMBmark value the bias state gets the true
  // bias; held near 1 it gets the whole disagreement, and the heading follows the encoders' turn.
  const double e_d = 1.01, bias = 0.005;
  const double encoder_turn_rate = -(2.0 * 0.3 / 0.4) * (e_d - 1.0) / (e_d + 1.0);
  const auto run = [&](double prior) {
    EkfOdometry ekf(NominalGeometry(),
                    {.increments = {},
                     .gyro_bias_sigma_rad_s = 0.05,
                     .wheel_diameter_ratio_sigma = 1e-4,
                     .wheel_diameter_ratio_prior = prior},
                    {});
    double true_theta = 0.0;
    DrivePhases({{60.0, 0.3, 0.0}}, 60.0, bias, 0.0, {.e_d = e_d},
                [&](const msgs::WheelEncoders& e, const msgs::GyroRate& w, double theta) {
                  ekf.AddEncoders(e);
                  ekf.AddGyro(w);
                  true_theta = theta;
                });
    return std::pair{ekf.bias_rad_s(), msgs::WrapAngle(ekf.pose().theta_rad - true_theta)};
  };
  const auto [calibrated_bias, calibrated_error] = run(e_d);
  EXPECT_NEAR(calibrated_bias, bias, 2e-4);
  EXPECT_LT(std::abs(calibrated_error), 0.01);
  const auto [uncalibrated_bias, uncalibrated_error] = run(1.0);
  EXPECT_NEAR(uncalibrated_bias, bias - encoder_turn_rate, 5e-4);
  EXPECT_NEAR(uncalibrated_error, encoder_turn_rate * 60.0, 0.03);  // -0.45 rad
}

TEST(EkfOdometryTest, ZeroVelocityUpdateRemovesAKnownBias) {
  // Standing still for 10 s with a 0.01 rad/s bias and no noise: the wheels do not move, so the
  // heading change is zero and the gyro's whole reading is bias. The filter must learn it, keep the
  // heading at 0, and carry the bias into the drive that follows.
  const double bias = 0.01;
  EkfOdometry ekf(NominalGeometry(), {.increments = {}, .gyro_bias_sigma_rad_s = 0.05}, {});
  GyroOdometry gyro(NominalGeometry(), {}, {});
  double bias_after_stop = 0.0, theta_after_stop = 0.0;
  double true_theta = 0.0;
  DrivePhases({{10.0, 0.0, 0.0}, {10.0, 0.3, 0.0}}, 20.0, bias, 0.0, {},
              [&](const msgs::WheelEncoders& e, const msgs::GyroRate& w, double theta) {
                ekf.AddEncoders(e);
                ekf.AddGyro(w);
                gyro.AddEncoders(e);
                gyro.AddGyro(w);
                true_theta = theta;
                if (std::abs(e.time_s - 10.0) < 1e-9) {
                  bias_after_stop = ekf.bias_rad_s();
                  theta_after_stop = ekf.pose().theta_rad;
                }
              });
  EXPECT_NEAR(bias_after_stop, bias, 1e-5);
  EXPECT_NEAR(theta_after_stop, 0.0, 1e-3);
  // The gyro alone integrates 20 s of bias: 0.2 rad; the filter stays on the true heading.
  EXPECT_NEAR(gyro.pose().theta_rad - true_theta, 0.2, 1e-3);
  EXPECT_LT(std::abs(ekf.pose().theta_rad - true_theta), 1e-3);
}

TEST(EkfOdometryTest, LeftAndRightTurnsSeparateTheTrackRatioFromTheBias) {
  // The real track is 3 % wider, the gyro exact but biased by 0.005 rad/s, and the robot never
  // stops: squares of 90 deg spot turns, alternately left and right. The bias shifts both turns
  // the same way, E_b scales them with their sign, so both are recovered.
  const double e_b = 1.03, bias = 0.005;
  EkfOdometry ekf(NominalGeometry(),
                  {.increments = {}, .gyro_bias_sigma_rad_s = 0.05, .track_ratio_sigma = 0.05}, {});
  double true_theta = 0.0;
  const double w = (kPi / 2.0) / 3.0;
  DrivePhases({{6.0, 0.3, 0.0}, {3.0, 0.0, w}, {6.0, 0.3, 0.0}, {3.0, 0.0, -w}}, 180.0, bias, 0.0,
              {.track_m = 0.4 * e_b},
              [&](const msgs::WheelEncoders& e, const msgs::GyroRate& g, double theta) {
                ekf.AddEncoders(e);
                ekf.AddGyro(g);
                true_theta = theta;
              });
  EXPECT_NEAR(ekf.track_ratio(), e_b, 1e-3);
  EXPECT_NEAR(ekf.bias_rad_s(), bias, 5e-5);
  EXPECT_NEAR(ekf.wheel_diameter_ratio(), 1.0, 1e-4);
  EXPECT_LT(std::abs(msgs::WrapAngle(ekf.pose().theta_rad - true_theta)), 5e-3);
}

// The stop-into-turn displacement (a calibration) is added once, in the frame of the approach
// heading, towards the outside of the turn; a stop before the turn does not trigger it.
TEST(EkfOdometryTest, AddsTheCalibratedStopDisplacementInTheApproachFrame) {
  const OdometryGeometry g{.left_wheel_radius_m = 0.1,
                           .right_wheel_radius_m = 0.1,
                           .track_m = 0.4,
                           .ticks_per_rev = 1000};
  const double along = -0.0025, outward = 0.003, heading = kPi / 6.0;
  const msgs::Pose2D start{1.0, 2.0, heading};
  for (const double turn : {1.0, -1.0}) {
    // 10 s at 0.4 m/s, then straight into a 90 deg turn on the spot in 4 s (exact sensors).
    const std::vector<Phase> phases{{10.0, 0.4, 0.0}, {4.0, 0.0, turn * (kPi / 2.0) / 4.0}};
    EkfOdometry plain(g, {}, start);
    EkfOdometry calibrated(g,
                           {.increments = {},
                            .stop_displacement_along_m = along,
                            .stop_displacement_outward_m = outward},
                           start);
    DrivePhases(phases, 13.9, 0.0, 0.0, {},
                [&](const msgs::WheelEncoders& e, const msgs::GyroRate& w, double) {
                  for (EkfOdometry* ekf : {&plain, &calibrated}) {
                    ekf->AddEncoders(e);
                    ekf->AddGyro(w);
                  }
                });
    EXPECT_EQ(calibrated.stops(), 1);
    // Outward is the robot's right (-y) in a left turn.
    const double lateral = -turn * outward;
    const double dx = along * std::cos(heading) - lateral * std::sin(heading);
    const double dy = along * std::sin(heading) + lateral * std::cos(heading);
    EXPECT_NEAR(calibrated.pose().x_m - plain.pose().x_m, dx, 1e-6) << "turn " << turn;
    EXPECT_NEAR(calibrated.pose().y_m - plain.pose().y_m, dy, 1e-6) << "turn " << turn;
    EXPECT_NEAR(calibrated.pose().theta_rad, plain.pose().theta_rad, 1e-9);
    // The plain filter ends where the robot is: 4 m along the heading (the turn is on the spot).
    EXPECT_NEAR(plain.pose().x_m, 1.0 + 4.0 * std::cos(heading), 2e-3);
    EXPECT_NEAR(plain.pose().y_m, 2.0 + 4.0 * std::sin(heading), 2e-3);
  }
  // Stopping first (2 s at rest) and then turning is no stop into a turn.
  EkfOdometry stopped(g,
                      {.increments = {},
                       .stop_displacement_along_m = along,
                       .stop_displacement_outward_m = outward},
                      start);
  DrivePhases({{10.0, 0.4, 0.0}, {2.0, 0.0, 0.0}, {4.0, 0.0, (kPi / 2.0) / 4.0}}, 15.9, 0.0, 0.0,
              {}, [&](const msgs::WheelEncoders& e, const msgs::GyroRate& w, double) {
                stopped.AddEncoders(e);
                stopped.AddGyro(w);
              });
  EXPECT_EQ(stopped.stops(), 0);
}

TEST(EkfOdometryTest, LeavesOutTheEncoderTurnOfABrakingTransient) {
  // Squares of 6 s legs at 0.3 m/s and 90 deg spot turns, all to the left, never standing still;
  // the gyro is exact but biased by 0.005 rad/s, the drive has no E_d / E_b error, but braking into
  // each turn its wheels turn 0.018 rad (1.03 deg) further than the body, in one interval (the
  // simulated P3-DX's stop into a spot turn). 20 turns: the encoders end 20 x 0.018 = 0.36 rad
  // off. Turning one way without stops, a filter that uses every encoder turn cannot tell that
  // excess from bias or E_b; with a 0.5 s braking window it leaves the first 5 intervals of each
  // turn out (the speed drops by 0.3 m/s in one interval) and the rest agree with the gyro's turns
  // up to the bias, which it finds.
  const double excess = 0.018, bias = 0.005;
  const double w = (kPi / 2.0) / 3.0;
  const auto run = [&](double window_s) {
    EkfOdometry ekf(NominalGeometry(),
                    {.increments = {}, .gyro_bias_sigma_rad_s = 0.05, .braking_window_s = window_s},
                    {});
    EncoderOdometry encoder(NominalGeometry(), EncoderOdometryOptions{}, {});
    double true_theta = 0.0;
    DrivePhases({{6.0, 0.3, 0.0}, {3.0, 0.0, w}}, 179.0, bias, 0.0,
                {.stop_turn_excess_rad = excess},
                [&](const msgs::WheelEncoders& e, const msgs::GyroRate& g, double theta) {
                  ekf.AddEncoders(e);
                  ekf.AddGyro(g);
                  encoder.AddEncoders(e);
                  true_theta = theta;
                });
    EXPECT_NEAR(msgs::WrapAngle(encoder.pose().theta_rad - true_theta), 20 * excess, 1e-3);
    return std::tuple{ekf.gated(), ekf.bias_rad_s(), ekf.track_ratio(),
                      msgs::WrapAngle(ekf.pose().theta_rad - true_theta)};
  };
  const auto [gated, gated_bias, gated_track, gated_error] = run(0.5);
  EXPECT_EQ(gated, 5 * 20);
  EXPECT_NEAR(gated_bias, bias, 5e-5);
  EXPECT_NEAR(gated_track, 1.0, 1e-3);
  EXPECT_LT(std::abs(gated_error), 3e-3);
  const auto [none, ungated_bias, ungated_track, ungated_error] = run(0.0);
  EXPECT_EQ(none, 0);
  // Without the window the filter splits the excess between E_b, bias and heading: the heading ends
  // a sizeable share of the encoders' 0.36 rad off.
  EXPECT_GT(std::abs(ungated_error), 0.05);
}

TEST(EkfOdometryTest, WeighsTheEncoderTurnOfAWheelSpeedChangeLess) {
  // Only the heading is uncertain (no bias, E_d, E_b, scale or slip uncertainty), so each
  // interval's update is scalar: the gyro's heading change g has variance q = sigma_g^2 tau dt, the
  // encoders' e has r, and the filter turns by g + q / (q + r) (e - g). From rest the robot starts
  // a spot turn: 10 ticks per wheel in 0.1 s (each wheel's speed changes by 0.0628 m/s) while the
  // body turns 2 mrad less than the encoders say (the wheels lead it). The next interval keeps the
  // wheel speeds (no change) and the encoders again report 1 mrad more than the gyro. r is the
  // quantisation 2 (tick / b)^2 / 12 plus, with the option, k^2 (dv_L^2 + dv_R^2) / b^2.
  const OdometryGeometry g = NominalGeometry();
  const double tick_m = 2.0 * kPi * 0.1 / 1000.0, track = 0.4, dt = 0.1, sigma_g = 0.02;
  const double encoder_turn = 2.0 * 10.0 * tick_m / track;  // per interval
  const double excess1 = 0.002, excess2 = 0.001;
  const double q = sigma_g * sigma_g * dt * dt;
  const double r_quantisation = 2.0 * std::pow(tick_m / track, 2) / 12.0;
  const double speed_change = 10.0 * tick_m / dt;
  const auto run = [&](double k) {
    EkfOdometry ekf(g,
                    {.increments = {},
                     .gyro_noise_rad_s = sigma_g,
                     .gyro_scale_sigma = 0.0,
                     .gyro_bias_sigma_rad_s = 0.0,
                     .gyro_bias_random_walk_rad_s_per_sqrt_s = 0.0,
                     .wheel_slip_sigma = 0.0,
                     .encoder_turn_sigma = 0.0,
                     .wheel_diameter_ratio_sigma = 0.0,
                     .track_ratio_sigma = 0.0,
                     .wheel_speed_change_sigma_s = k},
                    {});
    ekf.AddEncoders({0.0, 0, 0});
    ekf.AddGyro({0.0, 0.0});
    ekf.AddEncoders({0.1, -10, 10});
    ekf.AddGyro({0.1, (encoder_turn - excess1) / dt});
    const double after_first = ekf.pose().theta_rad;
    ekf.AddEncoders({0.2, -20, 20});
    ekf.AddGyro({0.2, (encoder_turn - excess2) / dt});
    return std::pair{after_first, ekf.pose().theta_rad - after_first};
  };
  for (const double k : {0.0, 0.01}) {
    const double r1 = r_quantisation + k * k * 2.0 * speed_change * speed_change / (track * track);
    const auto [first, second] = run(k);
    EXPECT_NEAR(first, encoder_turn - excess1 + q / (q + r1) * excess1, 1e-12) << "k " << k;
    // No speed change in the second interval: only the quantisation, whatever k.
    EXPECT_NEAR(second, encoder_turn - excess2 + q / (q + r_quantisation) * excess2, 1e-12)
        << "k " << k;
  }
  // Without the option the filter takes 91 % of the encoders' lead, with k = 10 ms 43 %.
  EXPECT_GT(run(0.0).first - (encoder_turn - excess1), 0.9 * excess1);
  EXPECT_LT(run(0.01).first - (encoder_turn - excess1), 0.45 * excess1);
}

}  // namespace
}  // namespace plywood::robot
