#pragma once

#include <Eigen/Core>
#include <vector>

#include "msgs/pose2d.h"
#include "msgs/range_ring.h"
#include "perception/sonar_map/log_odds_grid.h"

namespace plywood::perception {

// Which constants decide that a sonar beam's axis saw a cell free (BeamFreeGrid).
struct BeamFreeOptions {
  // Only transducers whose axis lies within this of a grid axis count: in a room of axis-parallel
  // walls and boxes, such an axis meets any face it crosses either nearly head-on (within the
  // sonar's incidence limit, so that face echoes and ends the reading before it) or nearly
  // parallel (a few cm of grazing at most). Oblique axes pass through corners they never hear.
  double axis_tolerance_rad = 10.0 * 3.14159265358979323846 / 180.0;
  // The axis is free from the transducer up to the echo less this (the echo's own cell, and the
  // range noise, stay out).
  double stop_short_m = 0.05;
  // Echoes farther than this are not used.
  double max_range_m = 5.0;
  // @throws std::invalid_argument naming the field.
  void Validate() const;
};

// The classical long-range free-space evidence beside the sonar network, which sees only its
// +-0.7 m local grid: for every echo of a transducer whose axis is within axis_tolerance_rad of a
// grid axis, each cell the axis passes through up to the echo (less stop_short_m) gets one pass.
// A reading that heard nothing (specular miss) says nothing. Same cells as the LogOddsGrid it
// shadows.
class BeamFreeGrid {
 public:
  BeamFreeGrid() = default;
  BeamFreeGrid(const LogOddsGridOptions& geometry, const BeamFreeOptions& options);

  void Integrate(const msgs::RangeRing& ring, const msgs::Pose2D& X_WR);
  // Readings whose axis passed through cell (ix, iy); 0 outside the grid.
  int Passes(int ix, int iy) const;
  // Echoes of such readings whose point lies in cell (ix, iy), by the grid direction the axis
  // pointed in (kWest: -x, kEast: +x, kSouth: -y, kNorth: +y); 0 outside the grid. The cells up to
  // such an echo were passed (Passes), so the face it came from bounds space seen free.
  enum Direction { kWest = 0, kEast = 1, kSouth = 2, kNorth = 3 };
  int Echoes(int ix, int iy, Direction direction) const;
  // Where each such echo puts the face it came from: an axis within axis_tolerance_rad of the
  // face's normal hears the face's nearest point (the perpendicular foot, inside the beam), so the
  // face lies `range` from the transducer along the grid axis, whatever the tilt: `face` is that
  // coordinate (x for kWest / kEast, y for kSouth / kNorth), `lateral` the transducer's other
  // coordinate (where that foot lies along the face, when the face reaches that far), `direction`
  // as for Echoes.
  struct FaceEcho {
    Direction direction;
    double face;
    double lateral;
  };
  const std::vector<FaceEcho>& face_echoes() const { return face_echoes_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  std::size_t Index(int ix, int iy) const { return static_cast<std::size_t>(iy) * width_ + ix; }
  LogOddsGridOptions geometry_;
  BeamFreeOptions options_;
  int width_ = 0, height_ = 0;
  std::vector<int> passes_;
  std::vector<int> echoes_[4];
  std::vector<FaceEcho> face_echoes_;
};

}  // namespace plywood::perception
