#include "eval/lines/back_to_back_scans.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sim/config/config_error.h"
#include "sim/runner/experiment_runner.h"

namespace plywood::eval {
namespace {

// One idle run with the laser site at p_W facing theta_rad.
sim::RunRecord ScanFrom(const sim::ExperimentConfig& base, const Eigen::Vector2d& p_W,
                        double theta_rad, int scans, std::uint64_t seed) {
  sim::ExperimentConfig config = base;
  config.protocol = "single";
  config.seed = seed;
  config.controller = sim::ControllerConfig{};  // idle
  config.odometry = sim::OdometryConfig{};
  config.sensors = sim::SensorSuiteConfig{};
  config.sensors.laser = base.sensors.laser;
  config.output.snapshot = false;
  // The rig's scans are scored against the ground truth: the runner's checks of a scored run apply
  // (a world geom the truth cannot hold is refused) whether or not the experiment lists `lines:`.
  config.lines.given = true;
  // Just long enough for `scans` scans at the laser's rate (one at t = 0).
  config.duration_s = (static_cast<double>(scans) - 0.5) / base.sensors.laser->rate_hz;
  const auto spawn = [&](const Eigen::Vector2d& site_R) {
    const Eigen::Vector2d robot_W = p_W - Eigen::Rotation2Dd(theta_rad).toRotationMatrix() * site_R;
    config.spawn = {robot_W.x(), robot_W.y(), theta_rad * 180.0 / std::numbers::pi};
  };
  spawn(Eigen::Vector2d::Zero());
  Eigen::Vector2d site_R = Eigen::Vector2d::Zero();
  {
    const sim::ExperimentRunner probe(config);
    const auto site = probe.scene().FindSite("laser");
    if (!site)
      throw sim::ConfigError(base.source_file, "robot.model", "the robot has no laser site");
    const msgs::Pose2D X_RS = probe.scene().SitePoseInRobot(*site);
    site_R = {X_RS.x_m, X_RS.y_m};
  }
  spawn(site_R);
  sim::ExperimentRunner runner(config);
  runner.Run();
  sim::RunRecord record = std::move(runner.mutable_record());
  if (static_cast<int>(record.laser.size()) > scans) record.laser.resize(scans);
  return record;
}

}  // namespace

BackToBackScans TakeBackToBackScans(const sim::ExperimentConfig& config, const Eigen::Vector2d& p_W,
                                    double theta_rad, int scans) {
  if (!config.sensors.laser) {
    throw sim::ConfigError(config.source_file, "sensors.laser", "missing: the rig needs a laser");
  }
  if (scans < 1) throw std::invalid_argument("scans: must be >= 1, got " + std::to_string(scans));
  BackToBackScans rig;
  sim::RunRecord front = ScanFrom(config, p_W, theta_rad, scans, config.seed);
  // The back scanner's noise from its own stream: seed + 1 was the next seed's front scanner, so
  // seeds pooled in a sweep shared their draws.
  sim::RunRecord back = ScanFrom(config, p_W, theta_rad + std::numbers::pi, scans,
                                 sim::ComponentSeed(config.seed, "back scanner"));
  rig.front = std::move(front.laser);
  rig.back = std::move(back.laser);
  rig.walls = std::move(front.walls);
  return rig;
}

std::vector<TruthScan> MakeTruthScans(const BackToBackScans& rig, double range_cut_m) {
  std::vector<TruthScan> scans;
  const std::size_t n = std::min(rig.front.size(), rig.back.size());
  for (std::size_t i = 0; i < n; ++i) {
    const sim::LaserRecord* pair[] = {&rig.front[i], &rig.back[i]};
    scans.push_back(MakeTruthScan(pair, rig.walls, range_cut_m));
  }
  return scans;
}

}  // namespace plywood::eval
