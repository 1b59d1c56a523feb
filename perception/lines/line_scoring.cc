#include "perception/lines/line_scoring.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "msgs/pose2d.h"

namespace plywood::perception {

void LineScoringOptions::Validate() const {
  if (!(max_alpha_diff_deg > 0.0)) throw std::invalid_argument("max_alpha_diff_deg: must be > 0");
  if (!(max_r_diff_m > 0.0)) throw std::invalid_argument("max_r_diff_m: must be > 0");
  if (!(min_overlap_fraction >= 0.0 && min_overlap_fraction <= 1.0)) {
    throw std::invalid_argument("min_overlap_fraction: must be in [0, 1]");
  }
  if (min_observed_rays < 1) throw std::invalid_argument("min_observed_rays: must be >= 1");
}

double LineScore::SigmaRM() const {
  return extracted_matched ? std::sqrt(sum_d_r_sq / extracted_matched) : 0.0;
}

double LineScore::SigmaAlphaDeg() const {
  return extracted_matched
             ? std::sqrt(sum_d_alpha_sq / extracted_matched) * 180.0 / std::numbers::pi
             : 0.0;
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

int MatchSegment(const LineSegment& segment, std::span<const TruthSegment> truth,
                 const LineScoringOptions& options, double* d_alpha_out, double* d_r_out) {
  const double max_alpha = options.max_alpha_diff_deg * std::numbers::pi / 180.0;
  int best = -1;
  double best_cost = 0.0;
  bool best_observed = false;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const TruthSegment& t = truth[k];
    const Eigen::Vector2d ab = t.b - t.a;
    const double length = ab.norm();
    if (length < 1e-9) continue;
    const Eigen::Vector2d u = ab / length;
    const Eigen::Vector2d n(u.y(), -u.x());
    double alpha = 0, r = 0;
    CanonicalNormalForm(std::atan2(n.y(), n.x()), n.dot(t.a), &alpha, &r);
    double d_alpha = 0, d_r = 0;
    NormalFormDifference(segment.alpha_rad, segment.r_m, alpha, r, &d_alpha, &d_r);
    if (std::abs(d_alpha) > max_alpha || std::abs(d_r) > options.max_r_diff_m) continue;
    // Overlap of the extracted segment's projection with [0, length].
    const double s0 = (segment.start - t.a).dot(u), s1 = (segment.end - t.a).dot(u);
    const double lo = std::min(s0, s1), hi = std::max(s0, s1);
    const double overlap = std::min(hi, length) - std::max(lo, 0.0);
    const double needed = options.min_overlap_fraction * (hi - lo);
    if (overlap < needed || overlap < 0.0) continue;
    const double cost = std::abs(d_alpha) / max_alpha + std::abs(d_r) / options.max_r_diff_m;
    const bool observed = t.observed_rays > 0;
    if (best < 0 || (observed && !best_observed) ||
        (observed == best_observed && cost < best_cost)) {
      best = static_cast<int>(k);
      best_cost = cost;
      best_observed = observed;
      if (d_alpha_out) *d_alpha_out = d_alpha;
      if (d_r_out) *d_r_out = d_r;
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
