#pragma once

#include "msgs/pose2d.h"
#include "msgs/wheel_speed_command.h"
#include "robot/drive/diff_drive_spec.h"

namespace plywood::robot {

// Planar body velocity of the centre of rotation: forward speed and yaw rate.
struct BodyTwist {
  double linear_m_s = 0.0;
  double angular_rad_s = 0.0;
};

BodyTwist WheelSpeedsToTwist(const DiffDriveSpec& spec, const msgs::WheelSpeedCommand& wheels);

// Inverse kinematics. When a wheel would exceed max_wheel_speed_rad_s both wheels are scaled down
// together, so the commanded path curvature is kept.
msgs::WheelSpeedCommand TwistToWheelSpeeds(const DiffDriveSpec& spec, const BodyTwist& twist);

// Advances a pose by a distance ds and heading change dtheta with midpoint integration
// (seed 004 eq. 3): x += ds cos(theta + dtheta/2), y += ds sin(theta + dtheta/2).
msgs::Pose2D IntegrateMidpoint(const msgs::Pose2D& X_WR, double ds_m, double dtheta_rad);

// Exact pose after moving along a circular arc (or straight line) of length ds turning dtheta.
msgs::Pose2D IntegrateArc(const msgs::Pose2D& X_WR, double ds_m, double dtheta_rad);

}  // namespace plywood::robot
