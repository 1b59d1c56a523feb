#pragma once

#include <vector>

#include "msgs/bumpers.h"

namespace plywood::sim {

class Scene;

struct BumperSensorOptions {
  double rate_hz = 10.0;  // the P3-DX reports bumpers in its 10 Hz server information packet

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// Contact switches on a ring of bump panels. The panels are the geoms bumper_0, bumper_1, ... up to
// the first missing index (a robot without them has zero panels); panel i is pressed while the
// robot touches anything that is not part of the robot (a wall, an obstacle) with
//  - the geom "bumper_ring", at a contact point whose bearing in the robot frame (atan2(y, x) from
//    the base origin) lies in panel i's arc, or
//  - the geom bumper_i itself, when that panel is a collision geom.
// Panel i's arc holds the bearings nearer to panel i's centre than to any other panel's centre
// (bearings of the bumper_i geoms' centres; the arcs meet halfway between neighbours). The shipped
// robots collide through one convex ring geom and keep bumper_i as visuals only, because MuJoCo
// 2.2.2 pairs every robot geom with every world geom on every step: one ring is ~10x cheaper than
// ten panels. Arcs of the shipped models (deg, counter-clockwise from forward):
//  - P3-DX: front 0..4 centred at -53.7, -24.5, 0, 24.5, 53.7; rear 5..9 at 143.1, 163.0, 180,
//    -163.0, -143.1 (so a contact on the ring's flat side goes to panel 4/5 or 9/0, split at 98.4).
//  - Magellan Pro: panel i centred at 22.5 i, each covering +-11.25.
// Contacts are MuJoCo's from the last step, i.e. at the start of that step, as a real switch is
// read a moment late. In the planar drive (DriveMode::kPlanar) there are no MuJoCo contacts: panel
// i is pressed while the bumper ring's footprint is within Scene::kPlanarContactSkinM of a static
// geom at a point whose bearing lies in its arc (Scene::PlanarContactBearings), at the current
// pose.
class BumperSensor {
 public:
  // @throws std::invalid_argument when `options` is invalid; ConfigError naming the robot file
  // when it has no bumper_0 panel, or neither a colliding bumper_ring nor a colliding panel.
  explicit BumperSensor(const Scene& scene, const BumperSensorOptions& options = {});

  double period_s() const { return 1.0 / options_.rate_hz; }
  int panel_count() const { return static_cast<int>(panel_bearings_rad_.size()); }

  // The panel whose arc holds `bearing_rad` (robot frame), -1 when there are no panels.
  int PanelAtBearing(double bearing_rad) const;

  msgs::Bumpers Sample(const Scene& scene) const;

 private:
  BumperSensorOptions options_;
  std::vector<double> panel_bearings_rad_;  // bearing of panel i's centre in the robot frame
  std::vector<int> panel_of_geom_;          // panel index of each geom id, -1 for other geoms
  int ring_geom_ = -1;                      // "bumper_ring", -1 when the robot has none
};

}  // namespace plywood::sim
