#include "robot/odometry/encoder_odometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace plywood::robot {
namespace {

constexpr double kPi = std::numbers::pi;

DiffDriveSpec TestSpec() {
  DiffDriveSpec spec;
  spec.wheel_radius_m = 0.1;
  spec.track_m = 0.4;
  spec.encoder_ticks_per_rev = 1000;
  return spec;
}

TEST(EncoderOdometryTest, StraightLineOfWholeRevolutions) {
  EncoderOdometry odometry(TestSpec(), {1.0, 2.0, kPi / 2.0});
  odometry.Update({0.0, 0, 0});
  odometry.Update({1.0, 3000, 3000});  // three revolutions: 3 * 2 pi * 0.1 m
  EXPECT_NEAR(odometry.pose().x_m, 1.0, 1e-12);
  EXPECT_NEAR(odometry.pose().y_m, 2.0 + 0.6 * kPi, 1e-12);
  EXPECT_NEAR(odometry.pose().theta_rad, kPi / 2.0, 1e-12);
}

TEST(EncoderOdometryTest, OnTheSpotQuarterTurn) {
  // Each wheel travels a quarter of the track circle: pi * 0.4 / 4 = 0.1 pi m = 500 ticks.
  EncoderOdometry odometry(TestSpec(), {});
  odometry.Update({0.0, 0, 0});
  for (int i = 1; i <= 100; ++i) odometry.Update({0.01 * i, -5 * i, 5 * i});
  EXPECT_NEAR(odometry.pose().x_m, 0.0, 1e-12);
  EXPECT_NEAR(odometry.pose().y_m, 0.0, 1e-12);
  EXPECT_NEAR(odometry.pose().theta_rad, kPi / 2.0, 1e-12);
}

}  // namespace
}  // namespace plywood::robot
