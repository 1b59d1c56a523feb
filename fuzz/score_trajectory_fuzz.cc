// Trajectory files of `plywood score` (eval/score/trajectory_file.h): TUM or Plywood's
// trajectory.csv, told apart by content. What loads is finite, at strictly increasing times.
#include <cmath>

#include "eval/score/trajectory_file.h"
#include "fuzz/fuzz_support.h"
#include "fuzz/fuzz_target.h"

namespace plywood::fuzz {
namespace {

void FuzzScoreTrajectory(std::span<const std::uint8_t> data) {
  const std::filesystem::path path = WriteScratchFile("trajectory.fuzz.tum", data);
  try {
    for (const eval::NamedTrajectory& trajectory : eval::ReadTrajectoryFile(path, "fuzz")) {
      Require(!trajectory.name.empty(), "a trajectory without a name");
      for (std::size_t i = 0; i < trajectory.poses.size(); ++i) {
        const perception::TimedPose& p = trajectory.poses[i];
        Require(std::isfinite(p.time_s) && std::isfinite(p.pose.x_m) && std::isfinite(p.pose.y_m) &&
                    std::isfinite(p.pose.theta_rad),
                "a non-finite pose");
        Require(i == 0 || p.time_s > trajectory.poses[i - 1].time_s, "times that do not increase");
      }
    }
  } catch (const std::runtime_error& e) {  // sim::ConfigError
    RequireCleanError(e, path.string());
  } catch (const std::invalid_argument& e) {  // the TUM reader's
    RequireCleanError(e, path.string());
  }
}

}  // namespace
}  // namespace plywood::fuzz

PLYWOOD_FUZZ_TARGET("score_trajectory", plywood::fuzz::FuzzScoreTrajectory)
