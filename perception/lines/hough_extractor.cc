#include "perception/lines/hough_extractor.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "msgs/shortest_number.h"
#include "perception/lines/tls_line_fit.h"

namespace plywood::perception {

void HoughOptions::Validate() const {
  // The accumulator holds (180 / theta_bin_deg) x (2 rho_max / rho_bin_m) cells: these ranges keep
  // it under 15 million (60 MB) for any scan within kMaxHoughRangeM.
  if (!(theta_bin_deg >= 0.25 && theta_bin_deg <= 10.0)) {
    throw std::invalid_argument("theta_bin_deg: must be in [0.25, 10], got " +
                                msgs::ShortestNumber(theta_bin_deg));
  }
  if (!(rho_bin_m >= 0.01 && rho_bin_m <= 1.0)) {
    throw std::invalid_argument("rho_bin_m: must be in [0.01, 1], got " +
                                msgs::ShortestNumber(rho_bin_m));
  }
  if (min_votes < 2) throw std::invalid_argument("min_votes: must be >= 2");
  if (!(distance_threshold_m > 0.0))
    throw std::invalid_argument("distance_threshold_m: must be > 0");
  if (!(max_gap_m > 0.0)) throw std::invalid_argument("max_gap_m: must be > 0");
  if (min_points < 2) throw std::invalid_argument("min_points: must be >= 2");
  if (!(min_length_m >= 0.0)) throw std::invalid_argument("min_length_m: must be >= 0");
  if (max_lines < 1) throw std::invalid_argument("max_lines: must be >= 1");
  breakpoints.Validate();
  round_objects.Validate();
}

HoughExtractor::HoughExtractor(const HoughOptions& options) : options_(options) {
  options_.Validate();
}

std::vector<LineSegment> HoughExtractor::Run(const ScanPoints& scan,
                                             std::vector<CircleFeature>* circles) const {
  std::vector<LineSegment> out;
  const auto& p = scan.points;
  const int n = static_cast<int>(p.size());
  if (n < options_.min_votes) return out;
  // theta in [0, pi), rho in [-rho_max, rho_max].
  const int thetas = static_cast<int>(std::lround(180.0 / options_.theta_bin_deg));
  double rho_max = 0.0;
  for (const auto& q : p) rho_max = std::max(rho_max, q.norm());
  if (!(rho_max <= kMaxHoughRangeM)) {
    throw std::invalid_argument("scan: a point lies " + msgs::ShortestNumber(rho_max) +
                                " m from the sensor, beyond the Hough accumulator's " +
                                msgs::ShortestNumber(kMaxHoughRangeM) + " m");
  }
  const int rhos = 2 * static_cast<int>(std::ceil(rho_max / options_.rho_bin_m)) + 3;
  std::vector<double> cos_t(thetas), sin_t(thetas);
  for (int t = 0; t < thetas; ++t) {
    const double theta = (t + 0.5) * std::numbers::pi / thetas;
    cos_t[t] = std::cos(theta);
    sin_t[t] = std::sin(theta);
  }
  std::vector<int> votes(static_cast<std::size_t>(thetas) * rhos, 0);
  const auto vote = [&](int i, int delta) {
    for (int t = 0; t < thetas; ++t) {
      const double rho = p[i].x() * cos_t[t] + p[i].y() * sin_t[t];
      const int k = static_cast<int>(std::floor(rho / options_.rho_bin_m)) + rhos / 2;
      votes[static_cast<std::size_t>(t) * rhos + k] += delta;
    }
  };
  // Points on round objects never vote.
  const bool ordered = scan.HasScanOrder();
  std::vector<char> removed =
      ordered ? RoundObjectPoints(scan, options_.breakpoints, options_.distance_threshold_m,
                                  options_.round_objects, circles)
              : std::vector<char>(n, 0);
  for (int i = 0; i < n; ++i)
    if (!removed[i]) vote(i, 1);
  const double tol = options_.distance_threshold_m;
  for (int round = 0; round < options_.max_lines; ++round) {
    const auto peak = std::max_element(votes.begin(), votes.end());
    if (*peak < options_.min_votes) break;
    const std::size_t cell = static_cast<std::size_t>(peak - votes.begin());
    const int t = static_cast<int>(cell / rhos);
    const double rho = (static_cast<int>(cell % rhos) - rhos / 2 + 0.5) * options_.rho_bin_m;
    std::vector<int> inliers;
    for (int i = 0; i < n; ++i)
      if (!removed[i] && std::abs(p[i].x() * cos_t[t] + p[i].y() * sin_t[t] - rho) <= tol)
        inliers.push_back(i);
    double alpha = std::atan2(sin_t[t], cos_t[t]), r = rho;
    if (inliers.size() >= 2) {
      LineMoments m;
      for (int i : inliers) m.Add(p[i]);
      m.Fit(&alpha, &r);
      std::vector<int> refined;
      for (int i = 0; i < n; ++i)
        if (!removed[i] &&
            std::abs(p[i].x() * std::cos(alpha) + p[i].y() * std::sin(alpha) - r) <= tol)
          refined.push_back(i);
      if (refined.size() >= inliers.size() / 2) inliers = std::move(refined);
    }
    if (inliers.empty()) {
      votes[cell] = 0;  // a cell voted by points that now all belong to earlier lines
      continue;
    }
    const std::vector<std::vector<int>> runs =
        ordered ? SplitRunsInScan(scan, inliers, alpha, options_.max_gap_m,
                                  options_.breakpoints.max_missing_beams)
                : SplitRunsAlongLine(p, inliers, alpha, options_.max_gap_m);
    for (const std::vector<int>& run : runs) {
      if (static_cast<int>(run.size()) < options_.min_points) continue;
      LineSegment s = FitSegmentTrimmed(p, run);
      if (s.LengthM() < options_.min_length_m) continue;
      out.push_back(s);
    }
    for (int i : inliers) {
      removed[i] = 1;
      vote(i, -1);
    }
  }
  return out;
}

}  // namespace plywood::perception
