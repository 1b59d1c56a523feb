#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "robot/control/controller.h"
#include "robot/drive/diff_drive_spec.h"

namespace plywood::robot {

enum class WallSide { kLeft, kRight };
enum class WallSensor { kSonar, kLaser };

// YAML spellings: "left"/"right", "sonar"/"laser".
std::string_view ToString(WallSide side);
std::string_view ToString(WallSensor sensor);
// @throws std::invalid_argument starting with "side" / "sensor" for unknown names.
WallSide ParseWallSide(std::string_view text);
WallSensor ParseWallSensor(std::string_view text);

struct WallFollowingOptions {
  WallSide side = WallSide::kLeft;
  WallSensor sensor = WallSensor::kSonar;
  double distance_m = 0.5;  // wanted distance from the centre of rotation to the wall
  double speed_m_s = 0.25;
  double accel_m_s2 = 0.3;
  double max_turn_rate_rad_s = 1.0;
  // P on distance: wanted heading towards the wall per metre of distance error, capped at
  // max_approach_angle_rad. D through the wall angle: yaw rate per radian between that wanted
  // heading and the heading relative to the wall. With v the speed the linearised loop is
  // e'' + a e' + v a d e = 0 (a = angle gain, d = distance gain): the defaults are slightly
  // overdamped at 0.25 m/s.
  double distance_gain_rad_per_m = 1.5;
  double angle_gain_per_s = 2.0;
  // Also keeps the sonar able to hear the wall: a smooth wall echoes only while a transducer's axis
  // is within its beam half-angle plus the specular incidence limit (about 35 deg for a Polaroid
  // on plywood, Leonard & Durrant-Whyte 1992) of the wall's normal.
  double max_approach_angle_rad = 0.35;
  // Points whose bearing from the centre of rotation lies within side_window_rad of the side's
  // normal measure the wall; those within front_window_rad of straight ahead look for obstacles.
  double side_window_rad = 0.6;
  double front_window_rad = 0.35;
  double max_wall_range_m = 2.0;   // side points beyond this are not the wall being followed
  double front_clearance_m = 0.8;  // turn on the spot, away from the wall, when anything in the
                                   // lane ahead is closer than this to the centre of rotation
  double lane_half_width_m = 0.3;  // half the width of that lane: the robot's plus a margin
  // Echo points are kept this long (in the estimate frame) after the reading that produced them:
  // a sonar that hears nothing has not seen free space, only a specular miss, so a wall heard a
  // moment ago still counts. 0 uses the latest reading only.
  double memory_s = 10.0;
  // Only points this recent shape the wall fit: a sonar echo placed on the beam axis is off by up
  // to the cone's half-angle, and older points add more of that error than they add wall.
  double wall_memory_s = 2.0;
  double duration_s = 0.0;  // finishes after this long; 0 runs until stopped

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// Follows a wall on one side at a set distance from sonar or laser readings. Each new reading's
// echo points are placed in the robot frame through their mounting pose X_RS and kept for
// memory_s in the estimate frame, so that sonar specular misses (no echo) read as "unknown", not
// as free space. Each tick a line is fitted (total least squares, then again without the points
// more than kOutlierM off it) to the remembered points beside the robot; its distance and
// direction feed the PD law above. With a single usable point the wall direction is carried over
// from the last fit through the change in the estimated heading. The speed falls as the lane ahead
// closes in; anything in it closer than front_clearance_m makes the robot turn on the spot away
// from the wall (inner corners, or heading into the wall) until the lane is clear by a further
// distance_m and the side sees a roughly parallel wall (or it has turned half a turn). When the
// wall goes out of view it drives an arc of radius distance_m towards the wall side (outer corners)
// for at most half a turn; before any wall was seen, or after such an arc found none, it drives
// straight ahead until the lane ahead closes in. Without a reading of the chosen sensor yet it
// commands zero.
// @pre Each new sonar ring or laser scan carries a later time_s than the one before.
class WallFollowingController final : public Controller {
 public:
  // @throws std::invalid_argument when the spec or options are invalid.
  WallFollowingController(const DiffDriveSpec& spec, const WallFollowingOptions& options);

  msgs::WheelSpeedCommand Update(const ControllerInput& input) override;
  bool Finished() const override { return finished_; }

  // Wall as last measured, in the robot frame: distance from the centre of rotation and the
  // direction of the wall relative to the robot's x axis in (-pi/2, pi/2]. Empty when not in view.
  struct WallEstimate {
    double distance_m = 0.0;
    double angle_rad = 0.0;
  };
  const std::optional<WallEstimate>& wall() const { return wall_; }

 private:
  struct Point {
    double x_m, y_m;
  };
  struct StampedPoint {
    Point p_W;  // in the estimate frame
    double time_s;
  };
  // Adds the echo points of a reading not seen before to memory_ and forgets the stale ones.
  void Remember(const ControllerInput& input);
  void AddPoint(const msgs::Pose2D& X_WR, const msgs::Pose2D& X_RS, double beam_rad, double range_m,
                double time_s);
  // Appends the remembered side (wall) points in the robot frame to `side`; returns how far ahead
  // the nearest point in the lane or the front window is (infinity: none that matters).
  double CollectPoints(const msgs::Pose2D& X_WR, std::vector<Point>* side);
  // The points older than wall_memory_s near the anchor pose (see CollectPoints), for the ahead
  // test only; re-sorted after each new reading and whenever the pose leaves the anchor's slack.
  void SortOldPoints(const msgs::Pose2D& X_WR, std::size_t old_count);
  std::optional<WallEstimate> FitWall(const std::vector<Point>& side, double theta_estimate_rad);

  const DiffDriveSpec spec_;
  const WallFollowingOptions options_;
  const double side_sign_;         // +1 left, -1 right
  const double relevant_range_m_;  // remembered points further away change nothing
  std::optional<double> start_time_s_;
  std::optional<double> last_time_s_;
  std::optional<double> wall_heading_W_rad_;  // last fitted wall direction in the estimate frame
  std::optional<WallEstimate> wall_;
  std::vector<StampedPoint> memory_;  // oldest first; those before memory_head_ are forgotten
  std::size_t memory_head_ = 0;
  std::vector<Point> side_scratch_;  // CollectPoints' output, kept to reuse its allocation
  // SortOldPoints' lists (estimate frame) for the anchor pose: the old points surely within reach
  // of any pose within the slack of the anchor, and those that may be (within reach + slack);
  // neither holds points surely behind every such pose.
  bool old_points_sorted_ = false;
  double old_anchor_x_m_ = 0.0, old_anchor_y_m_ = 0.0, old_anchor_theta_rad_ = 0.0;
  std::vector<Point> old_inside_, old_boundary_;
  std::optional<double> last_reading_time_s_;
  double speed_m_s_ = 0.0;
  double arc_turned_rad_ = 0.0;  // heading change of the arc since the wall went out of view
  bool turning_away_ = false;
  double turned_away_rad_ = 0.0;  // heading change since turning_away_ was set    // blocked ahead:
                                  // turning on the spot away from the wall
  bool finished_ = false;
};

}  // namespace plywood::robot
