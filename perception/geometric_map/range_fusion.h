#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "msgs/laser_scan.h"
#include "msgs/range_ring.h"

namespace plywood::perception {

// Which ranges feed the geometric map: the IR scan alone, the sonar ring alone, or both fused.
enum class RangeSource { kFused, kIrOnly, kSonarOnly };
const char* ToString(RangeSource source);
// @throws std::invalid_argument for anything but "fused", "ir" and "sonar".
RangeSource ParseRangeSource(const std::string& text);

// Seed 003's per-direction fusion of the rotating IR range finder with the sonar ring. The IR
// scanner is accurate but blind to dark or glass-like surfaces; the sonar hears them but cannot
// tell where in its wide cone the echo came from. For each sonar echo:
//   d_ir = the distance from the transducer of the nearest IR point inside its cone;
//   echo farther than d_ir + tau_m   -> the sonar saw past the IR's surface (or multipath):
//   ignored; echo within tau_m of d_ir        -> the IR saw the same surface, more precisely: IR
//   kept; echo nearer than d_ir - tau_m    -> an obstacle the IR missed: sonar used.
// Of neighbouring transducers (adjacent in the ring's order) with such echoes only the nearest is
// used: a flat surface is nearest along the transducer most square to it, the others heard it
// off-axis. A used echo is taken to come from a surface square to the transducer's axis (a smooth
// surface only echoes back when it nearly faces the transducer), so the IR beams whose ray meets
// that surface within fill_half_angle_deg of the axis get the range of the meeting point when it is
// nearer than their own, and within the IR's reach (beyond it the IR's silence says nothing).
// Defaults are assumptions (the paper gives no numbers): tau 0.1 m is about
// 10 sonar noise sigmas at 1 m; the cone is the Polaroid transducer's +-15 deg; +-10 deg fills
// about 10 IR beams at 1 m, enough for a line (segmentation.min_line_points); echoes beyond the
// IR's 3 m reach are not used, because there the IR cannot say anything about them.
struct FusionOptions {
  RangeSource source = RangeSource::kFused;
  double tau_m = 0.1;
  double sonar_half_angle_deg = 15.0;
  double fill_half_angle_deg = 10.0;
  double sonar_max_range_m = 3.0;

  // @throws std::invalid_argument starting with the field's name.
  void Validate() const;
};

// One range point of a (fused) scan in the robot frame, in the scan's beam order.
struct RangePoint {
  Eigen::Vector2d p_R = Eigen::Vector2d::Zero();
  int beam = 0;             // the IR beam it lies on
  bool from_sonar = false;  // the sonar's range replaced the IR's on this beam
};

// The points of one IR scan fused with the sonar ring read at the same instant (`sonar` may be
// null: no sonar), in the robot frame and beam order. Beams without a range give no point.
// @throws std::invalid_argument from ValidateScanAngles(ir).
std::vector<RangePoint> FuseRanges(const msgs::LaserScan& ir, const msgs::RangeRing* sonar,
                                   const FusionOptions& options);

}  // namespace plywood::perception
