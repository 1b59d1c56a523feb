#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "msgs/pose2d.h"
#include "robot/control/controller.h"
#include "robot/drive/diff_drive_kinematics.h"
#include "robot/drive/diff_drive_spec.h"

namespace plywood::robot {

enum class SquareDirection { kClockwise, kCounterClockwise };

// "cw" / "ccw", the YAML spelling.
std::string_view ToString(SquareDirection direction);
// @throws std::invalid_argument starting with "direction" for anything but "cw" or "ccw".
SquareDirection ParseSquareDirection(std::string_view text);

// The most laps SquarePathOptions accepts (its moves are laid out up front, 16 per lap).
inline constexpr int kMaxSquareLaps = 10000;

struct SquarePathOptions {
  double side_m = 4.0;  // UMBmark: 4 x 4 m
  SquareDirection direction = SquareDirection::kClockwise;
  int laps = 1;
  double speed_m_s = 0.2;        // cruise speed on the straight legs
  double turn_rate_rad_s = 0.5;  // cruise yaw rate of the spot turns
  // Wheel-rim acceleration for both the legs and the turns (a turn's angular acceleration is
  // accel_m_s2 / (track / 2)), gentle enough that the wheels do not slip.
  double accel_m_s2 = 0.3;
  double dwell_s = 0.5;  // standstill after every leg and every turn
  // Heading hold on the legs: yaw rate = heading_gain_per_s * heading error, where the wanted
  // heading leans back towards the leg's line by atan(cross_track_gain_rad_per_m * offset).
  double heading_gain_per_s = 2.0;
  double cross_track_gain_rad_per_m = 1.0;
  // Stopping rule: a leg ends when the estimate is within this distance of the corner (measured
  // along the leg) or past it; a turn when the estimated heading is within heading_tolerance_rad.
  double position_tolerance_m = 1e-4;
  double heading_tolerance_rad = 1e-4;
  // Turn at the last corner too, so the robot ends with its starting heading.
  bool final_turn = true;

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// The square's four corners laid out from `X_WR_start` (corner 0, the first leg along its
// heading), in driving order, each with the heading of the leg that leaves it.
std::vector<msgs::Pose2D> SquareCorners(const msgs::Pose2D& X_WR_start,
                                        const SquarePathOptions& options);

// Drives the UMBmark square (Borenstein & Feng 1996, "Measurement and correction of systematic
// odometry errors in mobile robots"): straight legs, a stop, a turn on the spot, a stop. Everything
// is judged from the pose estimate it is given, as a real robot judges it from its odometry: the
// square's corners are laid out from the first estimate (corner 0 = the start, first leg along its
// heading), each leg ends when the estimate reaches the next corner, each turn when the estimated
// heading reaches the next leg's heading. With a perfect pose feed the robot therefore returns to
// its start; with odometry it returns to where odometry believes the start is, and the difference
// is UMBmark's return-position error.
//
// Legs hold the line from corner to corner (heading plus cross-track feedback) and both legs and
// turns follow trapezoidal speed profiles that end with a one-tick exact stop (StoppingSpeed).
class SquarePathController final : public Controller {
 public:
  // @throws std::invalid_argument when the spec or options are invalid, or when the cruise speed
  // or turn rate needs more than the spec's max_wheel_speed_rad_s.
  SquarePathController(const DiffDriveSpec& spec, const SquarePathOptions& options);

  msgs::WheelSpeedCommand Update(const ControllerInput& input) override;
  bool Finished() const override;

  // The corners in the estimate's frame (corner 0 is the start, then in driving order), each with
  // the heading of the leg that leaves it. Empty before the first Update.
  const std::vector<msgs::Pose2D>& corners() const { return corners_; }

 private:
  struct Move {
    enum class Kind { kStraight, kTurn, kDwell } kind;
    msgs::Pose2D from;  // kStraight: start corner with the leg heading
    msgs::Pose2D to;    // kStraight: end corner; kTurn: heading to reach in to.theta_rad
  };

  void Plan(const msgs::Pose2D& X_WR_start);
  void Advance(double time_s);
  // The twist for the current move, or nullopt when the move is complete.
  std::optional<BodyTwist> Step(const Move& move, const ControllerInput& input, double dt_s);

  const DiffDriveSpec spec_;
  const SquarePathOptions options_;
  std::vector<msgs::Pose2D> corners_;
  std::vector<Move> moves_;
  std::size_t move_index_ = 0;
  double move_start_s_ = 0.0;
  std::optional<double> last_time_s_;
  double speed_ = 0.0;      // magnitude commanded at the previous tick of the current move
  double turn_sign_ = 0.0;  // +1 left, -1 right: direction the current turn started in
};

}  // namespace plywood::robot
