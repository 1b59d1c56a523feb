#include "robot/control/wheel_script_controller.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"
#include "robot/control/tick_time_slack.h"

namespace plywood::robot {
namespace {

// Tick times are accumulated sums of a period that is rarely exact in binary (0.01 s): a boundary
// closer than this counts as reached.

std::string SegmentField(std::size_t i, const char* member) {
  return "segments[" + std::to_string(i) + "]." + member;
}

}  // namespace

void WheelScriptOptions::Validate() const {
  if (segments.empty()) throw std::invalid_argument("segments: must hold at least one segment");
  for (std::size_t i = 0; i < segments.size(); ++i) {
    internal::RequirePositive(SegmentField(i, "duration_s"), segments[i].duration_s);
    if (!std::isfinite(segments[i].left_rad_s)) {
      throw std::invalid_argument(SegmentField(i, "left_rad_s") + ": must be finite");
    }
    if (!std::isfinite(segments[i].right_rad_s)) {
      throw std::invalid_argument(SegmentField(i, "right_rad_s") + ": must be finite");
    }
  }
}

WheelScriptController::WheelScriptController(const DiffDriveSpec& spec,
                                             const WheelScriptOptions& options)
    : options_(options) {
  spec.Validate();
  options_.Validate();
  double end_s = 0.0;
  for (std::size_t i = 0; i < options_.segments.size(); ++i) {
    const WheelSegment& segment = options_.segments[i];
    for (const auto& [member, value] : {std::pair{"left_rad_s", segment.left_rad_s},
                                        std::pair{"right_rad_s", segment.right_rad_s}}) {
      if (std::abs(value) > spec.max_wheel_speed_rad_s) {
        throw std::invalid_argument(SegmentField(i, member) + ": |" + msgs::ShortestNumber(value) +
                                    "| exceeds max_wheel_speed_rad_s " +
                                    msgs::ShortestNumber(spec.max_wheel_speed_rad_s));
      }
    }
    end_s += segment.duration_s;
    segment_end_s_.push_back(end_s);
  }
}

msgs::WheelSpeedCommand WheelScriptController::Update(const ControllerInput& input) {
  if (!start_time_s_) start_time_s_ = input.time_s;
  const double script_time_s = input.time_s - *start_time_s_;
  while (segment_ < segment_end_s_.size() &&
         script_time_s >= segment_end_s_[segment_] - kTickTimeSlackS) {
    ++segment_;
  }
  if (segment_ == segment_end_s_.size()) {
    finished_ = true;
    return {};
  }
  const WheelSegment& segment = options_.segments[segment_];
  return {segment.left_rad_s, segment.right_rad_s};
}

}  // namespace plywood::robot
