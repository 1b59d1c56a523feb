#include "sim/sensors/sensor_schedule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace plywood::sim {
namespace {

// Steps a clock the way MuJoCo does (time += timestep) and returns the step indices at which the
// schedule fired.
std::vector<long> FiringSteps(SensorSchedule* schedule, double timestep_s, long steps) {
  std::vector<long> fired;
  double time_s = 0.0;
  for (long n = 0; n <= steps; ++n) {
    if (schedule->Due(time_s)) fired.push_back(n);
    time_s += timestep_s;
  }
  return fired;
}

TEST(SensorScheduleTest, CommensurateRateFiresEveryNthStepWithoutDrift) {
  SensorSchedule schedule(10.0);
  // 100 s of a 10 ms clock: time is a running sum, so 0.1 s arrives slightly early or late.
  const std::vector<long> fired = FiringSteps(&schedule, 0.01, 10000);
  ASSERT_EQ(fired.size(), 1001u);
  for (std::size_t k = 0; k < fired.size(); ++k) EXPECT_EQ(fired[k], 10 * static_cast<long>(k));
}

TEST(SensorScheduleTest, IncommensurateRateFiresOnFirstStepAtOrAfterIdealTime) {
  SensorSchedule schedule(3.0);
  const std::vector<long> fired = FiringSteps(&schedule, 0.01, 3000);  // 30 s
  ASSERT_EQ(fired.size(), 91u);  // k = 0..90, the last at exactly 30 s
  for (std::size_t k = 0; k < fired.size(); ++k) {
    // First n with n * 10 ms >= k / 3 s, i.e. n = ceil(100 k / 3).
    EXPECT_EQ(fired[k], (100 * static_cast<long>(k) + 2) / 3) << "sample " << k;
  }
}

TEST(SensorScheduleTest, RateAboveStepRateFiresOncePerStepAndSkipsMissedSamples) {
  SensorSchedule schedule(1000.0);
  EXPECT_TRUE(schedule.Due(0.0));
  EXPECT_FALSE(schedule.Due(0.0));  // never twice at one instant
  EXPECT_TRUE(schedule.Due(0.01));
  EXPECT_EQ(schedule.next_sample(), 11);  // samples 1..10 were skipped, not queued
  EXPECT_FALSE(schedule.Due(0.0105));
  EXPECT_TRUE(schedule.Due(0.011));
}

TEST(SensorScheduleTest, ResetStartsOverAtTimeZero) {
  SensorSchedule schedule(2.0);
  EXPECT_TRUE(schedule.Due(0.0));
  EXPECT_FALSE(schedule.Due(0.4));
  EXPECT_DOUBLE_EQ(schedule.NextTimeS(), 0.5);
  schedule.Reset();
  EXPECT_TRUE(schedule.Due(0.0));
}

TEST(SensorScheduleTest, RejectsNonPositiveRateNamingTheField) {
  for (const double rate_hz : {0.0, -1.0, std::nan("")}) {
    try {
      SensorSchedule schedule(rate_hz);
      FAIL() << "accepted rate_hz " << rate_hz;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("rate_hz", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace plywood::sim
