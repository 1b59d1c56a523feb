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

// Contact switches: panel i is pressed while the robot's geom "bumper_i" touches anything that is
// not part of the robot (a wall, an obstacle). The panels are the geoms bumper_0, bumper_1, ...
// up to the first missing index; a robot without them has zero panels. Contacts are MuJoCo's from
// the last step, i.e. at the start of that step, as a real switch is read a moment late.
class BumperSensor {
 public:
  // @throws std::invalid_argument when `options` is invalid.
  explicit BumperSensor(const Scene& scene, const BumperSensorOptions& options = {});

  double period_s() const { return 1.0 / options_.rate_hz; }
  int panel_count() const { return static_cast<int>(panel_geoms_.size()); }

  msgs::Bumpers Sample(const Scene& scene) const;

 private:
  BumperSensorOptions options_;
  std::vector<int> panel_geoms_;    // geom id of panel i
  std::vector<int> panel_of_geom_;  // panel index of each geom id, -1 for other geoms
};

}  // namespace plywood::sim
