#pragma once

#include <string>

#include "sim/config/config_error.h"

namespace plywood::sim {

// The runner's refusal of the robot's spawn pose (inside a wall or an obstacle, outside every
// room): a ConfigError naming robot.spawn, which also keeps the problem alone. A caller that places
// the robot itself, where robot.spawn is not read (the seed 000 rig at the origin, the bench at
// the world's spawn_0), names its own field with it instead: "choose a free spawn" sent the user
// to a key whose change would not help (s43).
class SpawnRefused : public ConfigError {
 public:
  // `advice` (e.g. "; choose a free spawn") follows the problem in the robot.spawn message only.
  SpawnRefused(const std::string& file, const std::string& problem, const std::string& advice,
               const std::string& world_name)
      : ConfigError(file, "robot.spawn", problem + advice + " in " + world_name),
        problem_(problem) {}

  // The problem alone, e.g. "the robot at (0, 0) overlaps geom 'col' of the world by 128 mm (its
  // geom 'chassis')".
  const std::string& problem() const { return problem_; }

 private:
  std::string problem_;
};

}  // namespace plywood::sim
