#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "robot/control/controller.h"
#include "robot/drive/diff_drive_spec.h"

namespace plywood::robot {

// Hold these wheel speeds for duration_s.
struct WheelSegment {
  double duration_s = 0.0;
  double left_rad_s = 0.0;
  double right_rad_s = 0.0;
};

struct WheelScriptOptions {
  std::vector<WheelSegment> segments;

  // @throws std::invalid_argument naming the offending field ("segments[2].duration_s: ...").
  void Validate() const;
};

// Open-loop wheel-speed script, as seed 004 drove its V-REP Pioneer: a list of (duration, left,
// right) segments played from the first Update. Segment k covers [t_k, t_k + duration_k) of script
// time; a tick takes the segment its time falls in, so with a control period that divides every
// duration each segment lasts exactly its duration. It ignores the pose and the sensors.
class WheelScriptController final : public Controller {
 public:
  // @throws std::invalid_argument when the options are invalid or a speed exceeds the spec's
  // max_wheel_speed_rad_s.
  WheelScriptController(const DiffDriveSpec& spec, const WheelScriptOptions& options);

  msgs::WheelSpeedCommand Update(const ControllerInput& input) override;
  bool Finished() const override { return finished_; }

  // Sum of the segments' durations.
  double total_duration_s() const { return segment_end_s_.back(); }

 private:
  const WheelScriptOptions options_;
  std::vector<double> segment_end_s_;  // cumulative end time of each segment, script time
  std::optional<double> start_time_s_;
  std::size_t segment_ = 0;
  bool finished_ = false;
};

}  // namespace plywood::robot
