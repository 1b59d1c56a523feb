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
  // A transducer whose axis lies more than axis_tolerance_rad but at most this off a grid axis
  // places the face it heard too (oblique_face_echoes), for moving the room's sides out only: an
  // axis-parallel wall echoes at all only while the cone's ray nearest its normal meets it within
  // the sonar's incidence limit, and that ray's echo is the nearest, so the reading is the wall's
  // distance over cos(off - half_angle_rad). 35 deg is the beam's half-angle plus the 20 deg a
  // smooth plywood face still echoes at (the axis-to-normal angle Pioneer users see a wall at).
  // The default, 30 deg, keeps 5 deg of that incidence margin for the heading's error: from 31-35
  // deg off, a few degrees of encoder heading turned a corner's echo into a wall's and put a side
  // 0.8-1.1 m beyond a wall (issue 14 round 39c). 0 (or up to axis_tolerance_rad): none.
  double oblique_face_max_rad = 30.0 * 3.14159265358979323846 / 180.0;
  // The beam's half-angle (Polaroid 6500: about 15 deg, 30 deg full opening).
  double half_angle_rad = 15.0 * 3.14159265358979323846 / 180.0;
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

  // An echo without a usable range (RangeReading::HeardEcho) says nothing; an X_WR that is not
  // finite throws std::invalid_argument naming it, nothing written.
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
  // The same for the transducers between axis_tolerance_rad and oblique_face_max_rad off a grid
  // axis: the face perpendicular to that grid axis lies range * cos(max(off - half_angle_rad, 0))
  // from the transducer along it (the cone's ray nearest the face's normal heard it; inside the
  // beam that ray is the normal itself), `lateral` where that ray meets it; `from_face` and
  // `from_lateral` are the transducer's coordinates the same way round, so that ray runs from
  // (from_face, from_lateral) to (face, lateral). Such an axis passes convex corners it never
  // hears, so it gives no Passes and no Echoes.
  struct ObliqueFaceEcho {
    FaceEcho echo;
    double from_face;
    double from_lateral;
  };
  const std::vector<ObliqueFaceEcho>& oblique_face_echoes() const { return oblique_face_echoes_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  std::size_t Index(int ix, int iy) const { return static_cast<std::size_t>(iy) * width_ + ix; }
  // The grid direction of the axis `off` away from `heading` (std::remainder(heading, pi / 2)).
  static Direction AxisDirection(double heading, double off);
  void AddObliqueFace(const msgs::RangeReading& reading, const msgs::Pose2D& X_WR, double heading,
                      double off);
  LogOddsGridOptions geometry_;
  BeamFreeOptions options_;
  int width_ = 0, height_ = 0;
  std::vector<int> passes_;
  std::vector<int> echoes_[4];
  std::vector<FaceEcho> face_echoes_;
  std::vector<ObliqueFaceEcho> oblique_face_echoes_;
};

}  // namespace plywood::perception
