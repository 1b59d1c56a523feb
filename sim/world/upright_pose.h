#pragma once

#include <mujoco/mujoco.h>

#include <cmath>

#include "msgs/pose2d.h"

namespace plywood::sim {

// The planar pose of a free joint's body: its x, y and the yaw of its x axis projected on the
// floor (robust to small roll and pitch), from the joint's qpos (x, y, z, w, qx, qy, qz).
inline msgs::Pose2D UprightPoseFromQpos(const mjtNum* q) {
  const double w = q[3], x = q[4], y = q[5], z = q[6];
  const double yaw = std::atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z));
  return {q[0], q[1], yaw};
}

// Writes X_WR into a free joint's qpos: x, y and an upright yaw; the height is left as it is.
inline void WriteUprightPose(const msgs::Pose2D& X_WR, mjtNum* q) {
  q[0] = X_WR.x_m;
  q[1] = X_WR.y_m;
  q[3] = std::cos(X_WR.theta_rad / 2.0);
  q[4] = 0.0;
  q[5] = 0.0;
  q[6] = std::sin(X_WR.theta_rad / 2.0);
}

}  // namespace plywood::sim
