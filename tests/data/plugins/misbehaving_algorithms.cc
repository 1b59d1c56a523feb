// A plug-in whose algorithms break their contract, for tests/plugin_errors_test.cc:
// `nan_lines` returns one segment of NaN per scan, `throwing_lines` throws an int,
// `throwing_std_lines` a std::runtime_error, `world_frame_lines` a segment 10 m from the scan's
// points (as if in another frame), `negative_points_lines` a segment of -7 points; the estimators
// `nan_after_1s` and `spinning_1e300` give a pose of x NaN, or of heading 1e300 rad, from the
// encoder reading at 1 s on, and `starts_off_the_spawn` starts 1 m east of and 90 deg left of
// the initial pose it was given (as one integrating from the origin, or in another frame).
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "perception/lines/line_extractor.h"
#include "perception/plugins/plugin.h"

namespace {

using plywood::perception::LineSegment;
using plywood::perception::ScanPoints;

class NanLines : public plywood::perception::LineExtractor {
 public:
  std::string name() const override { return "nan_lines"; }
  std::vector<LineSegment> Extract(const ScanPoints&) const override {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    LineSegment s;
    s.alpha_rad = s.r_m = nan;
    s.start = s.end = Eigen::Vector2d(nan, nan);
    s.num_points = 5;
    return {s};
  }
};

class ThrowingLines : public plywood::perception::LineExtractor {
 public:
  std::string name() const override { return "throwing_lines"; }
  std::vector<LineSegment> Extract(const ScanPoints&) const override { throw 42; }
};

class ThrowingStdLines : public plywood::perception::LineExtractor {
 public:
  std::string name() const override { return "throwing_std_lines"; }
  std::vector<LineSegment> Extract(const ScanPoints&) const override {
    throw std::runtime_error("lost the scan");
  }
};

// The segment through the scan's first and last points, moved `offset_m` along x, of `points`
// points.
class ChordLines : public plywood::perception::LineExtractor {
 public:
  ChordLines(double offset_m, int points) : offset_m_(offset_m), points_(points) {}
  std::string name() const override { return "chord_lines"; }
  std::vector<LineSegment> Extract(const ScanPoints& scan) const override {
    if (scan.size() < 2) return {};
    LineSegment s;
    s.start = scan.points.front() + Eigen::Vector2d(offset_m_, 0);
    s.end = scan.points.back() + Eigen::Vector2d(offset_m_, 0);
    const Eigen::Vector2d d = (s.end - s.start).normalized();
    const Eigen::Vector2d n(-d.y(), d.x());
    plywood::perception::CanonicalNormalForm(std::atan2(n.y(), n.x()), n.dot(s.start), &s.alpha_rad,
                                             &s.r_m);
    s.num_points = points_ ? points_ : static_cast<int>(scan.size());
    return {s};
  }

 private:
  double offset_m_;
  int points_;
};

// Stands still at its initial pose, then gives `bad` from the encoder reading at 1 s on.
class BadFromOneSecond : public plywood::robot::OdometryEstimator {
 public:
  BadFromOneSecond(const plywood::msgs::Pose2D& initial, const plywood::msgs::Pose2D& bad)
      : initial_(initial), bad_(bad) {}
  void AddEncoders(const plywood::msgs::WheelEncoders& encoders) override {
    time_s_ = encoders.time_s;
  }
  plywood::msgs::Pose2D pose() const override { return time_s_ >= 1.0 ? bad_ : initial_; }

 private:
  plywood::msgs::Pose2D initial_, bad_;
  double time_s_ = 0.0;
};

}  // namespace

PLYWOOD_PLUGIN(registry) {
  registry.line_extractors.Add({"nan_lines", [](const plywood::robot::ParameterMap&) {
                                  return std::make_unique<NanLines>();
                                }});
  registry.line_extractors.Add({"throwing_lines", [](const plywood::robot::ParameterMap&) {
                                  return std::make_unique<ThrowingLines>();
                                }});
  registry.line_extractors.Add({"throwing_std_lines", [](const plywood::robot::ParameterMap&) {
                                  return std::make_unique<ThrowingStdLines>();
                                }});
  registry.line_extractors.Add({"world_frame_lines", [](const plywood::robot::ParameterMap&) {
                                  return std::make_unique<ChordLines>(10.0, 0);
                                }});
  registry.line_extractors.Add({"negative_points_lines", [](const plywood::robot::ParameterMap&) {
                                  return std::make_unique<ChordLines>(0.0, -7);
                                }});
  registry.odometry_estimators.Add(
      {"nan_after_1s", false,
       [](const plywood::robot::OdometryGeometry&, const plywood::msgs::Pose2D& X_WR,
          const plywood::robot::ParameterMap&) {
         const double nan = std::numeric_limits<double>::quiet_NaN();
         return std::make_unique<BadFromOneSecond>(X_WR, plywood::msgs::Pose2D{nan, 0.0, 0.0});
       }});
  registry.odometry_estimators.Add(
      {"spinning_1e300", false,
       [](const plywood::robot::OdometryGeometry&, const plywood::msgs::Pose2D& X_WR,
          const plywood::robot::ParameterMap&) {
         return std::make_unique<BadFromOneSecond>(X_WR, plywood::msgs::Pose2D{0.0, 0.0, 1e300});
       }});
  registry.odometry_estimators.Add(
      {"starts_off_the_spawn", false,
       [](const plywood::robot::OdometryGeometry&, const plywood::msgs::Pose2D& X_WR,
          const plywood::robot::ParameterMap&) {
         const plywood::msgs::Pose2D off{X_WR.x_m + 1.0, X_WR.y_m,
                                         X_WR.theta_rad + std::numbers::pi / 2};
         return std::make_unique<BadFromOneSecond>(off, off);
       }});
}
