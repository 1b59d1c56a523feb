#include "sim/config/guarded_algorithms.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "msgs/pose2d.h"
#include "msgs/shortest_number.h"
#include "perception/lines/line_segment.h"
#include "perception/logs/tum_trajectory.h"

namespace plywood::sim {
namespace {

using msgs::ShortestNumber;

// The bounds `plywood score lines` puts on a file's segments (perception/lines/line_segment.h).
constexpr double kMaxEndToPointM = perception::kMaxEndToScanPointM;
constexpr double kMaxLineToEndM = perception::kMaxLineToEndsM;

// Runs `call`, the algorithm's `function`; whatever it throws becomes one line naming it.
template <typename Call>
auto Guarded(const std::string& label, const char* function, Call&& call) -> decltype(call()) {
  try {
    return call();
  } catch (const std::exception& e) {
    throw std::runtime_error(label + ": its " + function + " threw during the run: " + e.what());
  } catch (...) {
    throw std::runtime_error(label + ": its " + function +
                             " threw during the run, an exception that is not a std::exception");
  }
}

std::string Point(const Eigen::Vector2d& p) {
  return "(" + ShortestNumber(p.x()) + ", " + ShortestNumber(p.y()) + ")";
}

class GuardedExtractor : public perception::LineExtractor {
 public:
  GuardedExtractor(std::unique_ptr<perception::LineExtractor> inner, std::string label)
      : inner_(std::move(inner)), label_(std::move(label)) {}

  std::string name() const override { return inner_->name(); }

  std::vector<perception::LineSegment> Extract(const perception::ScanPoints& scan) const override {
    auto lines = Guarded(label_, "Extract", [&] { return inner_->Extract(scan); });
    for (const perception::LineSegment& s : lines) RequireFitted(s, scan);
    return lines;
  }

  perception::ExtractedFeatures ExtractFeatures(const perception::ScanPoints& scan) const override {
    // Named Extract: a plug-in writes Extract, which ExtractFeatures calls unless overridden.
    auto features = Guarded(label_, "Extract", [&] { return inner_->ExtractFeatures(scan); });
    for (const perception::LineSegment& s : features.lines) RequireFitted(s, scan);
    for (const perception::CircleFeature& c : features.circles) {
      if (!(c.centre.allFinite() && std::isfinite(c.rms_m) && c.radius_m >= 0.0 &&
            std::isfinite(c.radius_m))) {
        Fail("gave a circle that is not finite (centre " + Point(c.centre) + ", radius_m " +
             ShortestNumber(c.radius_m) + ", rms_m " + ShortestNumber(c.rms_m) + ")");
      }
    }
    return features;
  }

 private:
  [[noreturn]] void Fail(const std::string& what) const {
    throw std::runtime_error(label_ + ": " + what + "; nothing was scored");
  }

  // What `plywood score lines` requires of a file's segment, so a run never scores what the
  // scorer of its own lines.csv would refuse.
  void RequireFitted(const perception::LineSegment& s, const perception::ScanPoints& scan) const {
    // Described only when it fails: this runs on every segment of every scan.
    const auto segment = [&] {
      return "a segment from " + Point(s.start) + " to " + Point(s.end) + " (alpha_rad " +
             ShortestNumber(s.alpha_rad) + ", r_m " + ShortestNumber(s.r_m) + ")";
    };
    if (!(s.start.allFinite() && s.end.allFinite() && std::isfinite(s.alpha_rad) &&
          std::isfinite(s.r_m))) {
      Fail("gave " + segment() + ", which is not finite");
    }
    // lines.csv's `points` column, which `score lines` reads as a count in 0..1e9.
    if (s.num_points < 0 || s.num_points > 1000000000) {
      Fail("gave " + segment() + " of " + std::to_string(s.num_points) +
           " points: a segment's point count is in 0..1e9");
    }
    const double off =
        std::max(std::abs(s.SignedLineDistance(s.start)), std::abs(s.SignedLineDistance(s.end)));
    if (!(off <= kMaxLineToEndM)) {
      Fail("gave " + segment() + " whose line passes " + msgs::SixDigitNumber(off) +
           " m from its ends, more than " + ShortestNumber(kMaxLineToEndM) +
           " m: the line and the ends must describe one segment");
    }
    for (const Eigen::Vector2d& end : {s.start, s.end}) {
      // hypot, not norm: an end at 1e300 is 1e300 m away, where the squared norm overflows.
      double nearest = std::numeric_limits<double>::infinity();
      for (const Eigen::Vector2d& p : scan.points) {
        nearest = std::min(nearest, std::hypot(p.x() - end.x(), p.y() - end.y()));
        if (nearest <= kMaxEndToPointM) break;  // near enough: the usual case, and the cheap one
      }
      if (nearest <= kMaxEndToPointM) continue;
      Fail("gave " + segment() + " whose end " + Point(end) + " lies " +
           (scan.empty() ? std::string("in a scan of no points")
                         : msgs::SixDigitNumber(nearest) + " m from every point of its scan") +
           ", more than " + ShortestNumber(kMaxEndToPointM) +
           " m: a segment is fitted to its scan's points, in their (the sensor's) frame, not the "
           "world's");
    }
  }

  std::unique_ptr<perception::LineExtractor> inner_;
  std::string label_;
};

class GuardedEstimator : public robot::OdometryEstimator {
 public:
  GuardedEstimator(std::unique_ptr<robot::OdometryEstimator> inner, std::string label,
                   const msgs::Pose2D& X_WR_initial)
      : inner_(std::move(inner)), label_(std::move(label)), X_WR_initial_(X_WR_initial) {}

  void AddEncoders(const msgs::WheelEncoders& encoders) override {
    Guarded(label_, "AddEncoders", [&] { inner_->AddEncoders(encoders); });
    last_encoders_s_ = encoders.time_s;
  }
  void AddGyro(const msgs::GyroRate& gyro) override {
    Guarded(label_, "AddGyro", [&] { inner_->AddGyro(gyro); });
  }

  // What `plywood score trajectory` requires of a file's pose, so the run's own scores (and the
  // controller steering by it) never take a pose that file would be refused for.
  msgs::Pose2D pose() const override {
    const msgs::Pose2D p = Guarded(label_, "pose", [&] { return inner_->pose(); });
    const double m = perception::kMaxTrajectoryCoordinateM;
    const double rad = perception::kMaxTrajectoryHeadingRad;
    if (std::abs(p.x_m) <= m && std::abs(p.y_m) <= m && std::abs(p.theta_rad) <= rad) {
      if (!start_checked_) RequireStartAtTheInitialPose(p);
      return p;
    }
    const std::string when = When();
    throw std::runtime_error(label_ + ": gave the pose x " + ShortestNumber(p.x_m) + " m, y " +
                             ShortestNumber(p.y_m) + " m, theta " + ShortestNumber(p.theta_rad) +
                             " rad " + when + ": a pose must be finite, within " +
                             ShortestNumber(m) + " m of the origin and " + ShortestNumber(rad) +
                             " rad of 0 (as plywood score trajectory requires); nothing was "
                             "scored");
  }

 private:
  // The first pose asked for (the run's first sample) is the estimate's start, which `plywood
  // score trajectory` requires at the spawn: the scores have no alignment. An estimator that
  // ignores the initial pose its factory got (integrating from the origin, say) would be scored
  // as its offset from the spawn.
  void RequireStartAtTheInitialPose(const msgs::Pose2D& p) const {
    start_checked_ = true;
    const double offset_m = std::hypot(p.x_m - X_WR_initial_.x_m, p.y_m - X_WR_initial_.y_m);
    const double offset_deg =
        std::abs(msgs::WrapAngle(p.theta_rad - X_WR_initial_.theta_rad)) * 180.0 / std::numbers::pi;
    if (offset_m <= perception::kMaxStartOffsetM &&
        offset_deg <= perception::kMaxStartHeadingOffsetDeg) {
      return;
    }
    const auto pose = [](const msgs::Pose2D& q) {
      return "(" + msgs::SixDigitNumber(q.x_m) + ", " + msgs::SixDigitNumber(q.y_m) + ") heading " +
             msgs::SixDigitNumber(q.theta_rad * 180.0 / std::numbers::pi) + " deg";
    };
    throw std::runtime_error(
        label_ + ": starts at " + pose(p) + " " + When() + ", " + msgs::SixDigitNumber(offset_m) +
        " m and " + msgs::SixDigitNumber(offset_deg) + " deg from the initial pose " +
        pose(X_WR_initial_) + " its factory was given: an estimate starts there (plywood score " +
        "trajectory scores without alignment, within " +
        ShortestNumber(perception::kMaxStartOffsetM) + " m and " +
        ShortestNumber(perception::kMaxStartHeadingOffsetDeg) + " deg); nothing was scored");
  }

  std::string When() const {
    return std::isnan(last_encoders_s_)
               ? "before the first encoder reading"
               : "after the encoder reading at t=" + msgs::SixDigitNumber(last_encoders_s_) + " s";
  }

  std::unique_ptr<robot::OdometryEstimator> inner_;
  std::string label_;
  msgs::Pose2D X_WR_initial_;
  mutable bool start_checked_ = false;
  double last_encoders_s_ = std::numeric_limits<double>::quiet_NaN();
};

class GuardedController : public robot::Controller {
 public:
  GuardedController(std::unique_ptr<robot::Controller> inner, std::string label)
      : inner_(std::move(inner)), label_(std::move(label)) {}

  msgs::WheelSpeedCommand Update(const robot::ControllerInput& input) override {
    const msgs::WheelSpeedCommand c =
        Guarded(label_, "Update", [&] { return inner_->Update(input); });
    if (std::isfinite(c.left_rad_s) && std::isfinite(c.right_rad_s)) return c;
    throw std::runtime_error(label_ + ": gave a wheel speed that is not finite at t=" +
                             msgs::SixDigitNumber(input.time_s) + " s (left " +
                             ShortestNumber(c.left_rad_s) + ", right " +
                             ShortestNumber(c.right_rad_s) + " rad/s)");
  }
  bool Finished() const override {
    return Guarded(label_, "Finished", [&] { return inner_->Finished(); });
  }

 private:
  std::unique_ptr<robot::Controller> inner_;
  std::string label_;
};

}  // namespace

std::unique_ptr<perception::LineExtractor> GuardRegistered(
    std::unique_ptr<perception::LineExtractor> extractor, std::string label) {
  return std::make_unique<GuardedExtractor>(std::move(extractor), std::move(label));
}

std::unique_ptr<robot::OdometryEstimator> GuardRegistered(
    std::unique_ptr<robot::OdometryEstimator> estimator, std::string label,
    const msgs::Pose2D& X_WR_initial) {
  return std::make_unique<GuardedEstimator>(std::move(estimator), std::move(label), X_WR_initial);
}

std::unique_ptr<robot::Controller> GuardRegistered(std::unique_ptr<robot::Controller> controller,
                                                   std::string label) {
  return std::make_unique<GuardedController>(std::move(controller), std::move(label));
}

}  // namespace plywood::sim
