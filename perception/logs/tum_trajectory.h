#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "msgs/pose2d.h"

namespace plywood::perception {

// TUM RGB-D trajectory files (Sturm et al., IROS 2012), the de-facto exchange format of
// trajectories: one pose per line, `timestamp tx ty tz qx qy qz qw` separated by spaces, lines
// starting with '#' are comments. A planar pose is tz = qx = qy = 0 and a rotation about z.

// A quaternion about z for a heading: qz = sin(theta / 2), qw = cos(theta / 2), each possibly
// moved by one unit in the last place so that HeadingOfQuaternion gives back exactly the same
// double (plain sin/cos miss it for about 7 % of headings; the norm stays within 1e-15 of 1). Exact
// for |theta| <= 2 pi, which covers every wrapped heading; larger angles are wrapped first.
struct PlanarQuaternion {
  double qz = 0.0;
  double qw = 1.0;
};
PlanarQuaternion QuaternionOfHeading(double theta_rad);

// The yaw of a unit quaternion: 2 atan2(qz, qw) when qx = qy = 0 (in (-2 pi, 2 pi], the exact
// inverse of QuaternionOfHeading), else the z-y-x Euler yaw of the normalised quaternion.
double HeadingOfQuaternion(double qx, double qy, double qz, double qw);

// One line `t x y 0 0 0 qz qw` (numbers in shortest round-trip form), ending in '\n'.
void WriteTumPose(std::ostream& out, double time_s, const msgs::Pose2D& pose);

struct TimedPose {
  double time_s = 0.0;
  msgs::Pose2D pose;
  std::size_t line_number = 0;  // in the file it came from
};

// The largest |x| or |y| (m) a trajectory file may hold: beyond it the scores' sums of squares
// overflow (a TUM x of 1e300 gave ate_rms_m = inf and a 300-digit final error, exit 0).
inline constexpr double kMaxTrajectoryCoordinateM = 1e9;

// The largest |heading| (rad) a trajectory may hold. Unwrapped headings are fine, but doubles are
// spaced 1.2e-7 rad at 1e9 rad (the scores print 1e-4 deg, 1.7e-6 rad) and 1e284 rad at 1e300,
// where a heading of 1e300 was scored as some angle (heading_error_deg -41.4, exit 0).
inline constexpr double kMaxTrajectoryHeadingRad = 1e9;

// How far an estimate's start may lie from the run's (the spawn): the scores have no alignment,
// since every estimator starts at the known spawn pose (and each Plywood file starts exactly
// there), so a file in another frame or unit (millimetres) was scored as an error of its offset.
// `plywood score trajectory` refuses such a file; a run refuses such a registered estimator.
inline constexpr double kMaxStartOffsetM = 0.1;
inline constexpr double kMaxStartHeadingOffsetDeg = 10.0;

// The largest tilt (deg) of a TUM pose, the angle its quaternion turns the z axis away from up.
// Plywood's floors are level (a tilted one is refused), so a ground robot's pose is level; 45 deg
// is halfway to the 90 deg at which a heading means nothing. A planar quaternion written w first
// (qw qx qy qz, a common slip) reads as a tilt of 180 deg less the heading, whose yaw is 0.
inline constexpr double kMaxTumTiltDeg = 45.0;

// Reads a TUM file into planar poses (tz is ignored; the heading is HeadingOfQuaternion).
// @throws std::invalid_argument "FILE:LINE: FIELD: what is wrong" (FIELD one of timestamp, tx, ty,
// tz, qx, qy, qz, qw) for a wrong number of fields, a field that is not a finite number, a tx or
// ty beyond kMaxTrajectoryCoordinateM, a quaternion whose norm is not 1 within 1e-3 or that tilts
// the pose beyond kMaxTumTiltDeg, timestamps that do not increase; "FILE: ..." for an unreadable
// file or one without poses.
std::vector<TimedPose> ReadTumTrajectory(const std::filesystem::path& path);

}  // namespace plywood::perception
