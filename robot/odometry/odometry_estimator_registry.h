#pragma once

#include <functional>
#include <memory>
#include <string>

#include "msgs/pose2d.h"
#include "robot/odometry/odometry_estimator.h"
#include "robot/odometry/odometry_increments.h"
#include "robot/plugins/parameter_map.h"
#include "robot/plugins/registry.h"

namespace plywood::robot {

// An odometry estimator user code adds by name (docs/plugins.md). The factory gets the robot's
// nominal geometry with the experiment's odometry calibration applied, the initial pose estimate
// and the estimator's options, and throws std::invalid_argument "<key>: <what is wrong>" for a bad
// option.
struct RegisteredOdometryEstimator {
  std::string name;
  // The host refuses to run it unless the gyro is on (it is then fed AddGyro as well).
  bool needs_gyro = false;
  std::function<std::unique_ptr<OdometryEstimator>(const OdometryGeometry& geometry,
                                                   const msgs::Pose2D& X_WR_initial,
                                                   const ParameterMap& options)>
      make;
};

using OdometryEstimatorRegistry = Registry<RegisteredOdometryEstimator>;

}  // namespace plywood::robot
