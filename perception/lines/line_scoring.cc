#include "perception/lines/line_scoring.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "msgs/pose2d.h"
#include "msgs/shortest_number.h"

namespace plywood::perception {

void LineScoringOptions::Validate() const {
  // A segment a metre off a wall's line is no estimate of it. Beyond, parallel walls across a room
  // pass the gate (10 m: a segment matched across the office, sigma_r 0.26 m), and by 1e300 the
  // gate's share of MatchSegment's cost is lost to rounding: the nearest wall no longer won
  // (recall 0.96 -> 0.65, sigma_r 3.2 m).
  if (!(max_endpoint_distance_m > 0.0 && max_endpoint_distance_m <= 1.0)) {
    throw std::invalid_argument("max_endpoint_distance_m: must be in (0, 1] m, got " +
                                msgs::ShortestNumber(max_endpoint_distance_m));
  }
  if (!(max_alpha_diff_deg > 0.0 && max_alpha_diff_deg < 90.0)) {
    throw std::invalid_argument("max_alpha_diff_deg: must be in (0, 90)");
  }
  if (!(range_noise_sigma_m >= 0.0 && range_noise_sigma_m <= 1.0)) {
    throw std::invalid_argument("range_noise_sigma_m: must be in [0, 1]");
  }
  if (!(direction_sigmas >= 0.0 && direction_sigmas <= 10.0)) {
    throw std::invalid_argument("direction_sigmas: must be in [0, 10]");
  }
  if (!(min_overlap_fraction >= 0.0 && min_overlap_fraction <= 1.0)) {
    throw std::invalid_argument("min_overlap_fraction: must be in [0, 1]");
  }
  if (min_observed_rays < 1) throw std::invalid_argument("min_observed_rays: must be >= 1");
}

// No matched line, no error to measure: NaN (metrics.json's null). 0 read as a perfect fit:
// seed004_ransac with ransac.distance_threshold_m 1e-300 found no line and reported sigma_r_m 0,
// sigma_alpha_deg 0 beside recall 0, exit 0 (s62).
double LineScore::SigmaRM() const {
  return extracted_matched ? std::sqrt(sum_d_r_sq / extracted_matched)
                           : std::numeric_limits<double>::quiet_NaN();
}

double LineScore::SigmaAlphaDeg() const {
  return extracted_matched
             ? std::sqrt(sum_d_alpha_sq / extracted_matched) * 180.0 / std::numbers::pi
             : std::numeric_limits<double>::quiet_NaN();
}

void LineScore::Add(const LineScore& o) {
  scans += o.scans;
  observable += o.observable;
  observable_matched += o.observable_matched;
  extracted += o.extracted;
  extracted_matched += o.extracted_matched;
  points += o.points;
  sum_d_r_sq += o.sum_d_r_sq;
  sum_d_alpha_sq += o.sum_d_alpha_sq;
}

void NormalFormDifference(double alpha_1, double r_1, double alpha_2, double r_2, double* d_alpha,
                          double* d_r) {
  const double direct = msgs::WrapAngle(alpha_1 - alpha_2);
  const double flipped = msgs::WrapAngle(alpha_1 - alpha_2 - std::numbers::pi);
  if (std::abs(direct) <= std::abs(flipped)) {
    *d_alpha = direct;
    *d_r = r_1 - r_2;
  } else {
    *d_alpha = flipped;
    *d_r = r_1 + r_2;
  }
}

double DirectionToleranceRad(double length_m, int num_points, const LineScoringOptions& options) {
  const double floor = options.max_alpha_diff_deg * std::numbers::pi / 180.0;
  const double n = std::max(2, num_points);
  const double spread_m2 = length_m * length_m * n * (n + 1.0) / (12.0 * (n - 1.0));
  if (!(spread_m2 > 0.0)) return std::numbers::pi / 2.0;
  const double sigma_theta = options.range_noise_sigma_m / std::sqrt(spread_m2);
  return std::min(std::numbers::pi / 2.0, std::max(floor, options.direction_sigmas * sigma_theta));
}

std::optional<FaceMatch> MatchFace(const LineSegment& segment, const TruthSegment& face,
                                   const LineScoringOptions& options) {
  const Eigen::Vector2d ab = face.b - face.a;
  const double length = ab.norm();
  if (length < 1e-9) return std::nullopt;
  const Eigen::Vector2d u = ab / length;
  const Eigen::Vector2d n(u.y(), -u.x());
  // A segment that is not finite matches nothing: every test below is written so that NaN fails
  // it (a NaN segment from a plug-in used to pass them all and count as found).
  if (!segment.start.allFinite() || !segment.end.allFinite() || !std::isfinite(segment.alpha_rad) ||
      !std::isfinite(segment.r_m)) {
    return std::nullopt;
  }
  FaceMatch match;
  // (1) Both endpoints near the face's line.
  match.endpoint_distance_m =
      std::max(std::abs(n.dot(segment.start - face.a)), std::abs(n.dot(segment.end - face.a)));
  if (!(match.endpoint_distance_m <= options.max_endpoint_distance_m)) return std::nullopt;
  // (2) Direction, within what the segment's length and points allow. A segment of no length (its
  // ends one point) has no direction, so it matches nothing: taken as parallel to every face it
  // touched, a plug-in's one-point "segments" scored recall 1 and precision 0.94.
  const Eigen::Vector2d d = segment.end - segment.start;
  const double segment_length = d.norm();
  if (!(segment_length > 1e-12)) return std::nullopt;
  match.angle_rad = std::atan2(std::abs(d.x() * u.y() - d.y() * u.x()), std::abs(d.dot(u)));
  match.angle_tolerance_rad = DirectionToleranceRad(segment_length, segment.num_points, options);
  if (!(match.angle_rad <= match.angle_tolerance_rad)) return std::nullopt;
  // (3) Overlap of the segment's projection with the face [0, length].
  const double s0 = (segment.start - face.a).dot(u), s1 = (segment.end - face.a).dot(u);
  const double lo = std::min(s0, s1), hi = std::max(s0, s1);
  const double overlap = std::min(hi, length) - std::max(lo, 0.0);
  if (!(overlap >= 0.0 && overlap >= options.min_overlap_fraction * (hi - lo))) return std::nullopt;
  double alpha = 0, r = 0;
  CanonicalNormalForm(std::atan2(n.y(), n.x()), n.dot(face.a), &alpha, &r);
  NormalFormDifference(segment.alpha_rad, segment.r_m, alpha, r, &match.d_alpha_rad, &match.d_r_m);
  return match;
}

int MatchSegment(const LineSegment& segment, std::span<const TruthSegment> truth,
                 const LineScoringOptions& options, double* d_alpha_out, double* d_r_out) {
  int best = -1;
  double best_cost = 0.0;
  bool best_observed = false;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const std::optional<FaceMatch> match = MatchFace(segment, truth[k], options);
    if (!match) continue;
    const double cost = match->endpoint_distance_m / options.max_endpoint_distance_m +
                        match->angle_rad / match->angle_tolerance_rad;
    const bool observed = truth[k].observed_rays > 0;
    if (best < 0 || (observed && !best_observed) ||
        (observed == best_observed && cost < best_cost)) {
      best = static_cast<int>(k);
      best_cost = cost;
      best_observed = observed;
      if (d_alpha_out) *d_alpha_out = match->d_alpha_rad;
      if (d_r_out) *d_r_out = match->d_r_m;
    }
  }
  return best;
}

LineScore ScoreScan(std::span<const LineSegment> extracted, std::span<const TruthSegment> truth,
                    long used_points, const LineScoringOptions& options) {
  LineScore score;
  score.scans = 1;
  score.points = used_points;
  score.extracted = static_cast<long>(extracted.size());
  std::vector<char> matched(truth.size(), 0);
  for (const LineSegment& s : extracted) {
    double d_alpha = 0, d_r = 0;
    const int k = MatchSegment(s, truth, options, &d_alpha, &d_r);
    if (k < 0) continue;
    matched[k] = 1;
    ++score.extracted_matched;
    score.sum_d_alpha_sq += d_alpha * d_alpha;
    score.sum_d_r_sq += d_r * d_r;
  }
  for (std::size_t k = 0; k < truth.size(); ++k) {
    if (truth[k].observed_rays < options.min_observed_rays) continue;
    ++score.observable;
    score.observable_matched += matched[k];
  }
  return score;
}

}  // namespace plywood::perception
