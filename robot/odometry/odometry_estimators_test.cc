// Closed-form checks of the dead-reckoning estimators (seed 004 eqs. 3-5 and the EKF): noise-free
// constant-curvature arcs and spot turns, the dead band, counter wrap, gains and sensor timing.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "robot/odometry/ekf_odometry.h"
#include "robot/odometry/encoder_odometry.h"
#include "robot/odometry/fused_odometry.h"
#include "robot/odometry/gyro_odometry.h"
#include "robot/odometry/weighted_fused_odometry.h"

namespace plywood::robot {
namespace {

constexpr double kPi = std::numbers::pi;

// r = 0.1 m, b = 0.4 m, 1000 ticks per revolution: one tick is 0.2 pi mm of travel.
OdometryGeometry TestGeometry() {
  return {.left_wheel_radius_m = 0.1,
          .right_wheel_radius_m = 0.1,
          .track_m = 0.4,
          .ticks_per_rev = 1000};
}
constexpr double kTick_m = 2.0 * kPi * 0.1 / 1000.0;

using Factory = std::function<std::unique_ptr<OdometryEstimator>(const IncrementOptions&)>;

struct Named {
  std::string name;
  Factory make;
};

std::vector<Named> AllEstimators() {
  const OdometryGeometry g = TestGeometry();
  return {
      {"encoder",
       [g](const IncrementOptions& o) {
         return std::make_unique<EncoderOdometry>(g, EncoderOdometryOptions{.increments = o},
                                                  msgs::Pose2D{});
       }},
      {"gyro",
       [g](const IncrementOptions& o) {
         return std::make_unique<GyroOdometry>(g, GyroOdometryOptions{.increments = o},
                                               msgs::Pose2D{});
       }},
      {"fused",
       [g](const IncrementOptions& o) {
         return std::make_unique<FusedOdometry>(g, FusedOdometryOptions{.increments = o},
                                                msgs::Pose2D{});
       }},
      {"weighted",
       [g](const IncrementOptions& o) {
         return std::make_unique<WeightedFusedOdometry>(
             g, WeightedFusedOdometryOptions{.increments = o}, msgs::Pose2D{});
       }},
      {"ekf",
       [g](const IncrementOptions& o) {
         return std::make_unique<EkfOdometry>(g, EkfOdometryOptions{.increments = o},
                                              msgs::Pose2D{});
       }},
  };
}

// Feeds `steps` samples at 10 Hz in which the wheels advance left/right ticks each; the gyro
// (sampled `gyro_per_encoder` times per encoder sample) reads the true yaw rate plus bias.
void Drive(OdometryEstimator& estimator, int steps, int left_ticks, int right_ticks,
           int gyro_per_encoder = 1, double gyro_bias_rad_s = 0.0, bool gyro_first = false) {
  const double dt = 0.1;
  const double rate = (right_ticks - left_ticks) * kTick_m / 0.4 / dt;
  estimator.AddEncoders({0.0, 0, 0});
  estimator.AddGyro({0.0, rate + gyro_bias_rad_s});
  for (int k = 1; k <= steps; ++k) {
    const msgs::WheelEncoders encoders{k * dt, std::int64_t{k} * left_ticks,
                                       std::int64_t{k} * right_ticks};
    if (!gyro_first) estimator.AddEncoders(encoders);
    for (int j = 1; j <= gyro_per_encoder; ++j) {
      estimator.AddGyro({(k - 1) * dt + j * dt / gyro_per_encoder, rate + gyro_bias_rad_s});
    }
    if (gyro_first) estimator.AddEncoders(encoders);
  }
}

TEST(OdometryEstimatorsTest, ConstantCurvatureArcIsExactWithArcIntegration) {
  // 10 and 20 ticks per 0.1 s: ds = 15 ticks, dtheta = 10 ticks / 0.4 m per step.
  const int steps = 200;
  const double ds = 15 * kTick_m, dtheta = 10 * kTick_m / 0.4;
  const double theta = steps * dtheta, radius = ds / dtheta;
  for (const Named& e : AllEstimators()) {
    for (int gyro_rate : {1, 5}) {
      auto estimator = e.make({.integration = Integration::kArc});
      Drive(*estimator, steps, 10, 20, gyro_rate);
      const msgs::Pose2D pose = estimator->pose();
      EXPECT_NEAR(pose.x_m, radius * std::sin(theta), 1e-9) << e.name << " gyro x" << gyro_rate;
      EXPECT_NEAR(pose.y_m, radius * (1.0 - std::cos(theta)), 1e-9) << e.name;
      // theta is pi here: compare the wrapped difference, not two values either side of the cut.
      EXPECT_NEAR(msgs::WrapAngle(pose.theta_rad - theta), 0.0, 1e-9) << e.name;
    }
  }
}

TEST(OdometryEstimatorsTest, MidpointOvershootsArcsByTheChordFactor) {
  // Seed 004 eq. 3 moves ds along the mid heading, the direction of the arc's chord, but the chord
  // is only ds sinc(dtheta/2) long: the steps overshoot, and the vertices lie exactly on a circle
  // of radius ds / (2 sin(dtheta/2)), larger than the true ds / dtheta by 1 / sinc(dtheta/2).
  const int steps = 200;
  const double ds = 15 * kTick_m, dtheta = 10 * kTick_m / 0.4;
  const double shrink = std::sin(dtheta / 2.0) / (dtheta / 2.0);
  const double theta = steps * dtheta, radius = ds / dtheta / shrink;
  for (const Named& e : AllEstimators()) {
    auto estimator = e.make({});
    Drive(*estimator, steps, 10, 20);
    const msgs::Pose2D pose = estimator->pose();
    EXPECT_NEAR(pose.x_m, radius * std::sin(theta), 1e-9) << e.name;
    EXPECT_NEAR(pose.y_m, radius * (1.0 - std::cos(theta)), 1e-9) << e.name;
    EXPECT_NEAR(pose.theta_rad, msgs::WrapAngle(theta), 1e-9) << e.name;
  }
}

TEST(OdometryEstimatorsTest, OnTheSpotTurnIsExact) {
  // A quarter of the track circle per wheel, pi * 0.4 / 4 m = 500 ticks, in 100 steps.
  for (const Named& e : AllEstimators()) {
    for (Integration integration : {Integration::kMidpoint, Integration::kArc}) {
      auto estimator = e.make({.integration = integration});
      Drive(*estimator, 100, -5, 5, 2, 0.0, /*gyro_first=*/true);
      EXPECT_NEAR(estimator->pose().x_m, 0.0, 1e-12) << e.name;
      EXPECT_NEAR(estimator->pose().y_m, 0.0, 1e-12) << e.name;
      EXPECT_NEAR(estimator->pose().theta_rad, kPi / 2.0, 1e-12) << e.name;
    }
  }
}

TEST(OdometryEstimatorsTest, GyroWaitsUntilItCoversTheEncoderInterval) {
  // A gyro-based estimate never uses a half-known interval: after the encoder reading alone it has
  // not moved, after the gyro reading it has.
  GyroOdometry odometry(TestGeometry(), {}, {});
  odometry.AddEncoders({0.0, 0, 0});
  odometry.AddGyro({0.0, 0.0});
  odometry.AddEncoders({0.1, 100, 100});
  EXPECT_EQ(odometry.pose().x_m, 0.0);
  odometry.AddGyro({0.1, 0.0});
  EXPECT_NEAR(odometry.pose().x_m, 100 * kTick_m, 1e-12);
}

TEST(OdometryEstimatorsTest, GyroBiasTurnsGyroHeadingButNotEncoderHeading) {
  const double bias = 0.01;  // rad/s over 20 s of straight driving: 0.2 rad
  auto encoder = AllEstimators()[0].make({});
  auto gyro = AllEstimators()[1].make({});
  auto fused = AllEstimators()[2].make({});
  Drive(*encoder, 200, 10, 10, 1, bias);
  Drive(*gyro, 200, 10, 10, 1, bias);
  Drive(*fused, 200, 10, 10, 1, bias);
  EXPECT_NEAR(encoder->pose().theta_rad, 0.0, 1e-12);
  EXPECT_NEAR(gyro->pose().theta_rad, 0.2, 1e-9);
  EXPECT_NEAR(fused->pose().theta_rad, 0.1, 1e-9);  // eq. 4: the mean
}

TEST(OdometryEstimatorsTest, GainsScaleTheHeadingChange) {
  const OdometryGeometry g = TestGeometry();
  EncoderOdometry encoder(g, {.increments = {}, .gain = 1.1}, {});
  GyroOdometry gyro(g, {.increments = {}, .gain = 0.9}, {});
  WeightedFusedOdometry weighted(g, {.increments = {}, .encoder_gain = 1.2, .gyro_gain = 0.6}, {});
  Drive(encoder, 100, -5, 5);
  Drive(gyro, 100, -5, 5);
  Drive(weighted, 100, -5, 5);
  EXPECT_NEAR(encoder.pose().theta_rad, 1.1 * kPi / 2.0, 1e-12);
  EXPECT_NEAR(gyro.pose().theta_rad, 0.9 * kPi / 2.0, 1e-12);
  EXPECT_NEAR(weighted.pose().theta_rad, (1.2 + 0.6) / 2.0 * kPi / 2.0, 1e-12);  // eq. 5
}

TEST(OdometryEstimatorsTest, DeadBandZeroesSmallChanges) {
  // Seed 004's threshold 0.01 rad: a 0.6 deg heading change per sample is dropped, so a gentle
  // arc is integrated as a straight line, while wheel angles (0.06 rad per sample) pass.
  EncoderOdometry odometry(TestGeometry(), {.increments = {.dead_band_rad = 0.01}}, {});
  Drive(odometry, 100, 9, 11);  // dtheta = 2 ticks / 0.4 m = 0.00314 rad per sample
  EXPECT_EQ(odometry.pose().theta_rad, 0.0);
  EXPECT_NEAR(odometry.pose().x_m, 100 * 10 * kTick_m, 1e-12);
  // Wheel angle increments of 1 tick (0.0063 rad) are below it too: nothing moves.
  EncoderOdometry creeping(TestGeometry(), {.increments = {.dead_band_rad = 0.01}}, {});
  Drive(creeping, 100, 1, 1);
  EXPECT_EQ(creeping.pose().x_m, 0.0);
}

TEST(OdometryEstimatorsTest, CounterWrapIsUnwrapped) {
  // A 16-bit counter: 65530 -> 4 is +10 ticks, 4 -> 65530 is -10.
  EncoderOdometry odometry(TestGeometry(), {.increments = {.counter_modulus = 65536}}, {});
  odometry.AddEncoders({0.0, 65530, 65530});
  odometry.AddEncoders({0.1, 4, 4});
  EXPECT_NEAR(odometry.pose().x_m, 10 * kTick_m, 1e-12);
  odometry.AddEncoders({0.2, 65530, 65530});
  EXPECT_NEAR(odometry.pose().x_m, 0.0, 1e-12);
  // Without the modulus the same readings are a jump of almost a whole counter.
  EncoderOdometry naive(TestGeometry(), {}, {});
  naive.AddEncoders({0.0, 65530, 65530});
  naive.AddEncoders({0.1, 4, 4});
  EXPECT_NEAR(naive.pose().x_m, -65526 * kTick_m, 1e-9);
}

TEST(OdometryEstimatorsTest, ANonFiniteGyroSampleIsADroppedSample) {
  // A quarter turn on the spot with one NaN and one inf sample from the gyro's driver in between:
  // the next good sample's mean rate covers the gap, as if the bad one never came. They poisoned
  // the integrated gyro angle for good: every later pose was NaN.
  for (const Named& e : AllEstimators()) {
    if (e.name == "encoder") continue;
    auto estimator = e.make({});
    const double rate = 10 * kTick_m / 0.4 / 0.1;
    estimator->AddEncoders({0.0, 0, 0});
    estimator->AddGyro({0.0, rate});
    for (int k = 1; k <= 100; ++k) {
      if (k == 30) estimator->AddGyro({(k - 0.5) * 0.1, std::nan("")});
      if (k == 60) estimator->AddGyro({(k - 0.5) * 0.1, HUGE_VAL});
      estimator->AddGyro({k * 0.1, rate});
      estimator->AddEncoders({k * 0.1, -5 * k, 5 * k});
    }
    EXPECT_NEAR(estimator->pose().theta_rad, kPi / 2.0, 1e-9) << e.name;
    EXPECT_NEAR(estimator->pose().x_m, 0.0, 1e-9) << e.name;
  }
}

TEST(OdometryEstimatorsTest, AnEncoderReadingOutOfTimeOrderIsDropped) {
  // 1000 ticks straight ahead in 100 readings; the driver repeats a timestamp (with new counts),
  // steps back in time and sends a NaN time. The counts are cumulative, so a dropped reading loses
  // no motion: the next good one carries it. The EKF lost the motion of a repeated or backward
  // timestamp (dt <= 0 skipped its step): 0.603 m of the 0.628 m driven.
  for (const Named& e : AllEstimators()) {
    auto estimator = e.make({});
    estimator->AddEncoders({0.0, 0, 0});
    estimator->AddGyro({0.0, 0.0});
    for (int k = 1; k <= 100; ++k) {
      estimator->AddGyro({k * 0.1, 0.0});
      double time_s = k * 0.1;
      if (k == 30) time_s = 29 * 0.1;      // repeats the previous reading's time
      if (k == 50) time_s = 40 * 0.1;      // goes back in time
      if (k == 70) time_s = std::nan("");  // no time at all
      estimator->AddEncoders({time_s, 10 * k, 10 * k});
    }
    EXPECT_NEAR(estimator->pose().x_m, 1000 * kTick_m, 1e-9) << e.name;
    EXPECT_NEAR(estimator->pose().y_m, 0.0, 1e-12) << e.name;
    EXPECT_NEAR(estimator->pose().theta_rad, 0.0, 1e-12) << e.name;
  }
}

TEST(OdometryEstimatorsTest, ACounterJumpOnlyAWrapExplainsIsRefused) {
  // An int32 counter wrapping from 2^31 - 1 to -2^31 without counter_modulus: 2^32 ticks in one
  // reading, 2700 km of travel for these wheels, was integrated as motion. A jump of 2^31 ticks
  // or more is refused, naming the field; with counter_modulus = 2^32 the wrap is +1 tick.
  for (const Named& e : AllEstimators()) {
    auto estimator = e.make({});
    estimator->AddEncoders({0.0, 2147483647, 0});
    estimator->AddGyro({0.0, 0.0});
    estimator->AddGyro({0.1, 0.0});
    try {
      estimator->AddEncoders({0.1, -2147483648LL, 0});
      ADD_FAILURE() << e.name << ": no throw, pose x " << estimator->pose().x_m;
    } catch (const std::invalid_argument& error) {
      EXPECT_EQ(std::string(error.what()).rfind("left_ticks:", 0), 0u) << error.what();
      EXPECT_NE(std::string(error.what()).find("-2147483648"), std::string::npos) << error.what();
    }
    auto wrapping = e.make({.counter_modulus = std::uint64_t{1} << 32});
    wrapping->AddEncoders({0.0, 2147483647, 2147483647});
    wrapping->AddGyro({0.0, 0.0});
    wrapping->AddGyro({0.1, 0.0});
    wrapping->AddEncoders({0.1, -2147483648LL, -2147483648LL});
    EXPECT_NEAR(wrapping->pose().x_m, kTick_m, 1e-12) << e.name;
  }
  // A modulus past what an int64 delta can hold was cast to a negative one: every delta was 0.
  try {
    IncrementOptions{.counter_modulus = ~std::uint64_t{0}}.Validate();
    ADD_FAILURE() << "no throw";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()).rfind("counter_modulus:", 0), 0u) << error.what();
  }
}

TEST(OdometryEstimatorsTest, CalibratedGeometryFollowsBorenstein) {
  DiffDriveSpec nominal;
  nominal.wheel_radius_m = 0.1;
  nominal.track_m = 0.4;
  const OdometryGeometry g =
      CalibratedGeometry(nominal, {.wheel_diameter_ratio = 1.01, .track_ratio = 1.05});
  EXPECT_NEAR(g.right_wheel_radius_m / g.left_wheel_radius_m, 1.01, 1e-12);
  EXPECT_NEAR((g.right_wheel_radius_m + g.left_wheel_radius_m) / 2.0, 0.1, 1e-12);
  EXPECT_NEAR(g.track_m, 0.42, 1e-12);
}

TEST(OdometryEstimatorsTest, OptionsRejectBadValuesNamingTheField) {
  const auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no throw");
  };
  EXPECT_EQ(message([] {
              EncoderOdometryOptions{.increments = {}, .gain = std::nan("")}.Validate();
            }).rfind("gain:", 0),
            0u);
  EXPECT_EQ(message([] {
              WeightedFusedOdometryOptions{.increments = {}, .gyro_gain = -1}.Validate();
            }).rfind("gyro_gain:", 0),
            0u);
  EXPECT_EQ(message([] {
              IncrementOptions{.dead_band_rad = -0.1}.Validate();
            }).rfind("dead_band_rad:", 0),
            0u);
  EXPECT_EQ(message([] {
              EkfOdometryOptions{.increments = {}, .gyro_noise_rad_s = 0}.Validate();
            }).rfind("gyro_noise_rad_s:", 0),
            0u);
  EXPECT_EQ(message([] {
              EkfOdometryOptions{.increments = {}, .gyro_gain = 0}.Validate();
            }).rfind("gyro_gain:", 0),
            0u);
  EXPECT_EQ(message([] {
              EkfOdometryOptions{.increments = {}, .track_ratio_sigma = 0.5}.Validate();
            }).rfind("track_ratio_sigma:", 0),
            0u);
  EXPECT_EQ(message([] {
              EkfOdometryOptions{.increments = {}, .zero_velocity_turn_sigma_rad = 0}.Validate();
            }).rfind("zero_velocity_turn_sigma_rad:", 0),
            0u);
  EXPECT_EQ(
      message([] {
        EkfOdometryOptions{.increments = {}, .wheel_diameter_ratio_prior = std::nan("")}.Validate();
      }).rfind("wheel_diameter_ratio_prior:", 0),
      0u);
  EXPECT_EQ(message([] {
              EkfOdometryOptions{.increments = {}, .track_ratio_prior = 1.5}.Validate();
            }).rfind("track_ratio_prior:", 0),
            0u);
  EXPECT_EQ(message([] {
              EkfOdometryOptions{.increments = {}, .stop_displacement_outward_m = 0.5}.Validate();
            }).rfind("stop_displacement_outward_m:", 0),
            0u);
  EXPECT_EQ(message([] {
              EkfOdometryOptions{.increments = {}, .stop_displacement_sigma_m = -1}.Validate();
            }).rfind("stop_displacement_sigma_m:", 0),
            0u);
  EXPECT_EQ(message([] {
              EkfOdometryOptions{.increments = {}, .braking_window_s = -1}.Validate();
            }).rfind("braking_window_s:", 0),
            0u);
  EXPECT_EQ(message([] {
              EkfOdometryOptions{.increments = {}, .wheel_speed_change_sigma_s = -1}.Validate();
            }).rfind("wheel_speed_change_sigma_s:", 0),
            0u);
  EXPECT_EQ(
      message([] { OdometryCalibration{.track_ratio = 3}.Validate(); }).rfind("track_ratio:", 0),
      0u);
  EXPECT_EQ(ParseIntegration("arc"), Integration::kArc);
  EXPECT_EQ(message([] { ParseIntegration("euler"); }).rfind("integration:", 0), 0u);
}

}  // namespace
}  // namespace plywood::robot
