#include "perception/lines/polar_neighbour_extractor.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "msgs/shortest_number.h"
#include "perception/lines/tls_line_fit.h"

namespace plywood::perception {

void PolarNeighbourOptions::Validate() const {
  const auto positive = [](const char* name, double v) {
    if (!(v > 0.0))
      throw std::invalid_argument(std::string(name) + ": must be > 0, got " +
                                  msgs::ShortestNumber(v));
  };
  positive("max_point_distance_m", max_point_distance_m);
  positive("max_alpha_diff_deg", max_alpha_diff_deg);
  positive("max_r_diff_m", max_r_diff_m);
  positive("max_range_m", max_range_m);
  if (min_points < 2) {
    throw std::invalid_argument("min_points: must be >= 2, got " + std::to_string(min_points));
  }
  ValidateMaxMissingBeams(max_missing_beams);
}

PolarNeighbourExtractor::PolarNeighbourExtractor(const PolarNeighbourOptions& options)
    : options_(options) {
  options_.Validate();
}

std::vector<LineSegment> PolarNeighbourExtractor::Extract(const ScanPoints& scan) const {
  std::vector<LineSegment> out;
  // Points within the range cut, in scan order.
  std::vector<int> used;
  for (int i = 0; i < static_cast<int>(scan.size()); ++i)
    if (scan.range_m[i] <= options_.max_range_m) used.push_back(i);
  const int n = static_cast<int>(used.size());
  if (n < options_.min_points) return out;
  const auto& p = scan.points;
  const double max_d = options_.max_point_distance_m;
  const double max_alpha = options_.max_alpha_diff_deg * std::numbers::pi / 180.0;
  const bool closed = scan.closed;
  // a before b in scan order.
  const auto close = [&](int a, int b) {
    return (p[used[a]] - p[used[b]]).norm() <= max_d &&
           !OpeningBetween(scan, used[a], used[b], options_.max_missing_beams);
  };
  // Local line of each point from itself and its close neighbours (two points at a chain's end).
  std::vector<double> alpha(n, 0.0), r(n, 0.0);
  std::vector<char> has_line(n, 0);
  for (int k = 0; k < n; ++k) {
    LineMoments m;
    m.Add(p[used[k]]);
    const int previous = k > 0 ? k - 1 : (closed ? n - 1 : -1);
    const int next = k + 1 < n ? k + 1 : (closed ? 0 : -1);
    if (previous >= 0 && previous != k && close(previous, k)) m.Add(p[used[previous]]);
    if (next >= 0 && next != k && next != previous && close(k, next)) m.Add(p[used[next]]);
    if (m.count() < 2) continue;
    m.Fit(&alpha[k], &r[k]);
    has_line[k] = 1;
  }
  const auto agree = [&](int a, int b) {
    if (!has_line[a] || !has_line[b] || !close(a, b)) return false;
    // Compare (alpha, r) allowing for the normal flipping when a line passes near the origin.
    const double da = AngleDifferenceRad(alpha[a], alpha[b]);
    const double da_flip = AngleDifferenceRad(alpha[a], alpha[b] + std::numbers::pi);
    if (da <= max_alpha && std::abs(r[a] - r[b]) <= options_.max_r_diff_m) return true;
    return da_flip <= max_alpha && r[a] + r[b] <= options_.max_r_diff_m;
  };
  // Chains; for a closed scan start after a break so no chain is cut at the seam.
  int start = 0;
  if (closed) {
    for (int k = 0; k < n; ++k)
      if (!agree((k + n - 1) % n, k)) {
        start = k;
        break;
      }
  }
  std::vector<int> chain;
  const auto flush = [&]() {
    if (static_cast<int>(chain.size()) >= options_.min_points)
      out.push_back(FitSegmentTls(p, chain));
    chain.clear();
  };
  for (int j = 0; j < n; ++j) {
    const int k = (start + j) % n;
    if (!chain.empty() && !agree((k + n - 1) % n, k)) flush();
    chain.push_back(used[k]);
  }
  flush();
  return out;
}

}  // namespace plywood::perception
