#pragma once

#include <optional>

#include "msgs/wheel_speed_command.h"

namespace plywood::sim {

class ExperimentRunner;

// Watches a run as it happens (the interactive viewer, the video recorder) and may take the wheels
// over (teleoperation). The runner only calls it; an observer that never overrides and never stops
// the run leaves every output byte-identical to an unobserved run.
class RunObserver {
 public:
  virtual ~RunObserver() = default;

  // Called once before the first step and after every physics step. Returning false ends the run
  // at the current time (as if duration_s had been reached).
  virtual bool AfterStep(const ExperimentRunner& runner) = 0;

  // Wheel speeds that replace the controller's while set; the controller is not consulted
  // meanwhile and gets the wheels back on its next control tick after the override ends.
  virtual std::optional<msgs::WheelSpeedCommand> WheelOverride() { return std::nullopt; }

  // Called once when the run has ended and been scored (the runner's record is complete).
  virtual void RunFinished(const ExperimentRunner& /*runner*/) {}
};

}  // namespace plywood::sim
