#include "perception/sonar_map/beam_free_grid.h"

#include <cmath>
#include <stdexcept>

namespace plywood::perception {

void BeamFreeOptions::Validate() const {
  if (!(axis_tolerance_rad >= 0.0 && axis_tolerance_rad <= 0.25 * 3.14159265358979323846))
    throw std::invalid_argument("axis_tolerance_rad: must be in [0, pi/4]");
  if (!(std::isfinite(stop_short_m) && stop_short_m >= 0.0))
    throw std::invalid_argument("stop_short_m: must be a finite number >= 0");
  if (!(std::isfinite(max_range_m) && max_range_m > 0.0))
    throw std::invalid_argument("max_range_m: must be a finite number > 0");
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
  return echoes_[direction][static_cast<std::size_t>(iy) * width_ + ix];
}

int BeamFreeGrid::Passes(int ix, int iy) const {
  if (ix < 0 || iy < 0 || ix >= width_ || iy >= height_) return 0;
  return passes_[static_cast<std::size_t>(iy) * width_ + ix];
}

void BeamFreeGrid::Integrate(const msgs::RangeRing& ring, const msgs::Pose2D& X_WR) {
  const double half_pi = 0.5 * 3.14159265358979323846;
  const double res = geometry_.resolution_m;
  const double c = std::cos(X_WR.theta_rad), s = std::sin(X_WR.theta_rad);
  std::vector<std::size_t> touched;
  for (const msgs::RangeReading& reading : ring.readings) {
    if (!reading.echo || reading.range_m > options_.max_range_m) continue;
    const double heading = X_WR.theta_rad + reading.X_RS.theta_rad;
    // Distance of the axis' direction from the nearest grid axis.
    const double off = std::remainder(heading, half_pi);
    if (std::abs(off) > options_.axis_tolerance_rad) continue;
    const double length = reading.range_m - options_.stop_short_m;
    if (length <= 0.0) continue;
    const Eigen::Vector2d from(X_WR.x_m + c * reading.X_RS.x_m - s * reading.X_RS.y_m,
                               X_WR.y_m + s * reading.X_RS.x_m + c * reading.X_RS.y_m);
    const Eigen::Vector2d dir(std::cos(heading), std::sin(heading));
    // Sampled at a fifth of a cell: every cell the axis crosses by more than that is counted once.
    const double step = 0.2 * res;
    const int samples = static_cast<int>(std::floor(length / step));
    touched.clear();
    for (int k = 0; k <= samples; ++k) {
      const Eigen::Vector2d p = from + (k * step) * dir;
      const long ix = std::lround(std::floor((p.x() - geometry_.origin_xy.x()) / res));
      const long iy = std::lround(std::floor((p.y() - geometry_.origin_xy.y()) / res));
      if (ix < 0 || iy < 0 || ix >= width_ || iy >= height_) continue;
      const std::size_t index = static_cast<std::size_t>(iy) * width_ + ix;
      if (touched.empty() || touched.back() != index) touched.push_back(index);
    }
    for (const std::size_t index : touched) ++passes_[index];
    // The echo's point, filed under the grid direction the axis pointed in.
    const Eigen::Vector2d echo = from + reading.range_m * dir;
    const long ex = std::lround(std::floor((echo.x() - geometry_.origin_xy.x()) / res));
    const long ey = std::lround(std::floor((echo.y() - geometry_.origin_xy.y()) / res));
    if (ex < 0 || ey < 0 || ex >= width_ || ey >= height_) continue;
    const double axis = std::remainder(heading - off, 2.0 * 3.14159265358979323846);
    const Direction direction = std::abs(axis) < 0.25 * half_pi                             ? kEast
                                : std::abs(std::abs(axis) - 2.0 * half_pi) < 0.25 * half_pi ? kWest
                                : axis > 0.0                                                ? kNorth
                                             : kSouth;
    ++echoes_[direction][static_cast<std::size_t>(ey) * width_ + ex];
  }
}

}  // namespace plywood::perception
