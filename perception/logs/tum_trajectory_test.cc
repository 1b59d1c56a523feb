#include "perception/logs/tum_trajectory.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>

namespace plywood::perception {
namespace {

constexpr double kPi = std::numbers::pi;

std::uint64_t Bits(double x) { return std::bit_cast<std::uint64_t>(x); }

std::filesystem::path WriteTemp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("plywood_tum_" + name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The message of the std::invalid_argument that reading `text` throws ("" if none).
std::string ReadError(const std::string& name, const std::string& text) {
  try {
    ReadTumTrajectory(WriteTemp(name, text));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(TumTrajectoryTest, EveryHeadingComesBackBitForBit) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> any(-kPi, kPi), wide(-2 * kPi, 2 * kPi);
  std::vector<double> headings = {0.0,
                                  -0.0,
                                  kPi,
                                  -kPi,
                                  kPi / 2,
                                  -kPi / 2,
                                  1e-300,
                                  -1e-17,
                                  3e-9,
                                  2 * kPi,
                                  -2 * kPi,
                                  std::nextafter(kPi, 0.0),
                                  std::nextafter(-kPi, 0.0)};
  for (int i = 0; i < 300000; ++i) headings.push_back(any(rng));
  for (int i = 0; i < 100000; ++i) headings.push_back(any(rng) * 1e-6);  // a robot going straight
  for (int i = 0; i < 100000; ++i) headings.push_back(wide(rng));
  int plain_misses = 0;
  for (const double theta : headings) {
    const PlanarQuaternion q = QuaternionOfHeading(theta);
    ASSERT_EQ(Bits(HeadingOfQuaternion(0.0, 0.0, q.qz, q.qw)), Bits(theta)) << theta;
    EXPECT_NEAR(std::hypot(q.qz, q.qw), 1.0, 1e-15);
    plain_misses += 2.0 * std::atan2(std::sin(theta / 2), std::cos(theta / 2)) != theta;
  }
  // Why the nudge exists: plain sin / cos miss a few percent of headings.
  EXPECT_GT(plain_misses, 1000);
}

TEST(TumTrajectoryTest, TiltedQuaternionsGiveTheirYaw) {
  // 30 deg yaw then a 10 deg roll: q = q_z(30) * q_x(10).
  const double y = 30 * kPi / 180, r = 10 * kPi / 180;
  const double qw = std::cos(y / 2) * std::cos(r / 2), qx = std::cos(y / 2) * std::sin(r / 2),
               qy = std::sin(y / 2) * std::sin(r / 2), qz = std::sin(y / 2) * std::cos(r / 2);
  EXPECT_NEAR(HeadingOfQuaternion(qx, qy, qz, qw), y, 1e-12);
}

// s42 thirteenth pass: a planar quaternion written w first (qw qx qy qz) read as yaw 0 at every
// heading, so a robot that turned 88 deg scored heading_error_deg 88 with exit 0. Its first pose
// (heading 0: "1 0 0 0") reads as a 180 deg roll, which no robot on a level floor has.
TEST(TumTrajectoryTest, AQuaternionWrittenWFirstIsRefusedAsATiltedPose) {
  const std::string w_first = "0 0 0 0 1 0 0 0\n";
  EXPECT_NE(ReadError("w_first.tum", w_first)
                .find("w_first.tum:1: qx: the quaternion tilts the pose 180 deg from level (qx 1, "
                      "qy 0), more than the 45 deg a robot on a level floor can: TUM's order is "
                      "qx qy qz qw; was it written w first?"),
            std::string::npos)
      << ReadError("w_first.tum", w_first);
  // Heading 60 deg written w first: cos 30, 0, 0, sin 30 reads as a 120 deg roll.
  EXPECT_NE(ReadError("w_first_60.tum", "0 0 0 0 0.8660254037844387 0 0 0.5\n")
                .find("w_first_60.tum:1: qx: the quaternion tilts the pose 120 deg from level"),
            std::string::npos);
  // A pitch of 46 deg is refused, naming qx (the pair qx, qy tilts); 44 deg still reads, as a
  // real estimator's few degrees of roll and pitch do.
  const auto pitched = [](double deg) {
    const double half = deg * kPi / 360.0;
    std::ostringstream line;
    line.precision(17);
    line << "0 0 0 0 0 " << std::sin(half) << " 0 " << std::cos(half) << "\n";
    return line.str();
  };
  EXPECT_NE(ReadError("pitch46.tum", pitched(46))
                .find("pitch46.tum:1: qx: the quaternion tilts "
                      "the pose 46 deg from level"),
            std::string::npos)
      << ReadError("pitch46.tum", pitched(46));
  EXPECT_EQ(ReadError("pitch44.tum", pitched(44)), "");
  EXPECT_EQ(ReadTumTrajectory(WriteTemp("pitch44.tum", pitched(44))).front().pose.theta_rad, 0.0);
}

TEST(TumTrajectoryTest, WrittenPosesReadBackExactly) {
  std::ostringstream text;
  text << "# comment\n";
  const std::vector<msgs::Pose2D> poses = {
      {0.1, -2.5, 0.3}, {1.0 / 3.0, 1e-9, -kPi}, {-7.25, 3.125, 2.9999999999999996}};
  for (std::size_t i = 0; i < poses.size(); ++i) WriteTumPose(text, 0.1 * i, poses[i]);
  const auto read = ReadTumTrajectory(WriteTemp("round_trip.tum", text.str() + "\n"));
  ASSERT_EQ(read.size(), poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_EQ(Bits(read[i].time_s), Bits(0.1 * i));
    EXPECT_EQ(read[i].pose, poses[i]);
    EXPECT_EQ(read[i].line_number, i + 2);
  }
}

TEST(TumTrajectoryTest, BadFilesNameTheLineAndTheField) {
  const std::string ok = "0 0 0 0 0 0 0 1\n";
  EXPECT_NE(ReadError("count.tum", ok + "0.1 0 0 0 0 0 1\n").find("count.tum:2: qw: expected 8"),
            std::string::npos);
  EXPECT_NE(
      ReadError("nan.tum", ok + "0.1 nan 0 0 0 0 0 1\n").find("nan.tum:2: tx: must be finite"),
      std::string::npos)
      << ReadError("nan.tum", ok + "0.1 nan 0 0 0 0 0 1\n");
  EXPECT_NE(ReadError("text.tum", ok + "0.1 0 x1 0 0 0 0 1\n").find("text.tum:2: ty: not a number"),
            std::string::npos);
  EXPECT_NE(ReadError("time.tum", ok + "0 0 0 0 0 0 0 1\n").find("time.tum:2: timestamp:"),
            std::string::npos);
  EXPECT_NE(
      ReadError("norm.tum", ok + "0.1 0 0 0 0 0 0 2\n").find("norm.tum:2: qw: the quaternion"),
      std::string::npos);
  EXPECT_NE(ReadError("empty.tum", "# nothing\n").find("empty.tum: empty"), std::string::npos);
  EXPECT_NE(ReadError("absent.tum", "").find("empty"), std::string::npos);
}

}  // namespace
}  // namespace plywood::perception
