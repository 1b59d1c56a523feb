#pragma once

namespace plywood::msgs {

// Wraps a finite angle (1e300 too) to (-pi, pi]; NaN and +-inf give NaN: no angle.
double WrapAngle(double angle_rad);

// A planar rigid transform. Frame notation follows Drake: X_AB is the pose of frame B expressed in
// frame A; W is the world, R the robot (centre of rotation), S a sensor.
struct Pose2D {
  double x_m = 0.0;
  double y_m = 0.0;
  double theta_rad = 0.0;

  // X_AC = X_AB * X_BC.
  Pose2D operator*(const Pose2D& X_BC) const;

  Pose2D Inverse() const;

  bool operator==(const Pose2D&) const = default;
};

// A pose handed to a library (a scan's, a ring's, an estimate): NaN or inf would go into its maps
// for good. Throws std::invalid_argument "<field>: must be finite, got (x, y, theta)".
void RequireFinitePose(const char* field, const Pose2D& pose);

}  // namespace plywood::msgs
