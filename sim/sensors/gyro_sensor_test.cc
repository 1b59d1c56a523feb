#include "sim/sensors/gyro_sensor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "msgs/pose2d.h"
#include "sim/world/scene.h"
#include "tests/support/mujoco_test_support.h"
#include "tests/support/options_test_support.h"

namespace plywood::sim {
namespace {

void ExpectInvalid(const GyroSensorOptions& options, const std::string& field) {
  plywood::testing::ExpectInvalidField(options, field);
}

TEST(GyroSensorTest, ValidateNamesTheField) {
  EXPECT_NO_THROW(GyroSensorOptions{}.Validate());
  ExpectInvalid({.rate_hz = 0.0}, "rate_hz");
  ExpectInvalid({.noise_sigma_rad_s = -1.0}, "noise_sigma_rad_s");
  ExpectInvalid({.bias_rad_s = std::nan("")}, "bias_rad_s");
  ExpectInvalid({.bias_random_walk_rad_s_per_sqrt_s = -0.1}, "bias_random_walk_rad_s_per_sqrt_s");
  ExpectInvalid({.scale_factor_error = -1.0}, "scale_factor_error");
  ExpectInvalid({.quantisation_rad_s = -0.01}, "quantisation_rad_s");
  EXPECT_THROW(GyroSensor({.rate_hz = -5.0}, 1), std::invalid_argument);
  EXPECT_DOUBLE_EQ(GyroSensor({.rate_hz = 100.0}, 1).period_s(), 0.01);
}

TEST(GyroSensorTest, NoiseFreeAppliesBiasAndScaleFactorExactly) {
  GyroSensor gyro({.noise_sigma_rad_s = 0.5,
                   .bias_rad_s = 0.003,
                   .bias_random_walk_rad_s_per_sqrt_s = 0.5,
                   .scale_factor_error = 0.01,
                   .noise_free = true},
                  9);
  for (int i = 0; i < 100; ++i) {
    const double rate = -2.0 + 0.04 * i;
    const msgs::GyroRate out = gyro.Measure(0.1 * i, rate);
    EXPECT_DOUBLE_EQ(out.time_s, 0.1 * i);
    EXPECT_DOUBLE_EQ(out.yaw_rate_rad_s, 1.01 * rate + 0.003);
  }
  GyroSensor ideal({.noise_sigma_rad_s = 0.0}, 1);
  EXPECT_EQ(ideal.Measure(0.0, 0.7).yaw_rate_rad_s, 0.7);
}

TEST(GyroSensorTest, QuantisesToTheNearestStep) {
  const double q = 0.01;
  GyroSensor gyro({.noise_sigma_rad_s = 0.0, .quantisation_rad_s = q}, 1);
  EXPECT_NEAR(gyro.Measure(0.0, 0.0149).yaw_rate_rad_s, 0.01, 1e-15);
  EXPECT_NEAR(gyro.Measure(0.1, 0.0151).yaw_rate_rad_s, 0.02, 1e-15);
  EXPECT_NEAR(gyro.Measure(0.2, -0.0149).yaw_rate_rad_s, -0.01, 1e-15);
  for (int i = 0; i < 200; ++i) {
    const double rate = 0.00123 * i - 0.1;
    const double out = gyro.Measure(0.3 + 0.1 * i, rate).yaw_rate_rad_s;
    EXPECT_NEAR(out / q, std::round(out / q), 1e-9);
    EXPECT_LE(std::abs(out - rate), q / 2 + 1e-12);
  }
}

TEST(GyroSensorTest, WhiteNoiseHasTheConfiguredMeanAndSigma) {
  const double sigma = 0.01, bias = 0.004, rate = 0.5;
  GyroSensor gyro({.noise_sigma_rad_s = sigma, .bias_rad_s = bias}, 2024);
  constexpr int kSamples = 100000;
  double sum = 0.0, sum_sq = 0.0, lag1 = 0.0, prev = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const double e = gyro.Measure(0.1 * i, rate).yaw_rate_rad_s - rate;
    sum += e;
    sum_sq += e * e;
    lag1 += (e - bias) * (prev - bias);
    prev = e;
  }
  const double mean = sum / kSamples;
  const double stddev = std::sqrt(sum_sq / kSamples - mean * mean);
  EXPECT_NEAR(mean, bias, 0.05 * bias);
  EXPECT_NEAR(stddev, sigma, 0.05 * sigma);
  EXPECT_NEAR(lag1 / kSamples / (sigma * sigma), 0.0, 0.02);  // white: uncorrelated samples
}

TEST(GyroSensorTest, BiasRandomWalkVarianceGrowsLinearlyWithTime) {
  // Many independent gyros at rest; their readings are their walked biases.
  const double walk = 0.001, period_s = 0.1;
  constexpr int kGyros = 4000, kShortSteps = 100, kLongSteps = 400;  // 10 s and 40 s
  double sum_short = 0, sq_short = 0, sum_long = 0, sq_long = 0;
  for (int g = 0; g < kGyros; ++g) {
    GyroSensor gyro({.noise_sigma_rad_s = 0.0, .bias_random_walk_rad_s_per_sqrt_s = walk},
                    static_cast<std::uint64_t>(g) + 1);
    double reading = gyro.Measure(0.0, 0.0).yaw_rate_rad_s;
    EXPECT_EQ(reading, 0.0);  // no time has passed yet
    for (int i = 1; i <= kLongSteps; ++i) {
      reading = gyro.Measure(i * period_s, 0.0).yaw_rate_rad_s;
      if (i == kShortSteps) sum_short += reading, sq_short += reading * reading;
    }
    sum_long += reading;
    sq_long += reading * reading;
  }
  const double var_short = sq_short / kGyros - std::pow(sum_short / kGyros, 2);
  const double var_long = sq_long / kGyros - std::pow(sum_long / kGyros, 2);
  // Sample variance of 4000 Gaussians is within ~2.2% (1 sigma) of the truth.
  EXPECT_NEAR(var_short, walk * walk * 10.0, 0.08 * walk * walk * 10.0);
  EXPECT_NEAR(var_long, walk * walk * 40.0, 0.08 * walk * walk * 40.0);
  EXPECT_NEAR(var_long / var_short, 4.0, 0.4);
}

TEST(GyroSensorTest, SameSeedSameNoise) {
  GyroSensor a({.noise_sigma_rad_s = 0.1}, 77), b({.noise_sigma_rad_s = 0.1}, 77),
      c({.noise_sigma_rad_s = 0.1}, 78);
  int differing = 0;
  for (int i = 0; i < 20; ++i) {
    const double ra = a.Measure(0.1 * i, 1.0).yaw_rate_rad_s;
    EXPECT_EQ(ra, b.Measure(0.1 * i, 1.0).yaw_rate_rad_s);
    differing += ra != c.Measure(0.1 * i, 1.0).yaw_rate_rad_s;
  }
  EXPECT_EQ(differing, 20);
}

TEST(GyroSensorTest, SamplesAverageTheTrueRateOverTheInterval) {
  const auto dir = testing::MakeTempDir("gyro_sensor");
  const auto world = testing::WriteFile(
      dir / "floor.xml",
      "<mujoco><worldbody><geom type=\"plane\" size=\"5 5 0.1\"/></worldbody></mujoco>\n");
  Scene scene({.world_mjcf = world,
               .robot_mjcf = testing::SourceRoot() / "models" / "p3dx.xml",
               .spawn = {.theta_rad = 3.0},
               .timestep_s = 0.01});
  GyroSensor gyro({.noise_free = true}, 1);
  EXPECT_EQ(gyro.Sample(scene).yaw_rate_rad_s, 0.0);  // at rest
  // A wobbling spin: the wheel speeds change every physics step, so an instantaneous 10 Hz
  // sample would alias; the interval average integrates to the true heading change.
  double integrated_rad = 0.0, true_change_rad = 0.0;
  msgs::Pose2D prev = scene.TruePose();
  for (int k = 1; k <= 50; ++k) {
    for (int i = 0; i < 10; ++i) {
      const double w = 3.0 + 2.0 * ((k * 10 + i) % 2 == 0 ? 1.0 : -1.0);
      scene.SetWheelSpeeds({-w, w});
      scene.Step();
      true_change_rad += msgs::WrapAngle(scene.TruePose().theta_rad - prev.theta_rad);
      prev = scene.TruePose();
    }
    const msgs::GyroRate sample = gyro.Sample(scene);
    EXPECT_NEAR(sample.time_s, 0.1 * k, 1e-9);
    integrated_rad += sample.yaw_rate_rad_s * 0.1;
  }
  EXPECT_GT(true_change_rad, 5.0);  // it turned past +-pi, so wrapping is exercised
  EXPECT_NEAR(integrated_rad, true_change_rad, 1e-6);
  // The instantaneous rate belongs to the same state as the pose, also while accelerating:
  // MuJoCo's semi-implicit Euler moves qpos with the new qvel, so over one step the heading changes
  // by exactly rate * dt.
  for (int i = 0; i < 20; ++i) {
    scene.SetWheelSpeeds({-0.3 * i, 0.3 * i});
    const double before = scene.TruePose().theta_rad;
    scene.Step();
    const double finite_difference = msgs::WrapAngle(scene.TruePose().theta_rad - before) / 0.01;
    EXPECT_NEAR(scene.TrueYawRateRadS(), finite_difference,
                1e-3 * std::abs(finite_difference) + 1e-9)
        << i;
  }
}

TEST(GyroSensorTest, PartialIntervalKeepsTheAngleRandomWalk) {
  // A read 30 ms after a full 100 ms sample (a robot reading its gyro when it stops): the heading
  // noise it adds, reading * dt, has the white-noise variance sigma^2 * period * dt, as a full
  // sample's sigma^2 * period^2 does.
  const double sigma = 0.01, period_s = 0.1, dt_s = 0.03;
  constexpr int kGyros = 20000;
  double sum = 0, sq = 0, sq_full = 0;
  for (int g = 0; g < kGyros; ++g) {
    GyroSensor gyro({.noise_sigma_rad_s = sigma}, static_cast<std::uint64_t>(g) + 1);
    gyro.Measure(0.0, 0.0);
    const double full = gyro.Measure(period_s, 0.0).yaw_rate_rad_s * period_s;
    const double angle = gyro.Measure(period_s + dt_s, 0.0).yaw_rate_rad_s * dt_s;
    sum += angle;
    sq += angle * angle;
    sq_full += full * full;
  }
  const double var = sq / kGyros - std::pow(sum / kGyros, 2);
  // Sample variance of 20000 Gaussians is within ~1% (1 sigma) of the truth.
  EXPECT_NEAR(var, sigma * sigma * period_s * dt_s, 0.05 * sigma * sigma * period_s * dt_s);
  EXPECT_NEAR(sq_full / kGyros, sigma * sigma * period_s * period_s,
              0.05 * sigma * sigma * period_s * period_s);
}

}  // namespace
}  // namespace plywood::sim
