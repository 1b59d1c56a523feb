#include "perception/sonar_map/sonar_cell_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/angle_units.h"
#include "msgs/pose2d.h"
#include "msgs/shortest_number.h"

namespace plywood::perception {
namespace {

double Logit(double p) { return std::log(p / (1.0 - p)); }

}  // namespace

SonarCellFeatures ComputeCellFeatures(const msgs::RangeRing& ring, const Eigen::Vector2d& p_R) {
  if (!(ring.range_max_m > 0.0 && ring.range_max_m < std::numeric_limits<double>::infinity())) {
    throw std::invalid_argument("range_max_m: must be a finite number > 0, got " +
                                msgs::ShortestNumber(ring.range_max_m));
  }
  const double bearing = std::atan2(p_R.y(), p_R.x());
  // Three smallest angular offsets; ties go to the lower index so the choice is deterministic.
  std::array<int, 3> best{-1, -1, -1};
  std::array<double, 3> best_offset{1e9, 1e9, 1e9};
  for (int i = 0; i < static_cast<int>(ring.readings.size()); ++i) {
    const double offset = std::abs(msgs::WrapAngle(bearing - ring.readings[i].X_RS.theta_rad));
    for (int k = 0; k < 3; ++k) {
      if (offset < best_offset[k]) {
        for (int j = 2; j > k; --j) {
          best[j] = best[j - 1];
          best_offset[j] = best_offset[j - 1];
        }
        best[k] = i;
        best_offset[k] = offset;
        break;
      }
    }
  }
  // A NaN heading is never nearest: with fewer than 3 usable transducers best[2] stays -1.
  if (best[2] < 0) {
    const int usable =
        static_cast<int>(std::count_if(best.begin(), best.end(), [](int i) { return i >= 0; }));
    throw std::invalid_argument(
        ring.readings.size() < 3
            ? "readings: need at least 3 transducers, got " + std::to_string(ring.readings.size())
            : "readings: need at least 3 transducers with a finite X_RS.theta_rad, got " +
                  std::to_string(usable));
  }
  SonarCellFeatures f;
  for (int k = 0; k < 3; ++k) {
    const msgs::RangeReading& r = ring.readings[best[k]];
    f.range_m[k] = r.HeardEcho() ? std::min(r.range_m, ring.range_max_m) : ring.range_max_m;
  }
  f.angle_rad = msgs::WrapAngle(bearing - ring.readings[best[0]].X_RS.theta_rad);
  f.distance_m = p_R.norm();
  return f;
}

Eigen::Matrix<double, 5, 1> NormalisedFeatures(const SonarCellFeatures& f, double range_max_m) {
  // Ranges and distance are scaled so that the interesting 0..1.5 m band spans about [-1, 1]
  // (squashed beyond it); the angle by half the 22.5 deg spacing of a 16-transducer ring.
  Eigen::Matrix<double, 5, 1> x;
  for (int k = 0; k < 3; ++k) x(k) = std::tanh(f.range_m[k] / 1.5) * 2.0 - 1.0;
  x(3) = f.angle_rad / (kPi / 16.0);
  x(4) = f.distance_m / 0.5 - 1.0;
  (void)range_max_m;
  return x;
}

void ClassicalSonarOptions::Validate() const {
  if (!(beam_half_angle_deg > 0.0 && beam_half_angle_deg < 90.0))
    throw std::invalid_argument("beam_half_angle_deg: must be in (0, 90), got " +
                                msgs::ShortestNumber(beam_half_angle_deg));
  if (!(arc_half_width_m > 0.0))
    throw std::invalid_argument("arc_half_width_m: must be > 0, got " +
                                msgs::ShortestNumber(arc_half_width_m));
  if (!(p_occupied > 0.5 && p_occupied < 1.0))
    throw std::invalid_argument("p_occupied: must be in (0.5, 1), got " +
                                msgs::ShortestNumber(p_occupied));
  if (!(p_free > 0.0 && p_free < 0.5))
    throw std::invalid_argument("p_free: must be in (0, 0.5), got " + msgs::ShortestNumber(p_free));
}

ClassicalSonarModel::ClassicalSonarModel(const ClassicalSonarOptions& options) : options_(options) {
  options_.Validate();
}

double ClassicalSonarModel::Probability(const msgs::RangeRing& ring,
                                        const Eigen::Vector2d& p_R) const {
  const double half = options_.beam_half_angle_deg * kPi / 180.0;
  double log_odds = 0.0;
  for (const msgs::RangeReading& r : ring.readings) {
    if (!r.HeardEcho()) continue;
    const Eigen::Vector2d d(p_R.x() - r.X_RS.x_m, p_R.y() - r.X_RS.y_m);
    const double dist = d.norm();
    const double phi = msgs::WrapAngle(std::atan2(d.y(), d.x()) - r.X_RS.theta_rad);
    if (!(std::abs(phi) <= half)) continue;  // a transducer without a pose (NaN) says nothing
    const double w = 1.0 - (phi / half) * (phi / half);
    if (std::abs(dist - r.range_m) <= options_.arc_half_width_m) {
      log_odds += w * Logit(options_.p_occupied);
    } else if (dist < r.range_m) {
      log_odds += w * Logit(options_.p_free);
    }
  }
  return 1.0 / (1.0 + std::exp(-log_odds));
}

}  // namespace plywood::perception
