#include "sim/runner/metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace plywood::sim {
namespace {

TEST(FormatNumberTest, ShortestRoundTrip) {
  EXPECT_EQ(FormatNumber(0.1), "0.1");
  EXPECT_EQ(FormatNumber(12.0), "12");
  EXPECT_EQ(FormatNumber(-2.5e-7), "-2.5e-07");
  EXPECT_EQ(FormatNumber(NAN), "null");
  EXPECT_EQ(std::stod(FormatNumber(1.0 / 3.0)), 1.0 / 3.0);
}

TEST(FormatNumberTest, TimesAtTheTimestepsPrecision) {
  // A clock that sums its steps drifts off the decimal grid; written times stay on it.
  double clock = 0.0;
  for (int step = 0; step < 50; ++step) clock += 0.002;
  ASSERT_NE(clock, 0.1);
  EXPECT_EQ(FormatNumber(TimeAtStepPrecision(clock, 0.002)), "0.1");
  double tenths = 0.0;
  for (int step = 0; step < 3; ++step) tenths += 0.1;
  EXPECT_EQ(FormatNumber(TimeAtStepPrecision(tenths, 0.1)), "0.3");  // not 0.30000000000000004
  EXPECT_EQ(FormatNumber(TimeAtStepPrecision(1.23456789e-4, 1e-7)), "0.0001235");
  // A timestep with no short decimal form: nanoseconds.
  EXPECT_EQ(FormatNumber(TimeAtStepPrecision(2.0 / 3.0, 1.0 / 3.0)), "0.666666667");
  EXPECT_EQ(FormatNumber(TimeAtStepPrecision(NAN, 0.002)), "null");
}

TEST(MetricsTest, NestsDottedKeysInSortedOrder) {
  Metrics metrics;
  metrics.Set("run.steps", 10.0);
  metrics.Set("odometry.encoder.drift_percent", 1.5);
  metrics.Set("odometry.encoder.ate_rms_m", 0.25);
  metrics.Set("odometry.gyro.ate_rms_m", 0.5);
  metrics.Set("run.world", std::string("office"));
  EXPECT_EQ(metrics.ToJson(),
            "{\n"
            "  \"odometry\": {\n"
            "    \"encoder\": {\n"
            "      \"ate_rms_m\": 0.25,\n"
            "      \"drift_percent\": 1.5\n"
            "    },\n"
            "    \"gyro\": {\n"
            "      \"ate_rms_m\": 0.5\n"
            "    }\n"
            "  },\n"
            "  \"run\": {\n"
            "    \"steps\": 10,\n"
            "    \"world\": \"office\"\n"
            "  }\n"
            "}\n");
}

TEST(MetricsTest, KeyThatIsAlsoAnObjectIsRejected) {
  Metrics metrics;
  metrics.Set("a", 1.0);
  metrics.Set("a.b", 2.0);
  EXPECT_THROW(metrics.ToJson(), std::invalid_argument);
}

}  // namespace
}  // namespace plywood::sim
