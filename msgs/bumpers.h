#pragma once

#include <vector>

namespace plywood::msgs {

// Contact switches around the body; panel i covers the arc described by the robot's spec.
struct Bumpers {
  double time_s = 0.0;
  std::vector<bool> pressed;
};

}  // namespace plywood::msgs
