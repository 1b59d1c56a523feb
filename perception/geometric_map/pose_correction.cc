#include "perception/geometric_map/pose_correction.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include "msgs/angle_units.h"
#include "perception/geometric_map/option_checks.h"

namespace plywood::perception {
namespace {

// Beyond 45 deg the map's walls, square to each other, look alike.
constexpr double kMaxHeadingWindowRad = kPi / 4.0;

Eigen::Vector2d ToWorld(const msgs::Pose2D& X_WR, const Eigen::Vector2d& p_R) {
  const double c = std::cos(X_WR.theta_rad), s = std::sin(X_WR.theta_rad);
  return {X_WR.x_m + c * p_R.x() - s * p_R.y(), X_WR.y_m + s * p_R.x() + c * p_R.y()};
}

// Offset of the maximum of three samples at -1, 0, +1 from the middle one (a parabola's vertex).
double ParabolaPeak(double left, double middle, double right) {
  const double denominator = left - 2.0 * middle + right;
  return denominator < 0.0 ? 0.5 * (left - right) / denominator : 0.0;
}

// The shift k in [-window, window] maximising sum_b a(b) * b(b + k), refined to a fraction of a
// bin; ties go to the smallest |k|.
double BestShift(const std::function<double(int)>& correlation, int window) {
  int best = 0;
  double best_value = correlation(0);
  for (int m = 1; m <= window; ++m) {
    for (int k : {-m, m}) {
      const double v = correlation(k);
      if (v > best_value) best_value = v, best = k;
    }
  }
  if (best_value <= 0.0 || std::abs(best) == window) return best;
  return best + ParabolaPeak(correlation(best - 1), best_value, correlation(best + 1));
}

// The voting scan points (coordinates along an axis) against the reference's within a bin of
// them, at a shift: how many scan points have one, and the pairs' summed signed distances.
struct PointMatch {
  long matched_points = 0;
  double pairs = 0.0;
  double offset_sum = 0.0;
};

class PointMatcher {
 public:
  PointMatcher(std::vector<double> voting, std::vector<double> reference, double bin)
      : voting_(std::move(voting)), reference_(std::move(reference)), bin_(bin) {
    std::sort(reference_.begin(), reference_.end());
    prefix_.assign(reference_.size() + 1, 0.0);
    for (std::size_t i = 0; i < reference_.size(); ++i) prefix_[i + 1] = prefix_[i] + reference_[i];
  }

  PointMatch Match(double shift_m) const {
    PointMatch match;
    for (double c : voting_) {
      const double at = c + shift_m;
      const auto lo = std::lower_bound(reference_.begin(), reference_.end(), at - bin_);
      const auto hi = std::upper_bound(lo, reference_.end(), at + bin_);
      const double n = static_cast<double>(hi - lo);
      if (n == 0.0) continue;
      ++match.matched_points;
      match.offset_sum +=
          prefix_[hi - reference_.begin()] - prefix_[lo - reference_.begin()] - n * at;
      match.pairs += n;
    }
    return match;
  }

 private:
  std::vector<double> voting_;
  std::vector<double> reference_;  // sorted
  std::vector<double> prefix_;     // prefix_[i]: the sum of the first i reference coordinates
  double bin_;
};

// `coarse_m` (the correlation's shift, matched as `at_coarse`) refined below the bin size, as the
// heading is refined on the fitted lines: the mean signed distance from each voting scan point
// (shifted) to the reference points within a bin of it, iterated (a flat-kernel mean shift) so
// that a wall's points, a fraction of a bin off, are matched whole. Sharp walls (little noise)
// fill one bin each, where the correlation's parabola has nothing to fit.
double RefineShift(const PointMatcher& matcher, PointMatch at_coarse, double coarse_m, double bin,
                   int min_pairs) {
  double shift_m = coarse_m;
  PointMatch match = at_coarse;
  for (int iteration = 0; iteration < 10; ++iteration) {
    if (iteration > 0) match = matcher.Match(shift_m);
    if (match.pairs < min_pairs) break;
    const double step = match.offset_sum / match.pairs;
    shift_m += step;
    if (std::abs(step) < 1e-4 * bin) break;
  }
  // The correlation's shift is right to a bin; the refinement only moves within it.
  return std::clamp(shift_m, coarse_m - bin, coarse_m + bin);
}

}  // namespace

void PoseCorrectionOptions::Validate() const {
  RequireOption(max_heading_step_deg > 0.0 && max_heading_step_deg <= 45.0, "max_heading_step_deg",
                "must be in (0, 45]", max_heading_step_deg);
  RequireOption(refine_window_deg >= 0.0 && refine_window_deg <= 45.0, "refine_window_deg",
                "must be in [0, 45]", refine_window_deg);
  RequireOption(max_shift_m > 0.0 && max_shift_m <= 2.0, "max_shift_m", "must be in (0, 2]",
                max_shift_m);
  RequireOption(position_bin_m >= 0.002 && position_bin_m <= 0.5, "position_bin_m",
                "must be in [0.002, 0.5]", position_bin_m);
  RequireOption(max_shift_m / position_bin_m <= 1000.0, "max_shift_m",
                "must be at most 1000 position bins", max_shift_m);
  RequireOption(min_virtual_lines >= 1 && min_virtual_lines <= 100000, "min_virtual_lines",
                "must be in [1, 100000]", min_virtual_lines);
  RequireOption(min_peak_votes >= 1 && min_peak_votes <= 100000, "min_peak_votes",
                "must be in [1, 100000]", min_peak_votes);
  RequireOption(reference_scans >= 1 && reference_scans <= 1000, "reference_scans",
                "must be in [1, 1000]", reference_scans);
}

HistogramPoseCorrector::HistogramPoseCorrector(const HistogramOptions& histograms,
                                               const PoseCorrectionOptions& options)
    : histogram_options_(histograms), options_(options) {}

double HistogramPoseCorrector::HeadingCorrection(std::span<const RangePoint> points_R,
                                                 std::span<const LineSegment> lines_R,
                                                 double heading_rad, double window_rad) const {
  const AngleHistogram scan = MakeAngleHistogram(points_R, histogram_options_, heading_rad);
  const int bins = static_cast<int>(scan.votes.size());
  const double bin_rad = kPi / bins;
  const int window = static_cast<int>(std::ceil(window_rad / bin_rad));
  const auto correlation = [&](int k) {
    double sum = 0.0;
    for (int b = 0; b < bins; ++b)
      sum += scan.votes[b] * map_angle_votes_[((b + k) % bins + bins) % bins];
    return sum;
  };
  double delta = BestShift(correlation, window) * bin_rad;
  // Below the bin size: the fitted lines parallel or square to the map's main direction.
  const double refine_window = options_.refine_window_deg * kDegToRad;
  double weighted = 0.0, weight = 0.0;
  for (const LineSegment& line : lines_R) {
    const Eigen::Vector2d d = line.end - line.start;
    const double direction = std::atan2(d.y(), d.x()) + heading_rad + delta;
    const double residual = std::remainder(direction - map_alpha_rad_, kPi / 2.0);
    if (std::abs(residual) > refine_window) continue;
    weighted += line.num_points * residual;
    weight += line.num_points;
  }
  if (weight >= options_.min_peak_votes) delta -= weighted / weight;
  return delta;
}

bool HistogramPoseCorrector::AxisShift(const std::vector<double>& scan, int axis_index,
                                       const Eigen::Vector2d& axis, const Eigen::Vector2d& robot_W,
                                       double* shift_m) const {
  const double bin = options_.position_bin_m;
  const auto bin_of = [&](double c) { return static_cast<long>(std::floor(c / bin)); };
  const int window = static_cast<int>(std::ceil(options_.max_shift_m / bin));
  std::map<long, double> scan_votes;
  for (double c : scan) scan_votes[bin_of(c)] += 1.0;
  // The scan must see a wall across the axis ...
  double strongest = 0.0;
  for (const auto& [b, v] : scan_votes) {
    const auto at = [&](long k) {
      const auto it = scan_votes.find(k);
      return it == scan_votes.end() ? 0.0 : it->second;
    };
    strongest = std::max(strongest, at(b - 1) + v + at(b + 1));
  }
  if (strongest < options_.min_peak_votes) return false;
  std::map<long, double> reference_votes;
  // The coordinates, kept only to match points one by one (the peak's support, the refinement).
  const bool match_points = options_.require_peak_support || options_.refine_position;
  std::vector<double> reference;
  const double reach = options_.max_shift_m + 10.0;
  for (const auto& points : recent_points_W_) {
    for (const AxisPoint& p : points) {
      if (p.axis == axis_index && (p.p_W - robot_W).squaredNorm() < reach * reach) {
        const double c = p.p_W.dot(axis);
        if (match_points) reference.push_back(c);
        reference_votes[bin_of(c)] += 1.0;
      }
    }
  }
  // ... and only its points with min_peak_votes reference points within the shift window vote, at
  // least min_peak_votes of them: a wall seen for the first time has nothing to align with yet,
  // and the few reference points near it (an edge an earlier scan glimpsed) would pick the shift
  // alone.
  if (options_.require_reference_support) {
    double supported_votes = 0.0;
    for (auto bin_votes = scan_votes.begin(); bin_votes != scan_votes.end();) {
      double nearby = 0.0;
      for (auto it = reference_votes.lower_bound(bin_votes->first - window);
           it != reference_votes.end() && it->first <= bin_votes->first + window; ++it) {
        nearby += it->second;
      }
      if (nearby >= options_.min_peak_votes) {
        supported_votes += bin_votes->second;
        ++bin_votes;
      } else {
        bin_votes = scan_votes.erase(bin_votes);
      }
    }
    if (supported_votes < options_.min_peak_votes) return false;
  }
  const auto correlation = [&](int k) {
    double sum = 0.0;
    for (const auto& [b, v] : scan_votes) {
      const auto it = reference_votes.find(b + k);
      if (it != reference_votes.end()) sum += v * it->second;
    }
    return sum;
  };
  *shift_m = BestShift(correlation, window) * bin;
  if (!match_points) return true;
  std::vector<double> voting;  // the scan points in bins that voted, in scan order
  for (double c : scan) {
    if (scan_votes.contains(bin_of(c))) voting.push_back(c);
  }
  const PointMatcher matcher(std::move(voting), std::move(reference), bin);
  const PointMatch at_peak = matcher.Match(*shift_m);
  // The correlation's shift is a match only where min_peak_votes scan points find a reference
  // point within a bin of them, as a peak needs min_peak_votes votes: its sum of products can peak
  // on a single pair (a wall seen for the first time against an unrelated point of the reference),
  // which moved the position by up to max_shift_m (docs/geometric_map.md, "Stop 54", "Stop 55").
  // Without such a match the axis is left alone, as without a peak.
  if (at_peak.matched_points < options_.min_peak_votes) return false;
  if (options_.refine_position) {
    *shift_m = RefineShift(matcher, at_peak, *shift_m, bin, options_.min_peak_votes);
  }
  return true;
}

msgs::Pose2D HistogramPoseCorrector::Correct(const msgs::Pose2D& X_OR,
                                             std::span<const RangePoint> points_R,
                                             std::span<const LineSegment> lines_R) {
  RequireFinitePose("X_OR", X_OR);
  msgs::Pose2D X_WR = X_WO_ * X_OR;
  const AngleHistogram predicted = MakeAngleHistogram(points_R, histogram_options_, X_WR.theta_rad);
  if (predicted.TotalVotes() < options_.min_virtual_lines) return X_WR;
  if (has_reference_ && options_.heading) {
    // The odometry's heading error since the last scan is at most what it turned (a wheel
    // spinning against a wall turns it 20 deg in half a second while the robot stands still).
    const double turned = std::abs(msgs::WrapAngle(X_OR.theta_rad - last_odometry_theta_rad_));
    const double window =
        std::min(options_.max_heading_step_deg * kDegToRad + turned, kMaxHeadingWindowRad);
    X_WR.theta_rad = msgs::WrapAngle(X_WR.theta_rad +
                                     HeadingCorrection(points_R, lines_R, X_WR.theta_rad, window));
  }
  // The first scan sets the map's main direction (its heading is the map frame's).
  if (!has_reference_) {
    map_angle_votes_.assign(predicted.votes.size(), 0.0);
    // alpha_max, refined on the fitted lines as the heading is (HeadingCorrection).
    map_alpha_rad_ = predicted.MainDirectionRad();
    double weighted = 0.0, weight = 0.0;
    for (const LineSegment& line : lines_R) {
      const Eigen::Vector2d d = line.end - line.start;
      const double residual =
          std::remainder(std::atan2(d.y(), d.x()) + X_WR.theta_rad - map_alpha_rad_, kPi / 2.0);
      if (std::abs(residual) > options_.refine_window_deg * kDegToRad) continue;
      weighted += line.num_points * residual;
      weight += line.num_points;
    }
    if (weight >= options_.min_peak_votes) map_alpha_rad_ += weighted / weight;
  }
  // The points on walls across each axis of the map's main frame (their virtual line square to
  // it): a wall along the axis has no distance there, and its points, denser on the side already
  // seen, would pull the shift back along the robot's path.
  const Eigen::Vector2d u(std::cos(map_alpha_rad_), std::sin(map_alpha_rad_)), v(-u.y(), u.x());
  std::vector<AxisPoint> points_W;
  const double max_tilt = histogram_options_.max_wall_tilt_deg * kDegToRad;
  for (const VirtualLine& line : MakeVirtualLines(points_R, histogram_options_)) {
    const double direction = line.direction_rad + X_WR.theta_rad;
    for (int axis = 0; axis < 2; ++axis) {
      // Square to u (axis 0) is along v, at map_alpha + pi/2.
      const double across = map_alpha_rad_ + (axis == 0 ? kPi / 2.0 : 0.0);
      if (std::abs(std::remainder(direction - across, kPi)) <= max_tilt) {
        points_W.push_back({ToWorld(X_WR, points_R[line.first].p_R), axis});
      }
    }
  }
  if (has_reference_ && options_.position) {
    const Eigen::Vector2d robot_W(X_WR.x_m, X_WR.y_m);
    Eigen::Vector2d move = Eigen::Vector2d::Zero();
    for (int axis = 0; axis < 2; ++axis) {
      const Eigen::Vector2d& direction = axis == 0 ? u : v;
      std::vector<double> coordinates;
      for (const AxisPoint& p : points_W) {
        if (p.axis == axis) coordinates.push_back(p.p_W.dot(direction));
      }
      double shift = 0.0;
      if (AxisShift(coordinates, axis, direction, robot_W, &shift)) move += shift * direction;
    }
    X_WR.x_m += move.x();
    X_WR.y_m += move.y();
    for (AxisPoint& p : points_W) p.p_W += move;
  }
  // The corrected scan joins the reference.
  has_reference_ = true;
  const AngleHistogram corrected = MakeAngleHistogram(points_R, histogram_options_, X_WR.theta_rad);
  for (std::size_t b = 0; b < corrected.votes.size(); ++b)
    map_angle_votes_[b] += corrected.votes[b];
  recent_points_W_.push_back(std::move(points_W));
  while (static_cast<int>(recent_points_W_.size()) > options_.reference_scans) {
    recent_points_W_.pop_front();
  }
  X_WO_ = X_WR * X_OR.Inverse();
  last_odometry_theta_rad_ = X_OR.theta_rad;
  return X_WR;
}

}  // namespace plywood::perception
