#include "perception/logs/carmen_log.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <numbers>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include "plywood_paths.h"

namespace plywood::perception {
namespace {

std::filesystem::path WriteTemp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("plywood_carmen_" + name);
  std::ofstream(path) << text;
  return path;
}

// At 100.25 s, or `time` (a log of one scan repeated at one time stamp is refused as joined to
// itself).
std::string Flaser(const std::string& ranges, int n, const std::string& time = "100.25") {
  return "FLASER " + std::to_string(n) + " " + ranges + " 1.0 2.0 0.5 1.1 2.1 0.6 " + time +
         " host 100.3\n";
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

// Fields are split at every kind of white space the C library's isspace knows, any number of it.
TEST(CarmenLogTest, FieldsSplitAtTabsAndEveryOtherWhiteSpace) {
  CarmenLog spaced, mixed;
  ASSERT_TRUE(ParseCarmenLine("FLASER 3 1 2 3 1.0 2.0 0.5 1.1 2.1 0.6 100.25 host 100.3", &spaced));
  ASSERT_TRUE(ParseCarmenLine(
      "\t FLASER\t3 \v1\f2\r3  1.0\t\t2.0 0.5 1.1 2.1 0.6 100.25 host 100.3 \r", &mixed));
  ASSERT_EQ(mixed.lasers.size(), 1u);
  EXPECT_EQ(mixed.lasers[0].scan.ranges_m, spaced.lasers[0].scan.ranges_m);
  EXPECT_EQ(mixed.lasers[0].scan.time_s, spaced.lasers[0].scan.time_s);
  EXPECT_EQ(mixed.lasers[0].X_WL.theta_rad, spaced.lasers[0].X_WL.theta_rad);
  EXPECT_EQ(mixed.lasers[0].X_WR_odom.theta_rad, spaced.lasers[0].X_WR_odom.theta_rad);
  // A character that is not white space (here a NUL is not one) stays inside its field.
  CarmenLog log;
  EXPECT_THROW(ParseCarmenLine(std::string("FLASER 3 1 2\0 3", 16) + " 1 2 0 1 2 0 5 h 5", &log),
               std::runtime_error);
  EXPECT_FALSE(ParseCarmenLine(" \t\r", &log));
}

TEST(CarmenLogTest, RangeMaxDefaultsToTheLargestRangeInTheLog) {
  const auto path = WriteTemp("max.log", Flaser("1 81.91 3", 3) + Flaser("2 2 2", 3));
  EXPECT_DOUBLE_EQ(ReadCarmenLog(path).lasers[1].scan.range_max_m, 81.91);
}

// CARMEN's own logs name the maximum range robot_front_laser_max (freiburg-079: 80.99 m). Read only
// as Plywood's front_laser_max, a stretch of log where the laser always saw something took its
// largest real return (5.5 m here) as the maximum, and the valid-ray cut dropped returns near it.
TEST(CarmenLogTest, CarmensRobotFrontLaserMaxIsTheMaximumRange) {
  const auto path = WriteTemp("carmen.log", "PARAM robot_front_laser_max 80.99 host 0\n" +
                                                Flaser("1 5.5 3", 3) + Flaser("2 2 2", 3));
  EXPECT_DOUBLE_EQ(ReadCarmenLog(path).lasers[0].scan.range_max_m, 80.99);
  // Plywood's own name wins when both are given.
  const auto both = WriteTemp("both.log",
                              "PARAM robot_front_laser_max 80.99 host 0\n"
                              "PARAM front_laser_max 8 host 0\n" +
                                  Flaser("1 5.5 3", 3));
  EXPECT_DOUBLE_EQ(ReadCarmenLog(both).lasers[0].scan.range_max_m, 8.0);
  try {
    ReadCarmenLog(
        WriteTemp("bad.log", Flaser("1 2 3", 3) + "PARAM robot_front_laser_max -1 h 0\n"));
    ADD_FAILURE() << "no error for robot_front_laser_max -1";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("bad.log:2: PARAM robot_front_laser_max: must be > 0"),
              std::string::npos)
        << e.what();
  }
}

TEST(CarmenLogTest, MalformedLinesNameTheLineOrAreSkippedAndCounted) {
  const std::string good = Flaser("1 2 3", 3);
  for (const std::string& bad : {Flaser("1 2", 3), Flaser("1 nan 3", 3), Flaser("1 abc 3", 3),
                                 Flaser("1 -2 3", 3), std::string("FLASER x\n")}) {
    const auto path = WriteTemp("bad.log", good + bad + Flaser("1 2 3", 3, "101.25"));
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
  // Beams 0.5 rad apart (a spacing of 0, every beam on one bearing, is refused since fuzz30).
  record.scan.angle_min_rad = -0.5;
  record.scan.angle_increment_rad = 0.5;
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

TEST(CarmenLogTest, HugeCoordinatesAreWrittenWholeNotTruncated) {
  // A 64-byte buffer cut %.6f of 1e200 to its first 63 digits: a different number, silently.
  CarmenLaserRecord record;
  record.scan.angle_min_rad = -0.5;
  record.scan.angle_increment_rad = 0.5;
  record.scan.ranges_m = {0.5, 1.25, 8.0};
  record.scan.range_max_m = 8.0;
  record.X_WL = {1e200, -3e150, 0.25};
  record.X_WR_odom = {-1e200, 2.0, 0.2};
  std::ostringstream out;
  WriteCarmenLaser(out, record);
  const CarmenLog log = ReadCarmenLog(WriteTemp("huge.log", out.str()));
  ASSERT_EQ(log.lasers.size(), 1u);
  EXPECT_DOUBLE_EQ(log.lasers[0].X_WL.x_m, 1e200);
  EXPECT_DOUBLE_EQ(log.lasers[0].X_WL.y_m, -3e150);
  EXPECT_DOUBLE_EQ(log.lasers[0].X_WR_odom.x_m, -1e200);
}

// Issue 18: a scan of fov != 180 deg written as FLASER was read back spread over 180 deg.
TEST(CarmenLogTest, ANarrowScanRoundTripsWithItsOwnBeamAngles) {
  CarmenLaserRecord record;
  const double deg = std::numbers::pi / 180.0;
  record.scan.angle_min_rad = -50.0 * deg;
  record.scan.angle_increment_rad = 1.0 * deg;
  record.scan.ranges_m.assign(101, 2.0);
  record.scan.ranges_m[7] = 9.0;
  record.scan.range_max_m = 8.0;
  record.scan.time_s = 1.5;
  record.X_WL = {1.0, 2.0, 0.5};
  record.X_WR_odom = {1.1, 2.1, 0.6};
  EXPECT_FALSE(IsFlaserScan(record.scan));
  std::ostringstream out;
  WriteCarmenLaser(out, record);
  EXPECT_EQ(out.str().rfind("ROBOTLASER1 ", 0), 0u) << out.str();
  const CarmenLog log = ReadCarmenLog(WriteTemp("narrow.log", out.str()));
  ASSERT_EQ(log.lasers.size(), 1u);
  const msgs::LaserScan& scan = log.lasers[0].scan;
  ASSERT_EQ(scan.ranges_m.size(), 101u);
  EXPECT_NEAR(scan.BeamAngleRad(0), -50.0 * deg, 1e-9);
  EXPECT_NEAR(scan.BeamAngleRad(100), 50.0 * deg, 1e-8);
  EXPECT_DOUBLE_EQ(scan.range_max_m, 8.0);
  EXPECT_DOUBLE_EQ(scan.ranges_m[7], 8.0);  // clipped to the maximum, as FLASER does
  EXPECT_DOUBLE_EQ(log.lasers[0].X_WL.theta_rad, 0.5);
  EXPECT_DOUBLE_EQ(log.lasers[0].X_WR_odom.x_m, 1.1);
  EXPECT_DOUBLE_EQ(scan.time_s, 1.5);

  // A 180-degree scan stays FLASER (the format every CARMEN reader knows).
  record.scan.angle_min_rad = -90.0 * deg;
  record.scan.angle_increment_rad = 180.0 * deg / 100.0;
  EXPECT_TRUE(IsFlaserScan(record.scan));
  std::ostringstream flaser;
  WriteCarmenLaser(flaser, record);
  EXPECT_EQ(flaser.str().rfind("FLASER 101 ", 0), 0u);
}

// s50: FLASER has no angles; for 400 / 401 beams CARMEN's reader guesses a 100 deg SICK at
// 0.25 deg, the replay read 180 deg at 0.45 deg (exit 0, every wall bent into another fan). Such a
// line is refused naming the count, and a 401-beam 180 deg scan of Plywood's goes out as
// ROBOTLASER1, which reads back with its own angles. 181 and 361 beams stay FLASER.
TEST(CarmenLogTest, AFlaserCountReadersTakeForAnotherFanIsRefused) {
  const double deg = std::numbers::pi / 180.0;
  for (const std::size_t n : {400u, 401u}) {
    SCOPED_TRACE(n);
    std::string line = "FLASER " + std::to_string(n);
    for (std::size_t i = 0; i < n; ++i) line += " 2.0";
    line += " 0 0 0 0 0 0 1.0 host 1.0\n";
    try {
      ReadCarmenLog(WriteTemp("flaser_" + std::to_string(n) + ".log", line));
      ADD_FAILURE() << "a " << n << "-beam FLASER line was read";
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(".log:1: FLASER beam count: " + std::to_string(n) + " beams"),
                std::string::npos)
          << message;
      EXPECT_NE(message.find("100 deg scan at 0.25 deg"), std::string::npos) << message;
    }
  }
  CarmenLaserRecord record;
  record.scan.angle_min_rad = -90.0 * deg;
  record.scan.angle_increment_rad = 180.0 * deg / 400.0;
  record.scan.ranges_m.assign(401, 2.0);
  record.scan.range_max_m = 8.0;
  EXPECT_FALSE(IsFlaserScan(record.scan));
  std::ostringstream out;
  WriteCarmenLaser(out, record);
  EXPECT_EQ(out.str().rfind("ROBOTLASER1 ", 0), 0u) << out.str().substr(0, 40);
  const CarmenLog log = ReadCarmenLog(WriteTemp("wide401.log", out.str()));
  ASSERT_EQ(log.lasers.size(), 1u);
  EXPECT_NEAR(log.lasers[0].scan.BeamAngleRad(200), 0.0, 1e-9);
  EXPECT_NEAR(log.lasers[0].scan.BeamAngleRad(400), 90.0 * deg, 1e-9);
  for (const std::size_t n : {181u, 361u}) {
    record.scan.angle_increment_rad = 180.0 * deg / static_cast<double>(n - 1);
    record.scan.ranges_m.assign(n, 2.0);
    EXPECT_TRUE(IsFlaserScan(record.scan)) << n;
  }
}

// s51: CARMEN's writers made 180 and 360 beams of a SICK's 181 and 361 by dropping the last, and
// its reader steps them 1 and 0.5 deg from -90 deg (to 89 and 89.5 deg). Plywood spread them over
// 180 deg, the last beam 1 deg off (17 cm at 10 m), exit 0: the shipped intel / aces logs (180) and
// freiburg-079 (360) were replayed so. Other counts keep 180 deg; the writer agrees with the
// reader.
TEST(CarmenLogTest, FlaserOf180Or360BeamsStepsAsCarmenDoes) {
  const double deg = std::numbers::pi / 180.0;
  const std::vector<std::pair<std::size_t, double>> counts = {{180, 89.0}, {360, 89.5}, {181, 90.0},
                                                              {361, 90.0}, {541, 90.0}, {2, 90.0}};
  for (const auto& [n, last_deg] : counts) {
    SCOPED_TRACE(n);
    std::string line = "FLASER " + std::to_string(n);
    for (std::size_t i = 0; i < n; ++i) line += " 2.0";
    line += " 0 0 0 0 0 0 1.0 host 1.0\n";
    const CarmenLog log = ReadCarmenLog(WriteTemp("steps" + std::to_string(n) + ".log", line));
    ASSERT_EQ(log.lasers.size(), 1u);
    const msgs::LaserScan& scan = log.lasers[0].scan;
    EXPECT_NEAR(scan.BeamAngleRad(0), -90.0 * deg, 1e-12);
    EXPECT_NEAR(scan.BeamAngleRad(n - 1), last_deg * deg, 1e-12);
    EXPECT_NEAR(FlaserAngleIncrementRad(n), scan.angle_increment_rad, 0.0);
  }
  // The writer: a 180-beam scan at 1 deg is FLASER and reads back as written; one spread over
  // 180 deg is not what a FLASER reader would take, so it goes out as ROBOTLASER1.
  CarmenLaserRecord record;
  record.scan.angle_min_rad = -90.0 * deg;
  record.scan.ranges_m.assign(180, 2.0);
  record.scan.range_max_m = 8.0;
  for (const double step : {1.0 * deg, 180.0 * deg / 179.0}) {
    record.scan.angle_increment_rad = step;
    std::ostringstream out;
    WriteCarmenLaser(out, record);
    EXPECT_EQ(IsFlaserScan(record.scan), step == 1.0 * deg);
    EXPECT_EQ(out.str().rfind(step == 1.0 * deg ? "FLASER 180 " : "ROBOTLASER1 ", 0), 0u);
    const CarmenLog log = ReadCarmenLog(WriteTemp("w180.log", out.str()));
    ASSERT_EQ(log.lasers.size(), 1u);
    EXPECT_NEAR(log.lasers[0].scan.BeamAngleRad(179), -90.0 * deg + 179.0 * step, 1e-9);
  }
}

// Each way a ROBOTLASER1 line can be malformed is refused naming the line, like FLASER's.
TEST(CarmenLogTest, MalformedRobotLaser1LinesNameTheLine) {
  CarmenLaserRecord record;
  record.scan.angle_min_rad = -0.5;
  record.scan.angle_increment_rad = 0.5;
  record.scan.ranges_m = {1.0, 2.0, 3.0};
  record.scan.range_max_m = 8.0;
  std::ostringstream line;
  WriteCarmenLaser(line, record);
  const std::string good = line.str();
  ASSERT_EQ(good.rfind("ROBOTLASER1 0 -0.5 ", 0), 0u) << good;
  // good: ROBOTLASER1 type start fov resolution max accuracy mode n=3 r r r m=0 ... (27 fields)
  const auto with = [&good](std::size_t field, const std::string& value) {
    std::istringstream in(good);
    std::vector<std::string> t{std::istream_iterator<std::string>(in), {}};
    if (value.empty()) {
      t.erase(t.begin() + static_cast<std::ptrdiff_t>(field));
    } else {
      t[field] = value;
    }
    std::string out;
    for (const std::string& token : t) out += (out.empty() ? "" : " ") + token;
    return out + "\n";
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {with(25, ""), "ROBOTLASER1: expected 27 fields for 3 beams and 0 remissions, got 26"},
      {with(8, "4"), "ROBOTLASER1: expected 28 fields for 4 beams and 0 remissions, got 27"},
      {with(8, "40"), "ROBOTLASER1: fewer ranges than announced"},
      {with(5, "0"), "ROBOTLASER1 maximum_range: must be > 0, got 0"},
      {with(2, "abc"), "ROBOTLASER1 start_angle"},
      {with(10, "-2"), "ROBOTLASER1 range"},
      {"ROBOTLASER1 0 0 3\n", "ROBOTLASER1: missing fields before the ranges"},
      // Geometry a scanner cannot have (all were read without a word before fuzz30).
      {with(3, "nan"), "ROBOTLASER1 field_of_view: not a finite number: 'nan'"},
      {with(4, "nan"), "ROBOTLASER1 angular_resolution: not a finite number: 'nan'"},
      {with(4, "0"),
       "ROBOTLASER1 angular_resolution: must be > 0 with the 3 beams spanning at "
       "most 360 deg, got 0"},
      {with(4, "-0.5"), "ROBOTLASER1 angular_resolution: must be > 0"},
      {with(4, "4"), "ROBOTLASER1 angular_resolution: must be > 0"},
      {with(2, "1e300"), "ROBOTLASER1 start_angle: must be in [-2 pi, 2 pi] rad, got 1e300"},
      // s42b: a fov the resolution does not span (a log thinned to every second beam that kept
      // its resolution: the beams were read into half the fan, without a word).
      {with(3, "2"),
       "ROBOTLASER1 field_of_view: 2 rad, but 3 beams at angular_resolution 0.5 rad span 1 rad "
       "(1.5 counting n steps): the beams' angles are unknown"},
      {with(4, "0.25"), "ROBOTLASER1 field_of_view: 1 rad, but 3 beams at angular_resolution 0.25"},
      {with(3, "0.5"), "ROBOTLASER1 field_of_view: 0.5 rad"},
  };
  // Two scans at two time stamps (field 24); one scan twice is refused (a log joined to itself).
  EXPECT_EQ(ReadCarmenLog(WriteTemp("robotlaser_ok.log", good + with(24, "1"))).lasers.size(), 2u);
  // A fov of n steps (some writers count so) or rounded to a few decimals still reads.
  for (const char* fov : {"1.5", "1.0004"}) {
    EXPECT_EQ(ReadCarmenLog(WriteTemp("fov_n.log", with(3, fov))).lasers.size(), 1u) << fov;
  }
  for (const auto& [bad, message] : cases) {
    try {
      ReadCarmenLog(WriteTemp("bad.log", good + bad + good));
      ADD_FAILURE() << "no error for " << bad;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("bad.log:2: " + message), std::string::npos)
          << e.what() << "\n for: " << bad;
    }
  }
}

TEST(CarmenLogTest, AnInfiniteOrNonPositiveFrontLaserMaxIsRefusedWithItsLine) {
  for (const std::string value : {"inf", "nan", "0", "-3", "1e999", "8x"}) {
    const auto path =
        WriteTemp("param.log", Flaser("1 2 3", 3) + "PARAM front_laser_max " + value + " host 0\n");
    try {
      ReadCarmenLog(path);
      ADD_FAILURE() << "no error for front_laser_max " << value;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("param.log:2: PARAM front_laser_max"), std::string::npos)
          << e.what();
    }
  }
}

// audit s40: one PARAM front_laser_max serves every FLASER scan of a log, those before it too. Two
// logs joined with cat (an 8 m laser's, then an 81.91 m one's) were read without a word, the first
// log's scans scored against 81.91 m: its no-return readings at 8 m counted as valid rays.
TEST(CarmenLogTest, ASecondDifferentFrontLaserMaxIsRefusedWithItsLine) {
  const auto path =
      WriteTemp("joined.log", "PARAM front_laser_max 8 host 0\n" + Flaser("1 2 8", 3) +
                                  "PARAM front_laser_max 81.91 host 0\n" + Flaser("1 2 3", 3));
  try {
    ReadCarmenLog(path);
    ADD_FAILURE() << "no error for a second front_laser_max";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("joined.log:3: PARAM front_laser_max: given again as "
                                         "81.91 after an earlier 8"),
              std::string::npos)
        << e.what();
  }
  // The same value again (a log's header repeated, or spelt 8.000000) is one maximum: read.
  const CarmenLog same = ReadCarmenLog(
      WriteTemp("same.log", "PARAM front_laser_max 8 host 0\n" + Flaser("1 2 8", 3) +
                                "PARAM front_laser_max 8.000000 host 0\n" + Flaser("1 2 3", 3)));
  ASSERT_EQ(same.lasers.size(), 2u);
  EXPECT_EQ(same.lasers[0].scan.range_max_m, 8.0);
}

// s42 thirteenth pass: some converters write every scan twice, as FLASER and as ROBOTLASER1 at one
// time stamp. The replay counted each scan twice: scans, lines, circles and valid_rays doubled.
TEST(CarmenLogTest, AScanWrittenAsBothFlaserAndRobotLaser1IsRefusedWithItsLine) {
  // The FLASER scan of Flaser("1 2 3", 3) (-90 deg, pi / 2 apart, at 100.25 s) as ROBOTLASER1.
  const std::string robot_laser =
      "ROBOTLASER1 0 -1.5707963267948966 3.1415926535897931 1.5707963267948966 8 0 0 3 1 2 3 0 "
      "1.0 2.0 0.5 1.1 2.1 0.6 0 0 0 0 0 100.25 host 100.3\n";
  const std::string later = "FLASER 3 1 2 3 1.0 2.0 0.5 1.1 2.1 0.6 101.25 host 101.3\n";
  for (const auto& [name, text, line, kind, first] :
       {std::tuple{"both.log", Flaser("1 2 3", 3) + robot_laser + later, "2", "ROBOTLASER1",
                   "line 1's FLASER"},
        std::tuple{"both_rl_first.log", robot_laser + Flaser("1 2 3", 3) + later, "2", "FLASER",
                   "line 1's ROBOTLASER1"}}) {
    SCOPED_TRACE(name);
    const auto path = WriteTemp(name, text);
    try {
      ReadCarmenLog(path);
      ADD_FAILURE() << "no error for a scan given twice";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(
          std::string(e.what()).find(std::string(name) + ":" + line + ": " + kind +
                                     " ipc_timestamp: 100.250000 s is " + first + " scan again"),
          std::string::npos)
          << e.what();
    }
    // --skip-bad passes over the second copy: each scan once.
    CarmenReadOptions options;
    options.skip_bad = true;
    const CarmenLog log = ReadCarmenLog(path, options);
    EXPECT_EQ(log.lasers.size(), 2u);
    EXPECT_EQ(log.skipped_lines, 1u);
  }
  // Both kinds for different scans are two scans, and one kind at one time twice with other
  // ranges is left as it was (the log's content; the same ranges too are a repeat, below).
  EXPECT_EQ(ReadCarmenLog(WriteTemp("mixed.log", robot_laser + later)).lasers.size(), 2u);
  EXPECT_EQ(ReadCarmenLog(WriteTemp("same_kind.log", Flaser("1 2 3", 3) + Flaser("1 2 4", 3)))
                .lasers.size(),
            2u);
}

// s58: a log joined to itself (`cat a.log a.log`) was read with every scan twice, and the replay
// counted each twice, exit 0. A scan of one kind whose time stamp and every range repeat an earlier
// one's is refused with its line, or skipped and counted with --skip-bad; none of the 6,141 FLASER
// scans of the three shipped logs repeats a time stamp at all (docs/errors.md, s58).
TEST(CarmenLogTest, ALogJoinedToItselfIsRefusedAtItsFirstRepeatedScan) {
  const std::string later = "FLASER 3 1 2 3 1.0 2.0 0.5 1.1 2.1 0.6 101.25 host 101.3\n";
  const std::string once = Flaser("1 2 3", 3) + later;
  const auto path = WriteTemp("joined_to_itself.log", once + once);
  try {
    ReadCarmenLog(path);
    ADD_FAILURE() << "no error for a log joined to itself";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(
        std::string(e.what()),
        path.string() +
            ":3: FLASER ipc_timestamp: 100.250000 s, every range and pose repeat line 1's scan: "
            "the log holds this scan twice (a log joined to itself?), so the replay would "
            "count it twice; remove the repeat");
  }
  CarmenReadOptions options;
  options.skip_bad = true;
  const CarmenLog log = ReadCarmenLog(path, options);
  EXPECT_EQ(log.lasers.size(), 2u);
  EXPECT_EQ(log.skipped_lines, 2u);
}

// audit s35: a UTF-8 byte-order mark before the first line made it an unknown message, skipped
// without a word: the PARAM front_laser_max was lost (scans scored against their largest range,
// 3 m here) or the first scan dropped.
TEST(CarmenLogTest, AByteOrderMarkBeforeTheFirstLineKeepsThatLine) {
  const std::string bom = "\xEF\xBB\xBF";
  const CarmenLog param =
      ReadCarmenLog(WriteTemp("bom_param.log", bom + "PARAM front_laser_max 8 host 0\n" +
                                                   Flaser("1 2 3", 3) + Flaser("2 2 2", 3)));
  ASSERT_EQ(param.lasers.size(), 2u);
  EXPECT_EQ(param.lasers[0].scan.range_max_m, 8.0);
  const CarmenLog scan = ReadCarmenLog(WriteTemp("bom_scan.log", bom + Flaser("1 2 3", 3)));
  ASSERT_EQ(scan.lasers.size(), 1u);
  EXPECT_EQ(scan.lasers[0].line_number, 1u);
}

TEST(CarmenLogTest, AllZeroRangesWithoutAParamLeaveTheMaximumRangeUnknownAndAreRefused) {
  // Found by fuzzing: the largest range in the log stood in for the maximum, and was 0.
  const auto path = WriteTemp("zeros.log", Flaser("0 0 0", 3));
  try {
    ReadCarmenLog(path);
    ADD_FAILURE() << "a log whose maximum range is unknown was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("zeros.log:1: the maximum range is unknown"),
              std::string::npos)
        << e.what();
  }
  // With the PARAM the same scan is fine: every beam a no-return.
  const auto with_param =
      WriteTemp("zeros_param.log", "PARAM front_laser_max 8\n" + Flaser("0 0 0", 3));
  EXPECT_EQ(ReadCarmenLog(with_param).lasers.front().scan.range_max_m, 8.0);
}

TEST(CarmenLogTest, ALogWithoutAUsableScanIsRefused) {
  std::string random_bytes;
  std::uint32_t state = 12345;
  for (int i = 0; i < 100000; ++i) {
    state = state * 1664525u + 1013904223u;  // Numerical Recipes' LCG
    random_bytes.push_back(static_cast<char>(state >> 24));
  }
  for (const auto& [name, text] : {std::pair<std::string, std::string>{"empty.log", ""},
                                   {"random.log", random_bytes},
                                   {"odom_only.log", "ODOM 0 0 0 0 0 0 1 h 1\n"}}) {
    try {
      CarmenReadOptions options;
      options.skip_bad = true;
      ReadCarmenLog(WriteTemp(name, text), options);
      ADD_FAILURE() << "no error for " << name;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(name + ": no usable laser scan"), std::string::npos)
          << e.what();
    }
  }
}

// zlib reports corrupt or truncated data as the end of the file unless asked: 9 of 30 single-byte
// flips used to read as a shorter log.
TEST(CarmenLogTest, CorruptOrTruncatedGzipIsAnError) {
  std::string text = "PARAM front_laser_max 8 host 0\n";
  for (int i = 0; i < 200; ++i) text += Flaser("1 2 3", 3, std::to_string(100 + i));
  const auto gz_path = std::filesystem::temp_directory_path() / "plywood_carmen_good.log.gz";
  gzFile gz = gzopen(gz_path.c_str(), "wb");
  ASSERT_NE(gz, nullptr);
  ASSERT_EQ(gzwrite(gz, text.data(), static_cast<unsigned>(text.size())),
            static_cast<int>(text.size()));
  ASSERT_EQ(gzclose(gz), Z_OK);
  EXPECT_EQ(ReadCarmenLog(gz_path).lasers.size(), 200u);
  std::ifstream in(gz_path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 40u);

  std::string truncated = bytes.substr(0, bytes.size() - 12);
  std::string trailer_flipped = bytes;
  trailer_flipped[bytes.size() - 6] ^= 0x5a;  // the stored length (ISIZE)
  std::string data_flipped = bytes;
  data_flipped[bytes.size() / 2] ^= 0xff;
  for (const auto& [name, corrupt] : {std::pair{"truncated", truncated},
                                      {"trailer_flipped", trailer_flipped},
                                      {"data_flipped", data_flipped}}) {
    const auto path = WriteTemp(std::string(name) + ".log.gz", corrupt);
    try {
      ReadCarmenLog(path);
      ADD_FAILURE() << "no error for " << name;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path.filename().string() + ":"), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("gzip"), std::string::npos) << e.what();
    }
  }
}

// The bytes of `text` as one gzip member.
std::string GzipMember(const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / "plywood_carmen_member.gz";
  gzFile gz = gzopen(path.c_str(), "wb");
  EXPECT_NE(gz, nullptr);
  EXPECT_EQ(gzwrite(gz, text.data(), static_cast<unsigned>(text.size())),
            static_cast<int>(text.size()));
  EXPECT_EQ(gzclose(gz), Z_OK);
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// zlib's gzread ends the stream at bytes after a member that start no other member: a plain log
// appended to a compressed one (`cat more.log >> run.log.gz`), or two members cut one byte into
// the second, replayed the first member's scans alone, exit 0 (the s62 fortieth pass).
TEST(CarmenLogTest, BytesAfterTheGzipDataThatZlibWouldSkipAreAnError) {
  std::string first = "PARAM front_laser_max 8 host 0\n", second;
  for (int i = 0; i < 20; ++i) first += Flaser("1 2 3", 3, std::to_string(100 + i));
  for (int i = 20; i < 40; ++i) second += Flaser("1 2 3", 3, std::to_string(100 + i));
  const std::string member1 = GzipMember(first), member2 = GzipMember(second);

  // Whole members, one after the other (gzip's own way to join files), and zero padding: all read.
  EXPECT_EQ(ReadCarmenLog(WriteTemp("two_members.log.gz", member1 + member2)).lasers.size(), 40u);
  EXPECT_EQ(
      ReadCarmenLog(WriteTemp("padded.log.gz", member1 + std::string(512, '\0'))).lasers.size(),
      20u);

  const std::string offset = std::to_string(member1.size());
  for (const auto& [name, bytes, what] :
       {std::tuple{"appended_plain", member1 + second,
                   std::to_string(second.size()) +
                       " bytes after the gzip data, which ends at byte " + offset},
        {"cut_into_second", member1 + member2.substr(0, 1),
         "1 byte after the gzip data, which ends at byte " + offset}}) {
    const auto path = WriteTemp(std::string(name) + ".log.gz", bytes);
    try {
      const CarmenLog log = ReadCarmenLog(path);
      ADD_FAILURE() << name << ": read " << log.lasers.size() << " scans without an error";
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(path.string() + ":22: " + what), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

// gzgets ended a line's text at its first NUL byte: a scan line after a zero-filled block (what a
// crash leaves in a file being written) read as an empty line and its scan was lost, "0 lines
// skipped", exit 0; a NUL inside a line joined its rest to the next line (the s62 fortieth pass).
TEST(CarmenLogTest, ALineWithANulByteIsRefusedNamingItsLineAndColumn) {
  const std::string head = "PARAM front_laser_max 8 host 0\n" + Flaser("1 2 3", 3, "100");
  const std::string scan = Flaser("1 2 3", 3, "101");
  const std::string tail = Flaser("1 2 3", 3, "102") + Flaser("1 2 3", 3, "103");
  for (const auto& [name, text, column] :
       {std::tuple{"nul_start.log", head + std::string(16, '\0') + scan + tail, 1},
        {"nul_inside.log", head + scan.substr(0, 9) + '\0' + scan.substr(9) + tail, 10}}) {
    const auto path = WriteTemp(name, text);
    try {
      const CarmenLog log = ReadCarmenLog(path);
      ADD_FAILURE() << name << ": read " << log.lasers.size() << " scans without an error";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path.string() + ":3: a NUL byte at column " +
                                           std::to_string(column) + ": "),
                std::string::npos)
          << e.what();
    }
    // --skip-bad skips that line alone and counts it; the lines after it keep their numbers.
    CarmenReadOptions options;
    options.skip_bad = true;
    const CarmenLog log = ReadCarmenLog(path, options);
    EXPECT_EQ(log.skipped_lines, 1u) << name;
    ASSERT_EQ(log.lasers.size(), 3u) << name;
    EXPECT_EQ(log.lasers.back().line_number, 5u) << name;
  }
}

// zlib reads any file that is not gzip as plain bytes: a log compressed with xz, bzip2 or zstd
// was read as binary lines, "no usable laser scan (FLASER or ROBOTLASER1 line) in 43 lines", not
// named as the compressed file it is (the s62 fortieth pass).
TEST(CarmenLogTest, ALogCompressedWithAnotherProgramIsNamedAsSuch) {
  const std::string body = "\x01\x02 PARAM FLASER binary\n\x03";
  for (const auto& [name, magic, program] :
       {std::tuple{"log.xz", std::string("\xFD\x37zXZ\0", 6), "xz"},
        {"log.bz2", std::string("BZh9"), "bzip2"},
        {"log.zst", std::string("\x28\xB5\x2F\xFD"), "zstd"},
        {"log.zip", std::string("PK\x03\x04"), "zip"}}) {
    const auto path = WriteTemp(name, magic + body);
    try {
      ReadCarmenLog(path);
      ADD_FAILURE() << "no error for " << name;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path.string() + ": compressed with " + program +
                                           ", which Plywood does not read"),
                std::string::npos)
          << e.what();
    }
  }
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
