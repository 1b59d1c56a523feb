#include "perception/logs/carmen_log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

namespace plywood::perception {
namespace {

std::filesystem::path WriteTemp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("plywood_carmen_" + name);
  std::ofstream(path) << text;
  return path;
}

std::string Flaser(const std::string& ranges, int n) {
  return "FLASER " + std::to_string(n) + " " + ranges +
         " 1.0 2.0 0.5 1.1 2.1 0.6 100.25 host 100.3\n";
}

TEST(CarmenLogTest, ParsesFlaserPosesRangesAndGeometry) {
  const auto path = WriteTemp("ok.log", "# comment\nPARAM front_laser_max 8.0 host 0\n" +
                                            Flaser("1 2 3", 3) + "ODOM 0 0 0 0 0 0 1 h 1\n");
  const CarmenLog log = ReadCarmenLog(path);
  ASSERT_EQ(log.lasers.size(), 1u);
  const CarmenLaserRecord& r = log.lasers[0];
  EXPECT_EQ(r.scan.ranges_m, (std::vector<double>{1, 2, 3}));
  EXPECT_DOUBLE_EQ(r.scan.angle_min_rad, -std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(r.scan.angle_increment_rad, std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(r.scan.range_max_m, 8.0);
  EXPECT_DOUBLE_EQ(r.X_WL.x_m, 1.0);
  EXPECT_DOUBLE_EQ(r.X_WR_odom.theta_rad, 0.6);
  EXPECT_DOUBLE_EQ(r.scan.time_s, 100.25);
  EXPECT_EQ(r.line_number, 3u);
}

TEST(CarmenLogTest, RangeMaxDefaultsToTheLargestRangeInTheLog) {
  const auto path = WriteTemp("max.log", Flaser("1 81.91 3", 3) + Flaser("2 2 2", 3));
  EXPECT_DOUBLE_EQ(ReadCarmenLog(path).lasers[1].scan.range_max_m, 81.91);
}

TEST(CarmenLogTest, MalformedLinesNameTheLineOrAreSkippedAndCounted) {
  const std::string good = Flaser("1 2 3", 3);
  for (const std::string& bad : {Flaser("1 2", 3), Flaser("1 nan 3", 3), Flaser("1 abc 3", 3),
                                 Flaser("1 -2 3", 3), std::string("FLASER x\n")}) {
    const auto path = WriteTemp("bad.log", good + bad + good);
    try {
      ReadCarmenLog(path);
      ADD_FAILURE() << "no error for " << bad;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("bad.log:2:"), std::string::npos) << e.what();
    }
    CarmenReadOptions options;
    options.skip_bad = true;
    const CarmenLog log = ReadCarmenLog(path, options);
    EXPECT_EQ(log.lasers.size(), 2u);
    EXPECT_EQ(log.skipped_lines, 1u);
  }
}

TEST(CarmenLogTest, WriteThenReadRoundTrips) {
  CarmenLaserRecord record;
  record.scan.ranges_m = {0.5, 1.25, 8.0};
  record.scan.range_max_m = 8.0;
  record.scan.time_s = 3.5;
  record.X_WL = {1.5, -2.0, 0.25};
  record.X_WR_odom = {1.4, -2.1, 0.2};
  std::ostringstream out;
  WriteCarmenParam(out, "front_laser_max", "8");
  WriteCarmenLaser(out, record);
  const CarmenLog log = ReadCarmenLog(WriteTemp("round.log", out.str()));
  ASSERT_EQ(log.lasers.size(), 1u);
  EXPECT_EQ(log.lasers[0].scan.ranges_m, record.scan.ranges_m);
  EXPECT_DOUBLE_EQ(log.lasers[0].X_WL.theta_rad, 0.25);
  EXPECT_DOUBLE_EQ(log.lasers[0].scan.time_s, 3.5);
}

TEST(CarmenLogTest, MissingFileIsAnError) {
  EXPECT_THROW(ReadCarmenLog("/nonexistent/file.log"), std::runtime_error);
}

TEST(CarmenLogTest, ReadsTheRealGzippedLogsWhenPresent) {
  const std::filesystem::path intel = std::filesystem::path(PLYWOOD_SOURCE_ROOT) / ".." / "shared" /
                                      "data" / "carmen" / "intel-corrected.log.gz";
  if (!std::filesystem::exists(intel)) GTEST_SKIP() << "no ../shared/data/carmen: skipped";
  const CarmenLog log = ReadCarmenLog(intel);
  EXPECT_EQ(log.lasers.size(), 910u);
  EXPECT_EQ(log.lasers.front().scan.ranges_m.size(), 180u);
}

}  // namespace
}  // namespace plywood::perception
