#pragma once

#include <Eigen/Core>
#include <array>

#include "msgs/range_ring.h"

namespace plywood::perception {

// The inputs seed 001 (after Thrun 1998) gives the sonar interpretation network for one cell of the
// robot-centred grid: the readings of the three transducers whose axes point nearest the cell
// (nearest first), the angle of the cell centre relative to the first transducer's axis, and the
// distance of the cell centre from the robot centre. A transducer that heard nothing reads
// range_max_m: a specular miss looks like free space to the network, as on the real robot.
struct SonarCellFeatures {
  std::array<double, 3> range_m{};
  double angle_rad = 0.0;
  double distance_m = 0.0;
};

// p_R: cell centre in the robot frame. A transducer without a usable echo (RangeReading::HeardEcho)
// reads range_max_m; transducers whose X_RS.theta_rad is not finite are left out.
// @throws std::invalid_argument naming the field when range_max_m is not a finite number > 0 or
// fewer than 3 transducers have a finite heading.
SonarCellFeatures ComputeCellFeatures(const msgs::RangeRing& ring, const Eigen::Vector2d& p_R);

// The features scaled to about [-1, 1], the network's input vector.
Eigen::Matrix<double, 5, 1> NormalisedFeatures(const SonarCellFeatures& f, double range_max_m);

// Anything that turns one sonar ring into P(occupied) for a point near the robot.
class SonarCellModel {
 public:
  virtual ~SonarCellModel() = default;
  // P(occupied | ring) of the cell centred on p_R (robot frame).
  virtual double Probability(const msgs::RangeRing& ring, const Eigen::Vector2d& p_R) const = 0;
};

// The classical inverse sensor model of Elfes (1987) and Moravec & Elfes (1985): each transducer's
// cone (half-angle beam_half_angle_deg) says "free" up to its echo, "occupied" on an arc of width
// 2 * arc_half_width_m around the echo, and nothing beyond, both weighted by (1 - (phi/half)^2) so
// the cone's axis counts most. Cones overlapping a cell add their log-odds. A transducer without an
// echo (RangeReading::HeardEcho) or without a finite pose says nothing: on smooth plywood a miss is
// usually specular, not free space.
struct ClassicalSonarOptions {
  double beam_half_angle_deg = 15.0;
  double arc_half_width_m = 0.05;
  double p_occupied = 0.8;  // on the axis, at the echo
  double p_free = 0.3;      // on the axis, before the echo
  // @throws std::invalid_argument naming the field.
  void Validate() const;
};

class ClassicalSonarModel final : public SonarCellModel {
 public:
  explicit ClassicalSonarModel(const ClassicalSonarOptions& options = {});
  double Probability(const msgs::RangeRing& ring, const Eigen::Vector2d& p_R) const override;

 private:
  ClassicalSonarOptions options_;
};

}  // namespace plywood::perception
