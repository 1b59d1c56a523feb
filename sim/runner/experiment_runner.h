#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "msgs/bumpers.h"
#include "msgs/gyro_rate.h"
#include "msgs/laser_scan.h"
#include "msgs/pose2d.h"
#include "msgs/range_ring.h"
#include "msgs/wheel_encoders.h"
#include "robot/control/controller.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/metrics.h"
#include "sim/runner/part_timer.h"
#include "sim/runner/run_observer.h"
#include "sim/world/ground_truth_walls.h"
#include "sim/world/scene.h"

namespace plywood::sim {

// One row of trajectory.csv: ground truth and every estimate the run computed, at one instant.
struct TrajectorySample {
  double time_s = 0.0;
  msgs::Pose2D truth;
  std::vector<msgs::Pose2D> estimates;  // in the order of RunRecord::estimator_names
};

// A laser scan with what the simulator knows about it: poses, and the ground-truth wall segment
// each beam hit (-1: nothing, or a geom that is not a wall segment, such as a table leg).
struct LaserRecord {
  msgs::LaserScan scan;
  msgs::Pose2D X_WR_truth;
  msgs::Pose2D X_WR_odometry;
  std::vector<int> hit_geom_ids;
  std::vector<int> hit_segment_ids;  // indices into RunRecord::walls.segments
};

// Everything a run produced, in memory; RunWriter puts it on disk.
struct RunRecord {
  std::vector<std::string> estimator_names;
  std::vector<TrajectorySample> trajectory;
  std::vector<LaserRecord> laser;
  std::vector<msgs::SonarRing> sonar;
  std::vector<msgs::IrRing> ir_ring;
  std::vector<LaserRecord> ir_scanner;  // the same record for the rotating IR head
  std::vector<msgs::WheelEncoders> encoders;
  std::vector<msgs::GyroRate> gyro;
  std::vector<msgs::Bumpers> bumpers;
  // At the laser's height when there is a laser, else at the IR scanner's when there is one, else
  // all heights.
  GroundTruthWalls walls;
  Metrics metrics;
};

// What a run cost; wall-clock figures, so never part of metrics.json.
struct RunCost {
  double wall_s = 0.0;
  double simulated_s = 0.0;
  long steps = 0;
  long rays = 0;
  double RealTimeFactor() const { return wall_s > 0.0 ? simulated_s / wall_s : 0.0; }
};

// Runs one experiment: builds the scene, the sensors (each with its own seed derived from the
// experiment's), the controller and the estimators; steps physics at physics.timestep_s; samples
// every sensor on its own schedule; feeds the hardware-side code plain messages; records ground
// truth beside every estimate; and scores the run.
class ExperimentRunner {
 public:
  // Called about once per simulated second with the fraction done.
  using Progress = std::function<void(double fraction, double simulated_s)>;

  // @throws ConfigError when the world, the robot or a sensor site does not fit the config.
  explicit ExperimentRunner(const ExperimentConfig& config);
  ~ExperimentRunner();
  ExperimentRunner(const ExperimentRunner&) = delete;
  ExperimentRunner& operator=(const ExperimentRunner&) = delete;

  // Runs until duration_s or until the controller has finished.
  // @throws std::runtime_error if the physics diverges.
  void Run(const Progress& progress = {});

  const RunRecord& record() const { return record_; }
  // For scorers that run after the run (line extraction, occupancy) and add their metrics.
  RunRecord& mutable_record() { return record_; }
  // The controller that drove the run (null for idle), e.g. to read an exploration map.
  const robot::Controller* controller() const;
  const RunCost& cost() const { return cost_; }
  // Times each part of the step loop into `*times` from the next Run on (null: off, the default).
  void ProfileStepParts(StepPartTimes* times) { part_times_ = times; }
  // Shows every step of the next Run to `observer` (null: none, the default). Not owned.
  void SetObserver(RunObserver* observer) { observer_ = observer; }
  // The latest wheel command the controller (or a teleoperating observer) gave.
  const msgs::WheelSpeedCommand& wheel_command() const { return wheel_command_; }
  const Scene& scene() const { return *scene_; }
  Scene& mutable_scene() { return *scene_; }
  const ExperimentConfig& config() const { return config_; }

 private:
  struct Parts;

  void SampleSensors();
  // Reads the odometry sensors (encoders, gyro) now unless they were read at this instant, off
  // their schedule, and feeds the estimators: a robot reads its counters when it stops.
  void ReadOdometryNow();
  // One encoder / gyro reading: recorded and fed to every estimator (on schedule or off it).
  void ReadEncoders();
  void ReadGyro();
  // The record of the scan in parts_->scan_scratch, taken from the sensor site `site_id`.
  LaserRecord MakeScanRecord(int site_id) const;
  void Score();

  ExperimentConfig config_;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<Parts> parts_;
  RunRecord record_;
  RunCost cost_;
  StepPartTimes* part_times_ = nullptr;
  RunObserver* observer_ = nullptr;
  msgs::WheelSpeedCommand wheel_command_;
};

// Seed of one component, derived from the experiment seed and the component's name so that adding
// a sensor never changes another sensor's noise.
std::uint64_t ComponentSeed(std::uint64_t experiment_seed, const std::string& component);

}  // namespace plywood::sim
