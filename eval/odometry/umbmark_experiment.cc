#include "eval/odometry/umbmark_experiment.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "msgs/angle_units.h"
#include "sim/config/config_archive.h"
#include "sim/config/config_error.h"
#include "sim/config/yaml_fields.h"

namespace plywood::eval {
namespace {

void SetStageMetrics(sim::Metrics& m, const std::string& prefix, const UmbmarkStage& stage) {
  const robot::UmbmarkResult& r = stage.result;
  m.Set(prefix + "x_cg_cw_m", r.x_cg_cw_m);
  m.Set(prefix + "y_cg_cw_m", r.y_cg_cw_m);
  m.Set(prefix + "x_cg_ccw_m", r.x_cg_ccw_m);
  m.Set(prefix + "y_cg_ccw_m", r.y_cg_ccw_m);
  m.Set(prefix + "r_cg_cw_m", r.r_cg_cw_m);
  m.Set(prefix + "r_cg_ccw_m", r.r_cg_ccw_m);
  m.Set(prefix + "alpha_deg", r.alpha_rad * kRadToDeg);
  m.Set(prefix + "beta_deg", r.beta_rad * kRadToDeg);
  m.Set(prefix + "ed", r.ed);
  m.Set(prefix + "eb", r.eb);
  m.Set(prefix + "calibration.wheel_diameter_ratio", stage.calibration.wheel_diameter_ratio);
  m.Set(prefix + "calibration.track_ratio", stage.calibration.track_ratio);
  m.Set(prefix + "turns.count", stage.turn_calibration.turns);
  m.Set(prefix + "turns.mean_error_deg", stage.turn_calibration.mean_error_deg);
  m.Set(prefix + "turns.error_sigma_deg", stage.turn_calibration.error_sigma_deg);
  m.Set(prefix + "turns.track_ratio", stage.turn_calibration.track_ratio);
}

}  // namespace

void UmbmarkOptions::Validate() const {
  if (runs_per_direction < 1 || runs_per_direction > 100) {
    throw std::invalid_argument("runs_per_direction: must be in [1, 100], got " +
                                std::to_string(runs_per_direction));
  }
}

UmbmarkOptions ReadUmbmarkOptions(const sim::ExperimentConfig& config) {
  UmbmarkOptions options;
  ReadOptions(sim::YamlFields(config.protocol_options, config.source_file, "umbmark"), options);
  return options;
}

std::vector<robot::TurnObservation> ExtractTurns(const sim::RunRecord& record,
                                                 std::size_t estimator) {
  std::vector<robot::TurnObservation> turns;
  const auto& trajectory = record.trajectory;
  const auto at_rest = [&](std::size_t i) {
    return i > 0 && trajectory[i].estimates[estimator] == trajectory[i - 1].estimates[estimator];
  };
  std::size_t motion_start = 0;  // last sample of the previous rest
  bool moving = false;
  for (std::size_t i = 1; i < trajectory.size(); ++i) {
    if (!at_rest(i)) {
      if (!moving) motion_start = i - 1;
      moving = true;
      continue;
    }
    if (!moving) continue;
    moving = false;
    const msgs::Pose2D& e0 = trajectory[motion_start].estimates[estimator];
    const msgs::Pose2D& e1 = trajectory[i].estimates[estimator];
    const double odometry_turn = msgs::WrapAngle(e1.theta_rad - e0.theta_rad);
    const double moved = std::hypot(e1.x_m - e0.x_m, e1.y_m - e0.y_m);
    if (std::abs(odometry_turn) > std::numbers::pi / 4.0 && moved < 0.05) {
      turns.push_back({odometry_turn, msgs::WrapAngle(trajectory[i].truth.theta_rad -
                                                      trajectory[motion_start].truth.theta_rad)});
    }
  }
  return turns;
}

UmbmarkOutcome RunUmbmark(const sim::ExperimentConfig& config, const UmbmarkOptions& options,
                          const UmbmarkRunSink& sink) {
  options.Validate();
  if (config.controller.type != "square_path") {
    throw sim::ConfigError(
        config.source_file, "controller.type",
        "UMBmark drives squares: expected square_path, got '" + config.controller.type + "'");
  }
  if (config.controller.steer_by == "ground_truth") {
    throw sim::ConfigError(config.source_file, "controller.steer_by",
                           "UMBmark measures the odometry the robot steers by: name an estimator "
                           "(e.g. encoder), not ground_truth");
  }
  const double side_m = config.controller.square_path.side_m;
  UmbmarkOutcome outcome;

  const auto drive = [&](const std::string& stage_name,
                         const robot::OdometryCalibration& calibration) {
    UmbmarkStage stage;
    stage.calibration = calibration;
    int index = 0;
    for (robot::SquareDirection direction :
         {robot::SquareDirection::kClockwise, robot::SquareDirection::kCounterClockwise}) {
      for (int i = 1; i <= options.runs_per_direction; ++i, ++index) {
        sim::ExperimentConfig run = config;
        run.protocol = "single";
        run.protocol_options = YAML::Node();
        run.seed = config.seed + static_cast<std::uint64_t>(index);
        run.odometry.calibration = calibration;
        run.controller.square_path.direction = direction;
        run.controller.square_path.laps = 1;
        if (direction == robot::SquareDirection::kClockwise) run.spawn.theta_deg += 90.0;
        const std::string name = std::string(robot::ToString(direction)) + "_" + std::to_string(i);
        run.name = config.name + "-" + stage_name + "-" + name;
        sim::ExperimentRunner runner(run);
        runner.Run();
        const sim::RunRecord& record = runner.record();
        const auto& names = record.estimator_names;
        const std::size_t steering =
            std::find(names.begin(), names.end(), config.controller.steer_by) - names.begin();
        const sim::TrajectorySample& first = record.trajectory.front();
        const sim::TrajectorySample& last = record.trajectory.back();
        stage.runs.push_back(robot::UmbmarkReturnError(direction, first.truth, last.truth,
                                                       last.estimates[steering]));
        for (const auto& turn : ExtractTurns(record, steering)) stage.turns.push_back(turn);
        if (sink) sink(stage_name, name, run, record);
      }
    }
    stage.result = robot::AnalyseUmbmark(
        stage.runs, side_m, robot::CalibratedGeometry(config.nominal, calibration).track_m);
    if (!stage.turns.empty()) stage.turn_calibration = robot::CalibrateTurns(stage.turns);
    return stage;
  };

  outcome.before = drive("before", config.odometry.calibration);
  outcome.corrected =
      robot::CorrectedCalibration(outcome.before.calibration, outcome.before.result);
  sim::Metrics& m = outcome.metrics;
  SetStageMetrics(m, "umbmark.before.", outcome.before);
  m.Set("umbmark.e_max_syst_before_m", outcome.before.result.e_max_syst_m);
  m.Set("umbmark.ed", outcome.before.result.ed);
  m.Set("umbmark.eb", outcome.before.result.eb);
  m.Set("umbmark.corrected.wheel_diameter_ratio", outcome.corrected.wheel_diameter_ratio);
  m.Set("umbmark.corrected.track_ratio", outcome.corrected.track_ratio);
  m.Set("umbmark.side_m", side_m);
  m.Set("umbmark.runs_per_direction", options.runs_per_direction);
  m.Set("umbmark.steer_by", config.controller.steer_by);
  if (options.correct) {
    outcome.after = drive("after", outcome.corrected);
    SetStageMetrics(m, "umbmark.after.", outcome.after);
    m.Set("umbmark.e_max_syst_after_m", outcome.after.result.e_max_syst_m);
    m.Set("umbmark.improvement_factor",
          outcome.after.result.e_max_syst_m > 0.0
              ? outcome.before.result.e_max_syst_m / outcome.after.result.e_max_syst_m
              : 0.0);
  }
  return outcome;
}

}  // namespace plywood::eval
