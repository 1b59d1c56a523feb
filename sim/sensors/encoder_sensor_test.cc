#include "sim/sensors/encoder_sensor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/world/scene.h"
#include "tests/support/mujoco_test_support.h"
#include "tests/support/options_test_support.h"

namespace plywood::sim {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::int64_t ExpectedTicks(double angle_rad, int ticks_per_rev) {
  return static_cast<std::int64_t>(std::floor(angle_rad / kTwoPi * ticks_per_rev));
}

void ExpectInvalid(const EncoderSensorOptions& options, const std::string& field) {
  plywood::testing::ExpectInvalidField(options, field);
}

TEST(EncoderSensorTest, ValidateNamesTheField) {
  EXPECT_NO_THROW(EncoderSensorOptions{}.Validate());
  EXPECT_EQ(EncoderSensorOptions{}.ticks_per_rev, robot::P3dxSpec().encoder_ticks_per_rev);
  ExpectInvalid({.ticks_per_rev = 0}, "ticks_per_rev");
  ExpectInvalid({.rate_hz = -1.0}, "rate_hz");
  ExpectInvalid({.rate_hz = std::nan("")}, "rate_hz");
  ExpectInvalid({.slip_sigma = -0.1}, "slip_sigma");
  EXPECT_THROW(EncoderSensor({.rate_hz = 0.0}, 1), std::invalid_argument);
  EXPECT_DOUBLE_EQ(EncoderSensor({.rate_hz = 20.0}, 1).period_s(), 0.05);
}

TEST(EncoderSensorTest, TicksAreTheFloorOfTheContinuousCount) {
  const int tpr = 800;
  EncoderSensor encoder({.ticks_per_rev = tpr}, 7);
  const msgs::WheelEncoders zero = encoder.Measure(0.0, 0.0, 0.0);
  EXPECT_EQ(zero.left_ticks, 0);
  EXPECT_EQ(zero.right_ticks, 0);
  // Whole revolutions and half-tick positions, forwards and backwards.
  for (int n = -5; n <= 5; ++n) {
    const msgs::WheelEncoders e = encoder.Measure(1.0, n * kTwoPi, (n + 0.5 / tpr) * kTwoPi);
    EXPECT_EQ(e.left_ticks, n * tpr) << n;
    EXPECT_EQ(e.right_ticks, n * tpr) << n;
  }
  const msgs::WheelEncoders back = encoder.Measure(2.0, -0.5 / tpr * kTwoPi, 1.5 / tpr * kTwoPi);
  EXPECT_EQ(back.left_ticks, -1);  // floor, not truncation towards zero
  EXPECT_EQ(back.right_ticks, 1);
  EXPECT_DOUBLE_EQ(back.time_s, 2.0);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> angle(-100.0, 100.0);
  for (int i = 0; i < 1000; ++i) {
    const double l = angle(rng), r = angle(rng);
    const msgs::WheelEncoders e = encoder.Measure(3.0, l, r);
    ASSERT_EQ(e.left_ticks, ExpectedTicks(l, tpr)) << l;
    ASSERT_EQ(e.right_ticks, ExpectedTicks(r, tpr)) << r;
  }
}

TEST(EncoderSensorTest, CountsFromTheAnglesAtTheFirstSample) {
  const int tpr = robot::P3dxSpec().encoder_ticks_per_rev;
  EncoderSensor encoder({}, 1);
  const msgs::WheelEncoders first = encoder.Measure(0.0, 12.3, -4.5);
  EXPECT_EQ(first.left_ticks, 0);
  EXPECT_EQ(first.right_ticks, 0);
  const msgs::WheelEncoders later = encoder.Measure(0.1, 12.3 + kTwoPi, -4.5 - kTwoPi);
  EXPECT_NEAR(later.left_ticks, tpr, 1);
  EXPECT_NEAR(later.right_ticks, -tpr, 1);
}

TEST(EncoderSensorTest, QuantisationErrorIsUniformOverOneTick) {
  const int tpr = 800;
  EncoderSensor encoder({.ticks_per_rev = tpr}, 1);
  encoder.Measure(0.0, 0.0, 0.0);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(0.0, 1000.0);
  constexpr int kBins = 10, kSamples = 100000;
  std::vector<int> histogram(kBins, 0);
  double sum = 0.0, sum_sq = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const double a = angle(rng);
    const double error =
        a / kTwoPi * tpr - static_cast<double>(encoder.Measure(0.1, a, a).left_ticks);
    ASSERT_GE(error, 0.0);
    ASSERT_LT(error, 1.0);
    ++histogram[static_cast<int>(error * kBins)];
    sum += error;
    sum_sq += error * error;
  }
  const double mean = sum / kSamples;
  EXPECT_NEAR(mean, 0.5, 0.005);
  EXPECT_NEAR(sum_sq / kSamples - mean * mean, 1.0 / 12.0, 0.002);
  double chi_square = 0.0;
  const double expected = static_cast<double>(kSamples) / kBins;
  for (int count : histogram) chi_square += (count - expected) * (count - expected) / expected;
  EXPECT_LT(chi_square, 27.9);  // chi-square, 9 degrees of freedom, p = 0.001
}

TEST(EncoderSensorTest, QuantisationDoesNotDrift) {
  // 0.37 ticks per sample for 100000 samples: per-sample rounding would be off by thousands.
  const int tpr = 1000;
  EncoderSensor encoder({.ticks_per_rev = tpr}, 1);
  const double step_rad = 0.37 / tpr * kTwoPi;
  msgs::WheelEncoders e;
  for (int i = 0; i <= 100000; ++i) e = encoder.Measure(i * 0.1, i * step_rad, -i * step_rad);
  EXPECT_EQ(e.left_ticks, ExpectedTicks(100000 * step_rad, tpr));
  EXPECT_NEAR(static_cast<double>(e.left_ticks), 37000.0, 1.0);
  EXPECT_NEAR(static_cast<double>(e.right_ticks), -37000.0, 1.0);
}

TEST(EncoderSensorTest, SlipHasTheConfiguredStatistics) {
  const double sigma = 0.05, step_rad = 1.0;
  const int tpr = 10000;
  EncoderSensor encoder({.ticks_per_rev = tpr, .slip_sigma = sigma}, 42);
  msgs::WheelEncoders prev = encoder.Measure(0.0, 0.0, 0.0);
  const double rolled_ticks = step_rad / kTwoPi * tpr;
  constexpr int kSamples = 20000;
  double sum_l = 0, sum_r = 0, sq_l = 0, sq_r = 0, cross = 0;
  for (int i = 1; i <= kSamples; ++i) {
    const msgs::WheelEncoders e = encoder.Measure(0.1 * i, i * step_rad, i * step_rad);
    // Per-sample slip estimate; quantisation adds at most 1/1591 of a rotation.
    const double s_l = (e.left_ticks - prev.left_ticks) / rolled_ticks - 1.0;
    const double s_r = (e.right_ticks - prev.right_ticks) / rolled_ticks - 1.0;
    sum_l += s_l, sum_r += s_r, sq_l += s_l * s_l, sq_r += s_r * s_r, cross += s_l * s_r;
    prev = e;
  }
  const double n = kSamples;
  EXPECT_NEAR(sum_l / n, 0.0, 4.0 * sigma / std::sqrt(n));
  EXPECT_NEAR(sum_r / n, 0.0, 4.0 * sigma / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sq_l / n), sigma, 0.05 * sigma);
  EXPECT_NEAR(std::sqrt(sq_r / n), sigma, 0.05 * sigma);
  EXPECT_NEAR(cross / n / (sigma * sigma), 0.0, 0.05);  // independent per wheel
}

TEST(EncoderSensorTest, SlipNeedsRotationAndNoiseFreeTurnsItOff) {
  EncoderSensor still({.ticks_per_rev = 1000, .slip_sigma = 0.3}, 5);
  for (int i = 0; i < 100; ++i) {
    const msgs::WheelEncoders e = still.Measure(0.1 * i, 1.0, 2.0);
    ASSERT_EQ(e.left_ticks, 0);
    ASSERT_EQ(e.right_ticks, 0);
  }
  EncoderSensor noise_free({.ticks_per_rev = 1000, .slip_sigma = 0.3, .noise_free = true}, 5);
  EncoderSensor noisy({.ticks_per_rev = 1000, .slip_sigma = 0.3}, 5);
  EncoderSensor same_seed({.ticks_per_rev = 1000, .slip_sigma = 0.3}, 5);
  noise_free.Measure(0.0, 0.0, 0.0);
  noisy.Measure(0.0, 0.0, 0.0);
  same_seed.Measure(0.0, 0.0, 0.0);
  int differing = 0;
  for (int i = 1; i <= 50; ++i) {
    const double a = 0.5 * i;
    const msgs::WheelEncoders ideal = noise_free.Measure(0.1 * i, a, -a);
    EXPECT_EQ(ideal.left_ticks, ExpectedTicks(a, 1000));
    EXPECT_EQ(ideal.right_ticks, ExpectedTicks(-a, 1000));
    const msgs::WheelEncoders slipped = noisy.Measure(0.1 * i, a, -a);
    const msgs::WheelEncoders repeat = same_seed.Measure(0.1 * i, a, -a);
    EXPECT_EQ(slipped.left_ticks, repeat.left_ticks);
    EXPECT_EQ(slipped.right_ticks, repeat.right_ticks);
    differing += slipped.left_ticks != ideal.left_ticks;
  }
  EXPECT_GT(differing, 40);
}

TEST(EncoderSensorTest, ReadsTheScenesWheelJoints) {
  const auto dir = testing::MakeTempDir("encoder_sensor");
  const auto world = testing::WriteFile(
      dir / "floor.xml",
      "<mujoco><worldbody><geom type=\"plane\" size=\"5 5 0.1\"/></worldbody></mujoco>\n");
  Scene scene({.world_mjcf = world,
               .robot_mjcf = testing::SourceRoot() / "models" / "p3dx.xml",
               .spawn = {},
               .timestep_s = 0.01});
  const int tpr = robot::P3dxSpec().encoder_ticks_per_rev;
  EncoderSensor encoder({.noise_free = true}, 1);
  const double left0 = scene.LeftWheelAngleRad(), right0 = scene.RightWheelAngleRad();
  encoder.Sample(scene);
  scene.SetWheelSpeeds({2.0, 3.0});
  for (int i = 0; i < 100; ++i) scene.Step();
  const msgs::WheelEncoders e = encoder.Sample(scene);
  EXPECT_DOUBLE_EQ(e.time_s, scene.time_s());
  EXPECT_GT(e.left_ticks, 0);
  EXPECT_GT(e.right_ticks, e.left_ticks);
  EXPECT_EQ(e.left_ticks, ExpectedTicks(scene.LeftWheelAngleRad() - left0, tpr));
  EXPECT_EQ(e.right_ticks, ExpectedTicks(scene.RightWheelAngleRad() - right0, tpr));
}

}  // namespace
}  // namespace plywood::sim
