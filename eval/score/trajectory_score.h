#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "eval/score/score_report.h"
#include "eval/score/trajectory_file.h"
#include "msgs/pose2d.h"

namespace plywood::eval {

struct TrajectoryScoreOptions {
  std::string name;                // the estimate's name in a TUM file; default TrajectoryNameOf
  double time_tolerance_s = 1e-3;  // how far the file's ends may miss the run's (see PosesAtTimes)
};

// The estimate at each of `times` (the run's trajectory.csv sample times, increasing): the pose
// stamped exactly at that time when the file has one, else linear interpolation between the two
// poses around it (heading along the shorter arc); before the file's first or after its last pose
// by at most tolerance_s, that end pose. The file must cover the run: its first pose at most
// tolerance_s after the run's first sample, its last at most tolerance_s before the run's last,
// and no pose more than tolerance_s outside them.
// @throws sim::ConfigError "FILE:LINE: timestamp: ..." naming the offending pose.
std::vector<msgs::Pose2D> PosesAtTimes(const NamedTrajectory& estimate,
                                       const std::vector<double>& times, const std::string& file,
                                       double tolerance_s);

// `plywood score trajectory RUN_DIR FILE`: every estimate in FILE (TUM or Plywood's CSV layout;
// a `truth` group is skipped) against RUN_DIR/trajectory.csv's ground truth, scored by
// robot::ScoreTrajectory as the runner does: odometry.NAME.{final_error_m, heading_error_deg,
// drift_percent, ate_rms_m} and truth.distance_m.
// @throws sim::ConfigError naming the file, line and field of anything wrong.
ScoreReport ScoreTrajectoryFile(const std::filesystem::path& run_dir,
                                const std::filesystem::path& file,
                                const TrajectoryScoreOptions& options = {});

}  // namespace plywood::eval
