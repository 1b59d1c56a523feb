#include "perception/logs/tum_trajectory.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "perception/logs/byte_order_mark.h"
#include "perception/logs/parse_number.h"

namespace plywood::perception {
namespace {

std::string Shortest(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

bool SameDouble(double a, double b) { return a == b && std::signbit(a) == std::signbit(b); }

// 2 atan2(qz, qw) == theta bit for bit.
bool RoundTrips(double qz, double qw, double theta) {
  return SameDouble(2.0 * std::atan2(qz, qw), theta);
}

}  // namespace

PlanarQuaternion QuaternionOfHeading(double theta_rad) {
  if (!(std::abs(theta_rad) <= 2.0 * std::numbers::pi)) theta_rad = msgs::WrapAngle(theta_rad);
  const PlanarQuaternion plain{std::sin(theta_rad / 2.0), std::cos(theta_rad / 2.0)};
  if (RoundTrips(plain.qz, plain.qw, theta_rad)) return plain;
  // atan2 lands one unit in the last place off: a neighbouring qz or qw lands on it.
  for (int ulps = 1; ulps <= 4; ++ulps) {
    for (const double direction : {1.0, -1.0}) {
      const double towards = direction * INFINITY;
      double qz = plain.qz, qw = plain.qw;
      for (int k = 0; k < ulps; ++k) qz = std::nextafter(qz, towards);
      if (RoundTrips(qz, plain.qw, theta_rad)) return {qz, plain.qw};
      for (int k = 0; k < ulps; ++k) qw = std::nextafter(qw, towards);
      if (RoundTrips(plain.qz, qw, theta_rad)) return {plain.qz, qw};
    }
  }
  return plain;  // not met in practice (tum_trajectory_test samples millions of headings)
}

double HeadingOfQuaternion(double qx, double qy, double qz, double qw) {
  if (qx == 0.0 && qy == 0.0) return 2.0 * std::atan2(qz, qw);
  const double n = std::sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
  qx /= n, qy /= n, qz /= n, qw /= n;
  return std::atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz));
}

void WriteTumPose(std::ostream& out, double time_s, const msgs::Pose2D& pose) {
  const PlanarQuaternion q = QuaternionOfHeading(pose.theta_rad);
  out << Shortest(time_s) << ' ' << Shortest(pose.x_m) << ' ' << Shortest(pose.y_m) << " 0 0 0 "
      << Shortest(q.qz) << ' ' << Shortest(q.qw) << '\n';
}

std::vector<TimedPose> ReadTumTrajectory(const std::filesystem::path& path) {
  static constexpr const char* kFields[] = {"timestamp", "tx", "ty", "tz", "qx", "qy", "qz", "qw"};
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(path.string() + ": cannot read the file");
  std::vector<TimedPose> poses;
  std::string line;
  std::size_t line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // A UTF-8 byte-order mark hid the first line's comment sign: "line: expected 8 fields, got 17".
    if (line_number == 1) DropUtf8ByteOrderMark(line);
    const auto fail = [&](const std::string& field, const std::string& what) {
      throw std::invalid_argument(path.string() + ":" + std::to_string(line_number) + ": " + field +
                                  ": " + what);
    };
    std::istringstream fields(line);
    std::vector<std::string> words;
    for (std::string word; fields >> word;) words.push_back(word);
    if (words.empty() || words.front().front() == '#') continue;
    if (words.size() != 8) {
      fail(words.size() < 8 ? kFields[words.size()] : "line",
           "expected 8 fields (timestamp tx ty tz qx qy qz qw), got " +
               std::to_string(words.size()));
    }
    double v[8];
    for (int i = 0; i < 8; ++i) {
      const std::optional<double> number = ParseFiniteNumber(words[i]);
      if (!number) {
        const bool non_finite = std::isnan(std::strtod(words[i].c_str(), nullptr)) ||
                                std::isinf(std::strtod(words[i].c_str(), nullptr));
        fail(kFields[i],
             (non_finite ? "must be finite, got '" : "not a number: '") + words[i] + "'");
      }
      v[i] = *number;
    }
    for (int i : {1, 2}) {
      if (std::abs(v[i]) > kMaxTrajectoryCoordinateM) {
        fail(kFields[i], "must be within 1e+09 m of the origin, got " + Shortest(v[i]));
      }
    }
    const double norm = std::sqrt(v[4] * v[4] + v[5] * v[5] + v[6] * v[6] + v[7] * v[7]);
    if (!(std::abs(norm - 1.0) <= 1e-3)) {
      fail("qw", "the quaternion's norm is " + Shortest(norm) + ", expected 1");
    }
    // A planar quaternion written w first read as yaw 0 at every heading: heading_error_deg of
    // the robot's whole turn, exit 0. cos(tilt) = 1 - 2 (qx^2 + qy^2) for a unit quaternion.
    const double cos_tilt = 1.0 - 2.0 * (v[4] * v[4] + v[5] * v[5]) / (norm * norm);
    const double tilt_deg = std::acos(std::clamp(cos_tilt, -1.0, 1.0)) * 180.0 / std::numbers::pi;
    if (tilt_deg > kMaxTumTiltDeg) {
      fail("qx", "the quaternion tilts the pose " + Shortest(std::round(tilt_deg * 10.0) / 10.0) +
                     " deg from level (qx " + words[4] + ", qy " + words[5] + "), more than the " +
                     Shortest(kMaxTumTiltDeg) +
                     " deg a robot on a level floor can: TUM's order is qx qy "
                     "qz qw; was it written w first?");
    }
    if (!poses.empty() && !(v[0] > poses.back().time_s)) {
      fail("timestamp", Shortest(v[0]) + " s does not come after line " +
                            std::to_string(poses.back().line_number) + "'s " +
                            Shortest(poses.back().time_s) + " s");
    }
    poses.push_back({v[0], {v[1], v[2], HeadingOfQuaternion(v[4], v[5], v[6], v[7])}, line_number});
  }
  if (in.bad()) throw std::invalid_argument(path.string() + ": cannot read the file");
  if (poses.empty()) throw std::invalid_argument(path.string() + ": empty: no poses in the file");
  return poses;
}

}  // namespace plywood::perception
