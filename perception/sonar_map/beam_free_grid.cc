#include "perception/sonar_map/beam_free_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "msgs/pose2d.h"

namespace plywood::perception {

void BeamFreeOptions::Validate() const {
  if (!(axis_tolerance_rad >= 0.0 && axis_tolerance_rad <= 0.25 * 3.14159265358979323846))
    throw std::invalid_argument("axis_tolerance_rad: must be in [0, pi/4]");
  if (!(std::isfinite(stop_short_m) && stop_short_m >= 0.0))
    throw std::invalid_argument("stop_short_m: must be a finite number >= 0");
  if (!(std::isfinite(max_range_m) && max_range_m > 0.0))
    throw std::invalid_argument("max_range_m: must be a finite number > 0");
  if (!(oblique_face_max_rad >= 0.0 && oblique_face_max_rad <= 0.25 * 3.14159265358979323846))
    throw std::invalid_argument("oblique_face_max_rad: must be in [0, pi/4]");
  if (!(half_angle_rad >= 0.0 && half_angle_rad <= 0.25 * 3.14159265358979323846))
    throw std::invalid_argument("half_angle_rad: must be in [0, pi/4]");
}

BeamFreeGrid::BeamFreeGrid(const LogOddsGridOptions& geometry, const BeamFreeOptions& options)
    : geometry_(geometry), options_(options), width_(geometry.width), height_(geometry.height) {
  geometry_.Validate();
  options_.Validate();
  passes_.assign(static_cast<std::size_t>(width_) * height_, 0);
  for (std::vector<int>& echoes : echoes_) echoes.assign(passes_.size(), 0);
}

int BeamFreeGrid::Echoes(int ix, int iy, Direction direction) const {
  if (ix < 0 || iy < 0 || ix >= width_ || iy >= height_) return 0;
  return echoes_[direction][Index(ix, iy)];
}

int BeamFreeGrid::Passes(int ix, int iy) const {
  if (ix < 0 || iy < 0 || ix >= width_ || iy >= height_) return 0;
  return passes_[Index(ix, iy)];
}

BeamFreeGrid::Direction BeamFreeGrid::AxisDirection(double heading, double off) {
  const double half_pi = 0.5 * 3.14159265358979323846;
  const double axis = std::remainder(heading - off, 2.0 * 3.14159265358979323846);
  return std::abs(axis) < 0.25 * half_pi                             ? kEast
         : std::abs(std::abs(axis) - 2.0 * half_pi) < 0.25 * half_pi ? kWest
         : axis > 0.0                                                ? kNorth
                                                                     : kSouth;
}

void BeamFreeGrid::AddObliqueFace(const msgs::RangeReading& reading, const msgs::Pose2D& X_WR,
                                  double heading, double off) {
  const msgs::Pose2D X_WS = X_WR * reading.X_RS;
  const Direction direction = AxisDirection(heading, off);
  // The cone's ray nearest the normal, its angle from the normal on the axis' side.
  const double tilt = std::max(std::abs(off) - options_.half_angle_rad, 0.0);
  const double depth = reading.range_m * std::cos(tilt);
  const double across = depth * std::tan(tilt) * (off > 0.0 ? 1.0 : -1.0);
  // `across` is measured counter-clockwise of the grid axis: +y for kEast, -y for kWest, -x for
  // kNorth, +x for kSouth.
  const bool along_x = direction == kEast || direction == kWest;
  const double from_face = along_x ? X_WS.x_m : X_WS.y_m;
  const double from_lateral = along_x ? X_WS.y_m : X_WS.x_m;
  FaceEcho echo{direction, 0.0, 0.0};
  switch (direction) {
    case kEast:
      echo = {direction, from_face + depth, from_lateral + across};
      break;
    case kWest:
      echo = {direction, from_face - depth, from_lateral - across};
      break;
    case kNorth:
      echo = {direction, from_face + depth, from_lateral - across};
      break;
    case kSouth:
      echo = {direction, from_face - depth, from_lateral + across};
      break;
  }
  oblique_face_echoes_.push_back({echo, from_face, from_lateral});
}

void BeamFreeGrid::Integrate(const msgs::RangeRing& ring, const msgs::Pose2D& X_WR) {
  const double half_pi = 0.5 * 3.14159265358979323846;
  const double res = geometry_.resolution_m;
  RequireFinitePose("X_WR", X_WR);
  std::vector<std::size_t> touched;
  for (const msgs::RangeReading& reading : ring.readings) {
    // An echo flagged with a NaN, infinite or non-positive range heard nothing usable.
    if (!reading.HeardEcho() || reading.range_m > options_.max_range_m) continue;
    // A reading at the blanking range stands for anything nearer: it places no face and frees
    // nothing.
    if (reading.range_m <= ring.range_min_m) continue;
    const double heading = X_WR.theta_rad + reading.X_RS.theta_rad;
    // Distance of the axis' direction from the nearest grid axis.
    const double off = std::remainder(heading, half_pi);
    if (std::abs(off) > options_.axis_tolerance_rad) {
      if (std::abs(off) <= options_.oblique_face_max_rad)
        AddObliqueFace(reading, X_WR, heading, off);
      continue;
    }
    const double length = reading.range_m - options_.stop_short_m;
    if (length <= 0.0) continue;
    const msgs::Pose2D X_WS = X_WR * reading.X_RS;
    const Eigen::Vector2d from(X_WS.x_m, X_WS.y_m);
    const Eigen::Vector2d dir(std::cos(heading), std::sin(heading));
    // Sampled at a fifth of a cell: every cell the axis crosses by more than that is counted once.
    const double step = 0.2 * res;
    const int samples = static_cast<int>(std::floor(length / step));
    touched.clear();
    for (int k = 0; k <= samples; ++k) {
      const Eigen::Vector2i cell = geometry_.CellAt(from + (k * step) * dir);
      if (cell.x() < 0) continue;
      const std::size_t index = Index(cell.x(), cell.y());
      if (touched.empty() || touched.back() != index) touched.push_back(index);
    }
    for (const std::size_t index : touched) ++passes_[index];
    // The echo's point, filed under the grid direction the axis pointed in.
    const Eigen::Vector2i echo = geometry_.CellAt(from + reading.range_m * dir);
    if (echo.x() < 0) continue;
    const Direction direction = AxisDirection(heading, off);
    ++echoes_[direction][Index(echo.x(), echo.y())];
    const double face = direction == kEast    ? from.x() + reading.range_m
                        : direction == kWest  ? from.x() - reading.range_m
                        : direction == kNorth ? from.y() + reading.range_m
                                              : from.y() - reading.range_m;
    const double lateral = direction == kEast || direction == kWest ? from.y() : from.x();
    face_echoes_.push_back({direction, face, lateral});
  }
}

}  // namespace plywood::perception
