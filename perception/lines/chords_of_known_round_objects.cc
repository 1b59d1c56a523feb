#include "perception/lines/chords_of_known_round_objects.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"

namespace plywood::perception {
namespace {

// The scan points a line was fitted to: its index range (wrapping past the seam of a closed
// scan), or the points near the segment when the extractor gave no range.
std::vector<Eigen::Vector2d> PointsOf(const ScanPoints& scan, const LineSegment& line,
                                      double near_m) {
  std::vector<Eigen::Vector2d> out;
  const int n = static_cast<int>(scan.size());
  if (line.first_index >= 0 && line.last_index >= 0 && line.first_index < n &&
      line.last_index < n) {
    for (int i = line.first_index;; i = (i + 1) % n) {
      out.push_back(scan.points[i]);
      if (i == line.last_index || static_cast<int>(out.size()) >= n) break;
    }
    return out;
  }
  for (const Eigen::Vector2d& p : scan.points)
    if (line.SegmentDistance(p) <= near_m) out.push_back(p);
  return out;
}

void RequirePositive(const std::string& field, double value) {
  if (!(std::isfinite(value) && value > 0.0))
    throw std::invalid_argument(field + ": must be a finite number > 0, got " +
                                msgs::ShortestNumber(value));
}

// Every number the test compares: with a NaN or a fraction of 0 it would keep (or remove) lines
// whatever the scan says.
void Validate(std::span<const CircleFeature> known_round_objects, double noise_sigma_m,
              const KnownRoundObjectOptions& options) {
  RequirePositive("noise_sigma_m", noise_sigma_m);
  RequirePositive("rim_sigmas", options.rim_sigmas);
  if (!(options.min_on_rim_fraction > 0.0 && options.min_on_rim_fraction <= 1.0))
    throw std::invalid_argument("min_on_rim_fraction: must be in (0, 1], got " +
                                msgs::ShortestNumber(options.min_on_rim_fraction));
  for (std::size_t i = 0; i < known_round_objects.size(); ++i) {
    const CircleFeature& circle = known_round_objects[i];
    const std::string field = "known_round_objects[" + std::to_string(i) + "]";
    if (!circle.centre.allFinite())
      throw std::invalid_argument(field + ".centre: must be finite, got (" +
                                  msgs::ShortestNumber(circle.centre.x()) + ", " +
                                  msgs::ShortestNumber(circle.centre.y()) + ")");
    RequirePositive(field + ".radius_m", circle.radius_m);
  }
}

bool IsChordOf(const std::vector<Eigen::Vector2d>& points, const LineSegment& line,
               const CircleFeature& circle, double tolerance_m, double min_fraction) {
  if (line.LengthM() > 2.0 * circle.radius_m + tolerance_m) return false;
  const auto on_rim = std::count_if(points.begin(), points.end(), [&](const Eigen::Vector2d& p) {
    return circle.RimDistance(p) <= tolerance_m;
  });
  return static_cast<double>(on_rim) >= min_fraction * static_cast<double>(points.size());
}

}  // namespace

int RemoveChordsOfKnownRoundObjects(const ScanPoints& scan,
                                    std::span<const CircleFeature> known_round_objects,
                                    double noise_sigma_m, const KnownRoundObjectOptions& options,
                                    std::vector<LineSegment>* lines) {
  if (known_round_objects.empty()) return 0;
  Validate(known_round_objects, noise_sigma_m, options);
  const double tolerance_m = options.rim_sigmas * noise_sigma_m;
  const auto chord = [&](const LineSegment& line) {
    const std::vector<Eigen::Vector2d> points = PointsOf(scan, line, tolerance_m);
    if (points.size() < 2) return false;
    return std::any_of(
        known_round_objects.begin(), known_round_objects.end(), [&](const CircleFeature& circle) {
          return IsChordOf(points, line, circle, tolerance_m, options.min_on_rim_fraction);
        });
  };
  const auto removed = std::remove_if(lines->begin(), lines->end(), chord);
  const int count = static_cast<int>(lines->end() - removed);
  lines->erase(removed, lines->end());
  return count;
}

}  // namespace plywood::perception
