#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "eval/score/trajectory_file.h"
#include "msgs/laser_scan.h"
#include "msgs/range_ring.h"
#include "sim/config/experiment_config.h"
#include "sim/world/ground_truth_walls.h"
#include "sim/world/scene.h"
#include "viewer/frame_content.h"
#include "viewer/view_controls.h"
#include "viewer/viewer_window.h"

namespace plywood::viewer {

// A finished single run read back from its directory (docs/run_outputs.md): no physics, only the
// world, the robot and what the run logged.
struct RunReplayData {
  sim::ExperimentConfig config;
  std::vector<eval::NamedTrajectory> trajectories;  // "truth" first, then the estimates
  struct Scan {
    double time_s = 0.0;
    msgs::Pose2D X_WS;  // true sensor pose
    msgs::LaserScan scan;
  };
  std::vector<Scan> laser;             // from laser.log, when the run wrote it
  std::vector<msgs::RangeRing> sonar;  // from sonar.csv (X_RS filled from the robot model)
  // The final maps, when the run made them (cognitive_map.json, geometric_map.json).
  std::optional<MapView> map;
  std::optional<GeometricMapView> geometric_map;
  // walls.csv: the box faces the run's world had, to tell a world file changed since the run.
  sim::GroundTruthWalls walls;
  std::filesystem::path config_yaml;

  double start_s() const;
  double end_s() const;
};

// Reads `run_dir`. Refuses a directory that is not a complete single run: config.yaml missing or
// bad, a multi-run protocol's directory, metrics.json missing (the run did not finish), a missing
// or bad trajectory.csv; laser.log, sonar.csv and the map files are optional, but checked when
// present.
// @throws sim::ConfigError naming the file (and line, field).
RunReplayData LoadRunReplay(const std::filesystem::path& run_dir);

// The pose of `trajectory` at `t_s`: the sample stamped then, else the linear interpolation of the
// two around it (heading along the shorter arc); clamped to the ends.
msgs::Pose2D PoseAt(const eval::NamedTrajectory& trajectory, double t_s);

// Shows a replay: the robot placed on its ground-truth path at the timeline's time, the logged
// laser scan and sonar ring nearest before it, the paths up to it. Space plays / pauses, the
// timeline slider (Dear ImGui) or , / . seek.
class ReplayViewer {
 public:
  // @throws std::runtime_error when no window can be opened; ConfigError for a bad world or one
  // changed since the run (RequireWorldAsTheRunSawIt).
  ReplayViewer(RunReplayData data, const WindowOptions& window);
  ~ReplayViewer();

  // Draws the run at `t_s` (clamped to the run).
  void ShowAt(double t_s);
  // Interactive: plays from the start at 1x until the window is closed.
  void Run();

  ViewerWindow& window() { return *window_; }
  ViewControls& controls() { return *controls_; }
  const sim::Scene& scene() const { return *scene_; }
  double time_s() const { return time_s_; }

 private:
  FrameContent ContentAt(double t_s) const;

  RunReplayData data_;
  std::unique_ptr<sim::Scene> scene_;
  std::unique_ptr<ViewerWindow> window_;
  std::unique_ptr<ViewControls> controls_;
  render::WorldBounds world_;
  std::vector<msgs::Pose2D> sonar_X_RS_;
  double sonar_height_m_ = 0.2;
  double laser_height_m_ = 0.3;
  double time_s_ = 0.0;
};

}  // namespace plywood::viewer
