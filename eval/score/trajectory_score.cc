#include "eval/score/trajectory_score.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "eval/score/run_directory.h"
#include "msgs/shortest_number.h"
#include "perception/logs/tum_trajectory.h"
#include "robot/odometry/trajectory_metrics.h"
#include "sim/config/config_error.h"

namespace plywood::eval {
namespace {

std::string Seconds(double t) { return sim::FormatNumber(t) + " s"; }

using perception::kMaxStartHeadingOffsetDeg;
using perception::kMaxStartOffsetM;

// @throws sim::ConfigError naming the file's first pose when `start`, the estimate at the run's
// first sample, is not at `truth_start`.
void RequireStartAtTheSpawn(const NamedTrajectory& estimate, const msgs::Pose2D& start,
                            const msgs::Pose2D& truth_start, const std::string& file, bool tum) {
  const double offset_m = std::hypot(start.x_m - truth_start.x_m, start.y_m - truth_start.y_m);
  const double offset_deg =
      std::abs(msgs::WrapAngle(start.theta_rad - truth_start.theta_rad)) * 180.0 / std::numbers::pi;
  if (offset_m <= kMaxStartOffsetM && offset_deg <= kMaxStartHeadingOffsetDeg) return;
  const auto pose = [](const msgs::Pose2D& p) {
    return "(" + msgs::SixDigitNumber(p.x_m) + ", " + msgs::SixDigitNumber(p.y_m) + ") heading " +
           msgs::SixDigitNumber(p.theta_rad * 180.0 / std::numbers::pi) + " deg";
  };
  const std::string fields =
      tum ? "tx, ty, qz, qw"
          : estimate.name + "_x_m, " + estimate.name + "_y_m, " + estimate.name + "_theta_rad";
  throw sim::ConfigError(
      file + ":" + std::to_string(estimate.poses.front().line_number), fields,
      estimate.name + " starts at " + pose(start) + ", " + msgs::SixDigitNumber(offset_m) +
          " m and " + msgs::SixDigitNumber(offset_deg) + " deg from the run's start " +
          pose(truth_start) +
          ": an estimate starts at the spawn pose (it is scored without "
          "alignment, within " +
          msgs::ShortestNumber(kMaxStartOffsetM) + " m and " +
          msgs::ShortestNumber(kMaxStartHeadingOffsetDeg) +
          " deg), so one in another frame or unit (millimetres?) would be scored as its offset");
}

}  // namespace

std::vector<msgs::Pose2D> PosesAtTimes(const NamedTrajectory& estimate,
                                       const std::vector<double>& times, const std::string& file,
                                       double tolerance_s) {
  const std::vector<perception::TimedPose>& poses = estimate.poses;
  const double first = times.front(), last = times.back();
  const auto fail = [&](const perception::TimedPose& pose, const std::string& what) {
    throw sim::ConfigError(file + ":" + std::to_string(pose.line_number), "timestamp", what);
  };
  const std::string run = " (the run's samples span " + Seconds(first) + " to " + Seconds(last) +
                          ", tolerance " + Seconds(tolerance_s) + ")";
  for (const perception::TimedPose& pose : poses) {
    if (pose.time_s < first - tolerance_s || pose.time_s > last + tolerance_s) {
      fail(pose, Seconds(pose.time_s) + " falls outside the run" + run);
    }
  }
  if (poses.front().time_s > first + tolerance_s) {
    fail(poses.front(), "the file starts at " + Seconds(poses.front().time_s) +
                            ", after the run's first sample" + run);
  }
  if (poses.back().time_s < last - tolerance_s) {
    fail(poses.back(), "the file ends at " + Seconds(poses.back().time_s) +
                           ", before the run's last sample" + run);
  }
  std::vector<msgs::Pose2D> out;
  out.reserve(times.size());
  std::size_t j = 0;  // first pose at or after t
  for (const double t : times) {
    while (j < poses.size() && poses[j].time_s < t) ++j;
    if (j < poses.size() && poses[j].time_s == t) {
      out.push_back(poses[j].pose);
    } else if (j == 0) {
      out.push_back(poses.front().pose);
    } else if (j == poses.size()) {
      out.push_back(poses.back().pose);
    } else {
      const perception::TimedPose& a = poses[j - 1];
      const perception::TimedPose& b = poses[j];
      const double w = (t - a.time_s) / (b.time_s - a.time_s);
      out.push_back({a.pose.x_m + w * (b.pose.x_m - a.pose.x_m),
                     a.pose.y_m + w * (b.pose.y_m - a.pose.y_m),
                     msgs::WrapAngle(a.pose.theta_rad +
                                     w * msgs::WrapAngle(b.pose.theta_rad - a.pose.theta_rad))});
    }
  }
  return out;
}

ScoreReport ScoreTrajectoryFile(const std::filesystem::path& run_dir,
                                const std::filesystem::path& file,
                                const TrajectoryScoreOptions& options) {
  const std::filesystem::path truth_path =
      RunFile(run_dir, "trajectory.csv",
              "the run's ground truth; multi-run protocols keep it in each run's subfolder");
  std::vector<NamedTrajectory> run = ReadTrajectoryFile(truth_path, "truth");
  const auto truth_it = std::find_if(run.begin(), run.end(),
                                     [](const NamedTrajectory& t) { return t.name == "truth"; });
  if (truth_it == run.end()) {
    throw sim::ConfigError(truth_path.string(), "truth_x_m", "missing: no ground-truth columns");
  }
  std::vector<double> times;
  std::vector<msgs::Pose2D> truth;
  for (const perception::TimedPose& p : truth_it->poses) {
    times.push_back(p.time_s);
    truth.push_back(p.pose);
  }

  std::string name = options.name.empty() ? TrajectoryNameOf(file) : options.name;
  if (!IsMetricName(name)) {
    throw sim::ConfigError("--name", "", NotAMetricName(name));
  }
  // The estimate named so was dropped with the truth columns below, and the file blamed for it:
  // "FILE: header: no estimate to score (only truth columns)" (s59).
  if (options.name == "truth") {
    throw sim::ConfigError("--name", "",
                           "'truth' names the run's ground truth, which is never scored against "
                           "itself: give the estimate another name");
  }
  std::vector<NamedTrajectory> estimates = ReadTrajectoryFile(file, name, options.name);
  std::erase_if(estimates, [](const NamedTrajectory& t) { return t.name == "truth"; });
  if (estimates.empty()) {
    throw sim::ConfigError(file.string(), "header", "no estimate to score (only truth columns)");
  }

  ScoreReport report;
  const double distance = robot::ScoreTrajectory(truth, truth).distance_travelled_m;
  if (!(distance >= robot::kMinDriftDistanceM)) {
    // A scorer never reports a number against empty ground truth (drift_percent divides by it).
    throw sim::ConfigError((run_dir / "trajectory.csv").string(), "truth_x_m, truth_y_m",
                           "the ground truth travels " + sim::FormatNumber(distance) +
                               " m, less than 1 cm: drift_percent (per distance travelled) is "
                               "undefined, nothing to score against");
  }
  report.metrics.Set("truth.distance_m", distance);
  char line[512];
  std::snprintf(line, sizeof(line), "%-18s %s: %zu samples, %s to %s, %.3f m travelled\n", "run",
                run_dir.c_str(), times.size(), sim::FormatNumber(times.front()).c_str(),
                Seconds(times.back()).c_str(), distance);
  report.table += line;
  std::snprintf(line, sizeof(line), "%-18s %s: %zu trajectories, %zu poses\n", "file", file.c_str(),
                estimates.size(), estimates.front().poses.size());
  report.table += line;
  std::snprintf(line, sizeof(line), "%-18s %14s %18s %14s %12s\n", "estimate", "final_error_m",
                "heading_error_deg", "drift_percent", "ate_rms_m");
  report.table += line;
  for (const NamedTrajectory& estimate : estimates) {
    const std::vector<msgs::Pose2D> poses =
        PosesAtTimes(estimate, times, file.string(), options.time_tolerance_s);
    RequireStartAtTheSpawn(estimate, poses.front(), truth.front(), file.string(),
                           !IsPlywoodCsvLayout(file));
    const robot::TrajectoryErrors errors = robot::ScoreTrajectory(truth, poses);
    const std::string key = "odometry." + estimate.name + ".";
    report.metrics.Set(key + "final_error_m", errors.final_error_m);
    report.metrics.Set(key + "heading_error_deg", errors.heading_error_deg);
    report.metrics.Set(key + "drift_percent", errors.drift_percent);
    report.metrics.Set(key + "ate_rms_m", errors.ate_rms_m);
    std::snprintf(line, sizeof(line), "%-18s %14.6f %18.4f %14.4f %12.6f\n", estimate.name.c_str(),
                  errors.final_error_m, errors.heading_error_deg, errors.drift_percent,
                  errors.ate_rms_m);
    report.table += line;
  }
  return report;
}

}  // namespace plywood::eval
