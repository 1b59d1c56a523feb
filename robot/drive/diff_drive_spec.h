#pragma once

#include <string>

namespace plywood::robot {

// Nominal geometry of a differential-drive base: what the robot's own software believes. The
// simulated robot may differ (see sim/world/physical_deviation.h); odometry is always given this
// one.
struct DiffDriveSpec {
  double wheel_radius_m = 0.0975;
  double track_m = 0.33;  // distance between the wheels' contact points
  double max_wheel_speed_rad_s = 12.3;
  int encoder_ticks_per_rev =
      500 * 19.5 * 4;  // P3-DX: 500-line encoder, 19.5:1 gearbox, quadrature

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// Pioneer P3-DX (Adept MobileRobots data sheet; ARIA p3dx.p).
DiffDriveSpec P3dxSpec();

// Magellan Pro (iRobot/RWI). Wheel size and track are not published: the values here are
// assumptions (docs/robots.md) and every experiment can override them.
DiffDriveSpec MagellanProSpec();

}  // namespace plywood::robot
