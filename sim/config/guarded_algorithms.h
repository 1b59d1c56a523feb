#pragma once

#include <memory>
#include <string>

#include "msgs/pose2d.h"
#include "perception/lines/line_extractor.h"
#include "robot/control/controller.h"
#include "robot/odometry/odometry_estimator.h"

namespace plywood::sim {

// A registered algorithm (a plug-in's, or one compiled in) as the host runs it: every call goes
// through, and what the algorithm does wrong at run time ends the run with one line naming it
// (`label`, such as "line extractor 'mine' (plug-in /path/libmine.so)") and what it did, instead
// of a score computed from it. std::runtime_error (exit 1, a failure during the run) when it
// throws anything, or gives:
// - an extractor: a segment or circle that is not finite, a segment of a negative point count,
//   whose line (alpha_rad, r_m) passes more than 1 mm from its ends, or with an end more than
//   0.5 m from every point of the scan (segments are in the scan's sensor frame): what `plywood
//   score lines` refuses in a file;
// - an estimator: a pose not finite, beyond 1e9 m of the origin or 1e9 rad of 0, or a first pose
//   more than 0.1 m or 10 deg from `X_WR_initial` (the spawn its factory got): what `plywood
//   score trajectory` refuses in a file;
// - a controller: a wheel speed that is not finite.
// The built-in algorithms are not wrapped: their output is Plywood's own, tested code.
std::unique_ptr<perception::LineExtractor> GuardRegistered(
    std::unique_ptr<perception::LineExtractor> extractor, std::string label);
std::unique_ptr<robot::OdometryEstimator> GuardRegistered(
    std::unique_ptr<robot::OdometryEstimator> estimator, std::string label,
    const msgs::Pose2D& X_WR_initial);
std::unique_ptr<robot::Controller> GuardRegistered(std::unique_ptr<robot::Controller> controller,
                                                   std::string label);

}  // namespace plywood::sim
