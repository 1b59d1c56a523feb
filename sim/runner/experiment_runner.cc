#include "sim/runner/experiment_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "msgs/angle_units.h"
#include "msgs/shortest_number.h"
#include "msgs/stable_hash.h"
#include "robot/control/controller.h"
#include "robot/odometry/trajectory_metrics.h"
#include "sim/config/config_error.h"
#include "sim/config/controller_config.h"
#include "sim/config/odometry_config.h"
#include "sim/raycast/grid_ray_caster_2d.h"
#include "sim/runner/checked_scene.h"
#include "sim/runner/controller_targets.h"
#include "sim/runner/sensors_the_config_needs.h"
#include "sim/sensors/sensor_schedule.h"
#include "sim/world/occupancy_raster.h"
#include "sim/world/setup_checks.h"

namespace plywood::sim {

// The types of ExperimentRunner::Parts' members. Parts has external linkage, so they are named
// rather than in the anonymous namespace (GCC's -Wsubobject-linkage, once this source shares a
// unity batch with others).
namespace experiment_runner_detail {

// A sensor together with its sampling schedule.
template <typename Sensor>
struct Scheduled {
  template <typename... Args>
  Scheduled(double rate_hz, Args&&... args)
      : schedule(rate_hz), sensor(std::forward<Args>(args)...) {}
  SensorSchedule schedule;
  Sensor sensor;
};

// A ground-truth face as the beam labels use it: its index into RunRecord::walls.segments, its
// first end a and b - a, taken once instead of for every beam.
struct FaceForLabels {
  int index = -1;
  double ax = 0.0, ay = 0.0, abx = 0.0, aby = 0.0;
  // From the current scan's origin o (MakeScanRecord fills them once per scan and geom): a - o and
  // the numerator of the beam's distance t, which do not depend on the beam.
  double aox = 0.0, aoy = 0.0, t_numerator = 0.0;
};

// A scan's beam directions in the sensor frame, (cos, sin) of each beam angle, kept while the
// scan's angles stay the same: the labels then turn them by the heading (one sincos per scan
// instead of one per beam, ~7 us of a 361-beam scan).
struct BeamDirections {
  double angle_min_rad = 0.0, angle_increment_rad = 0.0;
  std::vector<double> cos, sin;

  void Update(const msgs::LaserScan& scan) {
    const std::size_t n = scan.ranges_m.size();
    if (cos.size() == n && angle_min_rad == scan.angle_min_rad &&
        angle_increment_rad == scan.angle_increment_rad) {
      return;
    }
    angle_min_rad = scan.angle_min_rad;
    angle_increment_rad = scan.angle_increment_rad;
    cos.resize(n);
    sin.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      cos[i] = std::cos(scan.BeamAngleRad(i));
      sin[i] = std::sin(scan.BeamAngleRad(i));
    }
  }
};

}  // namespace experiment_runner_detail

using experiment_runner_detail::BeamDirections;
using experiment_runner_detail::FaceForLabels;
using experiment_runner_detail::Scheduled;

namespace {

// MuJoCo (and the planar drive) would zero a non-finite command and let the robot stand still
// silently; a run whose controller computes NaN must fail and say so instead.
// The time is formatted only for the error: this runs at every control tick.
void RequireFiniteCommand(const msgs::WheelSpeedCommand& command, double time_s, double dt,
                          const char* source) {
  if (std::isfinite(command.left_rad_s) && std::isfinite(command.right_rad_s)) return;
  throw std::runtime_error(std::string(source) + " gave a non-finite wheel speed at t=" +
                           FormatNumber(TimeAtStepPrecision(time_s, dt)) + " s (left " +
                           msgs::ShortestNumber(command.left_rad_s) + ", right " +
                           msgs::ShortestNumber(command.right_rad_s) + " rad/s)");
}

// The ground-truth segment a beam hit: the first of the hit geom's faces (`candidates`, their
// aox, aoy and t_numerator filled for the beam's origin) that the beam's ray crosses (exact, and
// independent of the range noise). u is only taken for a face at a t that could win.
int HitSegment(const std::vector<FaceForLabels>& candidates, double dir_x, double dir_y) {
  int best = -1;
  double best_t = std::numeric_limits<double>::infinity();
  for (const FaceForLabels& f : candidates) {
    // Solve origin + t dir = a + u (b - a) for t >= 0, u in [0, 1].
    const double denominator = dir_x * f.aby - dir_y * f.abx;
    if (std::abs(denominator) < 1e-12) continue;
    const double t = f.t_numerator / denominator;
    if (!(t >= 0.0 && t < best_t)) continue;
    const double u = (f.aox * dir_y - f.aoy * dir_x) / denominator;
    if (u >= -1e-9 && u <= 1.0 + 1e-9) {
      best_t = t;
      best = f.index;
    }
  }
  return best;
}

}  // namespace

std::uint64_t ComponentSeed(std::uint64_t experiment_seed, const std::string& component) {
  return SplitMix64(experiment_seed ^ SplitMix64(Fnv1a64(component)));
}

struct ExperimentRunner::Parts {
  std::unique_ptr<RayCaster> caster;
  std::optional<Scheduled<LaserSensor>> laser;
  std::optional<Scheduled<SonarSensor>> sonar;
  std::optional<Scheduled<IrRingSensor>> ir_ring;
  std::optional<Scheduled<IrScannerSensor>> ir_scanner;
  std::optional<Scheduled<EncoderSensor>> encoders;
  std::optional<Scheduled<GyroSensor>> gyro;
  std::optional<Scheduled<BumperSensor>> bumpers;
  std::unique_ptr<robot::Controller> controller;
  std::optional<SensorSchedule> control_schedule;
  SensorSchedule trajectory_schedule{10.0};
  std::vector<std::unique_ptr<robot::OdometryEstimator>> estimators;
  // The estimate the controller steers by; null: ground truth.
  const robot::OdometryEstimator* steering = nullptr;
  // Latest readings handed to the controller.
  std::optional<msgs::SonarRing> last_sonar;
  std::optional<msgs::LaserScan> last_laser;
  ScanMeasurement scan_scratch;
  // Each geom's faces in RunRecord::walls.segments, by geom id.
  // Mutable: their per-scan fields are MakeScanRecord's scratch (stamped by geom: filled once
  // per scan for the geoms its beams hit).
  mutable std::vector<std::vector<FaceForLabels>> segments_of_geom;
  mutable std::vector<unsigned> labels_stamp;
  mutable unsigned labels_epoch = 0;
  mutable std::vector<std::pair<int, BeamDirections>> beam_directions_by_site;
  long rays_per_laser_scan = 0, rays_per_sonar_ring = 0, rays_per_ir_ring = 0, rays_per_ir_scan = 0;
};

ExperimentRunner::ExperimentRunner(const ExperimentConfig& config)
    : config_(config), parts_(std::make_unique<Parts>()) {
  scene_ = MakeCheckedScene(config);
  RequireReachableControllerTargets(config, *scene_);
  RequireControllerSensors(config);

  Parts& p = *parts_;
  p.caster = std::make_unique<GridRayCaster2D>(scene_->model(), scene_->data());
  const SensorSuiteConfig& s = config.sensors;
  const std::uint64_t seed = config.seed;
  // A sensor the robot cannot carry (no such site) is reported against the experiment file.
  const auto in_file = [&](const char* sensor, auto make) {
    try {
      make();
    } catch (const ConfigError& e) {
      throw ConfigError(config.source_file, std::string("sensors.") + sensor,
                        "robot '" + config.robot + "' cannot carry it: " + e.what());
    }
  };
  if (s.laser) {
    in_file("laser", [&] {
      p.laser.emplace(s.laser->rate_hz, *scene_, "laser", *s.laser, ComponentSeed(seed, "laser"));
    });
    p.rays_per_laser_scan = s.laser->BeamCount();
  }
  if (s.sonar) {
    in_file("sonar", [&] {
      p.sonar.emplace(s.sonar->rate_hz, *scene_, SonarSensor::DefaultSiteNames(), *s.sonar,
                      ComponentSeed(seed, "sonar"));
    });
    p.rays_per_sonar_ring = 16L * s.sonar->rays_per_cone;
  }
  if (s.ir_ring) {
    in_file("ir_ring", [&] {
      p.ir_ring.emplace(s.ir_ring->rate_hz, *scene_, IrRingSensor::DefaultSiteNames(), *s.ir_ring,
                        ComponentSeed(seed, "ir_ring"));
    });
    p.rays_per_ir_ring = 16L * s.ir_ring->rays_per_beam;
  }
  if (s.ir_scanner) {
    in_file("ir_scanner", [&] {
      p.ir_scanner.emplace(s.ir_scanner->rate_hz, *scene_, "ir_scanner", *s.ir_scanner,
                           ComponentSeed(seed, "ir_scanner"));
    });
    p.rays_per_ir_scan = s.ir_scanner->BeamCount();
  }
  if (s.encoders) {
    p.encoders.emplace(s.encoders->rate_hz, *s.encoders, ComponentSeed(seed, "encoders"));
  }
  RequireOdometrySensors(config);
  for (auto& [name, estimator] :
       MakeEstimators(config.odometry, config.nominal, scene_->TruePose())) {
    record_.estimator_names.push_back(name);
    if (config.controller.steer_by == name) p.steering = estimator.get();
    p.estimators.push_back(std::move(estimator));
  }
  if (s.gyro) p.gyro.emplace(s.gyro->rate_hz, *s.gyro, ComponentSeed(seed, "gyro"));
  if (s.bumpers) {
    in_file("bumpers", [&] { p.bumpers.emplace(s.bumpers->rate_hz, *scene_, *s.bumpers); });
  }
  if (config.controller.steer_by != "ground_truth" && p.steering == nullptr) {
    throw ConfigError(config.source_file, "controller.steer_by",
                      "expected ground_truth or an estimator enabled under odometry: (which needs "
                      "sensors.encoders), got '" +
                          config.controller.steer_by + "'");
  }
  try {
    p.controller = MakeController(config.controller, config.nominal);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(config.source_file, "controller", e.what());
  }
  if (p.controller) p.control_schedule.emplace(config.controller.rate_hz);
  p.trajectory_schedule = SensorSchedule(config.output.trajectory_rate_hz);

  GroundTruthOptions truth_options;
  if (p.laser) {
    truth_options.height_m = scene_->SitePoseInWorld(p.laser->sensor.site_id()).translation().z();
  } else if (p.ir_scanner) {
    truth_options.height_m =
        scene_->SitePoseInWorld(p.ir_scanner->sensor.site_id()).translation().z();
  }
  record_.walls = ExtractGroundTruthWalls(scene_->model(), truth_options);
  // The slices a run is scored in against the 2-D ground truth: its line scores' and geometric
  // map's at the scanner's height, the sonar explorer's occupancy truth at the raster's.
  std::vector<double> scored_heights_m;
  if ((config.lines.given || config.geometric_map.given) && truth_options.height_m) {
    scored_heights_m.push_back(*truth_options.height_m);
  }
  if (config.controller.type == "sonar_explorer") {
    scored_heights_m.push_back(OccupancyRasterOptions{}.height_m);
  }
  for (const double height_m : scored_heights_m) {
    if (const auto problem = GeomTheGroundTruthCannotHold(*scene_, height_m)) {
      throw ConfigError(config.source_file, "world", config.world_path.string() + ": " + *problem);
    }
  }
  if (const auto problem = GeomThePlanarDriveHoldsByItsBound(*scene_)) {
    throw ConfigError(config.source_file, "world", config.world_path.string() + ": " + *problem);
  }
  // The rasters laid over the whole world after the run: the sonar map's truth, the geometric
  // map's picture. Checked now, not after minutes of running.
  std::vector<double> raster_resolutions_m;
  if (config.controller.type == "sonar_explorer") {
    raster_resolutions_m.push_back(kOccupancyTruthResolutionM);
  }
  if (config.geometric_map.given && config.output.snapshot) {
    raster_resolutions_m.push_back(kGeometricMapPictureResolutionM);
  }
  for (const double resolution_m : raster_resolutions_m) {
    if (const auto problem = WorldTooWideToRasterise(*scene_, resolution_m)) {
      throw ConfigError(config.source_file, "world", config.world_path.string() + ": " + *problem);
    }
  }
  p.segments_of_geom.resize(scene_->model()->ngeom);
  p.labels_stamp.assign(scene_->model()->ngeom, 0u);
  for (std::size_t i = 0; i < record_.walls.segments.size(); ++i) {
    const WallSegment& w = record_.walls.segments[i];
    const Eigen::Vector2d ab = w.b - w.a;
    p.segments_of_geom[w.geom_id].push_back(
        {static_cast<int>(i), w.a.x(), w.a.y(), ab.x(), ab.y()});
  }
}

ExperimentRunner::~ExperimentRunner() = default;

const robot::Controller* ExperimentRunner::controller() const { return parts_->controller.get(); }

LaserRecord ExperimentRunner::MakeScanRecord(int site_id) const {
  const Parts& p = *parts_;
  LaserRecord record;
  record.scan = p.scan_scratch.scan;
  record.X_WR_truth = scene_->TruePose();
  // The log's odometry pose: the steering estimate, else the first estimator, else truth.
  record.X_WR_odometry = p.steering             ? p.steering->pose()
                         : p.estimators.empty() ? record.X_WR_truth
                                                : p.estimators.front()->pose();
  record.hit_geom_ids = p.scan_scratch.hit_geom_ids;
  record.hit_segment_ids.assign(record.scan.ranges_m.size(), -1);
  const Eigen::Vector2d origin_W = scene_->SitePoseInWorld(site_id).translation().head<2>();
  const double heading_W = (record.X_WR_truth * record.scan.X_RS).theta_rad;
  const double cos_heading = std::cos(heading_W), sin_heading = std::sin(heading_W);
  auto site_beams = std::find_if(p.beam_directions_by_site.begin(), p.beam_directions_by_site.end(),
                                 [&](const auto& entry) { return entry.first == site_id; });
  if (site_beams == p.beam_directions_by_site.end()) {
    site_beams = p.beam_directions_by_site.insert(site_beams, {site_id, {}});
  }
  BeamDirections& beams = site_beams->second;
  beams.Update(record.scan);
  if (++p.labels_epoch == 0) {
    std::fill(p.labels_stamp.begin(), p.labels_stamp.end(), 0u);
    p.labels_epoch = 1;
  }
  for (std::size_t i = 0; i < record.scan.ranges_m.size(); ++i) {
    const int geom = record.hit_geom_ids[i];
    if (geom < 0) continue;
    std::vector<FaceForLabels>& faces = p.segments_of_geom[geom];
    if (faces.empty()) continue;  // a geom without faces at the sensor's height: no label
    if (p.labels_stamp[geom] != p.labels_epoch) {
      p.labels_stamp[geom] = p.labels_epoch;
      for (FaceForLabels& f : faces) {
        f.aox = f.ax - origin_W.x();
        f.aoy = f.ay - origin_W.y();
        f.t_numerator = f.aox * f.aby - f.aoy * f.abx;
      }
    }
    // The beam's world direction: its sensor-frame direction turned by the heading.
    const double dir_x = cos_heading * beams.cos[i] - sin_heading * beams.sin[i];
    const double dir_y = sin_heading * beams.cos[i] + cos_heading * beams.sin[i];
    record.hit_segment_ids[i] = HitSegment(faces, dir_x, dir_y);
  }
  return record;
}

void ExperimentRunner::SampleSensors() {
  Parts& p = *parts_;
  const double t = scene_->time_s();
  StepPartTimes* times = part_times_;
  double* const other_s = times ? &times->other_s : nullptr;
  if (p.encoders && p.encoders->schedule.Due(t)) {
    const PartTimer timer(other_s);
    ReadEncoders();
  }
  if (p.gyro && p.gyro->schedule.Due(t)) {
    const PartTimer timer(other_s);
    ReadGyro();
  }
  if (p.bumpers && p.bumpers->schedule.Due(t)) {
    const PartTimer timer(other_s);
    record_.bumpers.push_back(p.bumpers->sensor.Sample(*scene_));
  }
  if (p.laser && p.laser->schedule.Due(t)) {
    {
      const PartTimer timer(times ? &times->laser_s : nullptr);
      p.laser->sensor.Measure(*scene_, *p.caster, &p.scan_scratch);
    }
    const PartTimer timer(times ? &times->recording_s : nullptr);
    LaserRecord laser = MakeScanRecord(p.laser->sensor.site_id());
    p.last_laser = laser.scan;
    record_.laser.push_back(std::move(laser));
    cost_.rays += p.rays_per_laser_scan;
  }
  if (p.sonar && p.sonar->schedule.Due(t)) {
    std::optional<msgs::SonarRing> ring;
    {
      const PartTimer timer(times ? &times->sonar_s : nullptr);
      ring = p.sonar->sensor.Measure(*scene_, *p.caster);
    }
    const PartTimer timer(times ? &times->recording_s : nullptr);
    record_.sonar.push_back(std::move(*ring));
    p.last_sonar = record_.sonar.back();
    cost_.rays += p.rays_per_sonar_ring;
  }
  if (p.ir_ring && p.ir_ring->schedule.Due(t)) {
    const PartTimer timer(other_s);
    record_.ir_ring.push_back(p.ir_ring->sensor.Measure(*scene_, *p.caster));
    cost_.rays += p.rays_per_ir_ring;
  }
  if (p.ir_scanner && p.ir_scanner->schedule.Due(t)) {
    const PartTimer timer(other_s);
    p.ir_scanner->sensor.Measure(*scene_, *p.caster, &p.scan_scratch);
    record_.ir_scanner.push_back(MakeScanRecord(p.ir_scanner->sensor.site_id()));
    cost_.rays += p.rays_per_ir_scan;
  }
}

void ExperimentRunner::ReadEncoders() {
  Parts& p = *parts_;
  record_.encoders.push_back(p.encoders->sensor.Sample(*scene_));
  for (auto& estimator : p.estimators) estimator->AddEncoders(record_.encoders.back());
}

void ExperimentRunner::ReadGyro() {
  Parts& p = *parts_;
  record_.gyro.push_back(p.gyro->sensor.Sample(*scene_));
  for (auto& estimator : p.estimators) estimator->AddGyro(record_.gyro.back());
}

void ExperimentRunner::ReadOdometryNow() {
  const Parts& p = *parts_;
  const double t = scene_->time_s();
  if (p.encoders && (record_.encoders.empty() || record_.encoders.back().time_s != t)) {
    ReadEncoders();
  }
  if (p.gyro && (record_.gyro.empty() || record_.gyro.back().time_s != t)) ReadGyro();
}

void ExperimentRunner::Run(const Progress& progress) {
  Parts& p = *parts_;
  const auto start = std::chrono::steady_clock::now();
  const double duration = config_.duration_s;
  const double dt = scene_->timestep_s();
  double next_progress_s = 1.0;
  bool finished = false;
  const auto record_trajectory = [&] {
    TrajectorySample sample{scene_->time_s(), scene_->TruePose(), {}};
    for (const auto& estimator : p.estimators) sample.estimates.push_back(estimator->pose());
    record_.trajectory.push_back(std::move(sample));
  };
  // Step k integrates [k dt, (k+1) dt]; the run covers [0, duration] in whole steps.
  const long total_steps = std::lround(std::ceil(duration / dt - 1e-9));
  bool overridden = false;
  bool stopped = observer_ && !observer_->AfterStep(*this);
  for (long step = 0; step < total_steps && !stopped; ++step) {
    SampleSensors();
    const std::optional<msgs::WheelSpeedCommand> override =
        observer_ ? observer_->WheelOverride() : std::nullopt;
    if (override) {
      wheel_command_ = *override;
      RequireFiniteCommand(wheel_command_, scene_->time_s(), dt, "the wheel override");
      scene_->SetWheelSpeeds(wheel_command_);
    } else if (p.controller && p.control_schedule->Due(scene_->time_s())) {
      const PartTimer timer(part_times_ ? &part_times_->controller_s : nullptr);
      robot::ControllerInput input;
      input.time_s = scene_->time_s();
      input.X_WR_estimate = p.steering ? p.steering->pose() : scene_->TruePose();
      input.sonar = p.last_sonar ? &*p.last_sonar : nullptr;
      input.laser = p.last_laser ? &*p.last_laser : nullptr;
      input.bumpers = record_.bumpers.empty() ? nullptr : &record_.bumpers.back();
      wheel_command_ = p.controller->Update(input);
      RequireFiniteCommand(wheel_command_, scene_->time_s(), dt, "the controller");
      scene_->SetWheelSpeeds(wheel_command_);
      if (p.controller->Finished() && !finished) finished = true;
    } else if (overridden && !p.controller) {
      // Handed back to no controller (idle): the robot stops rather than keep the last keys.
      wheel_command_ = {};
      scene_->SetWheelSpeeds(wheel_command_);
    }
    overridden = override.has_value();
    if (p.trajectory_schedule.Due(scene_->time_s())) {
      const PartTimer timer(part_times_ ? &part_times_->recording_s : nullptr);
      record_trajectory();
    }
    if (finished) break;
    // MuJoCo resets the data when the accelerations blow up, so after the step its clock reads one
    // step from zero: a run that diverged at 21.24 s was reported "at t=0.03 s" (s46).
    const double step_start_s = scene_->time_s();
    {
      const PartTimer timer(part_times_ ? &part_times_->physics_s : nullptr);
      scene_->Step();
    }
    ++cost_.steps;
    const mjData* d = scene_->stepped_data();
    if (d->warning[mjWARN_BADQACC].number > 0 || !std::isfinite(d->qpos[0])) {
      throw std::runtime_error(
          "physics diverged at t=" + FormatNumber(TimeAtStepPrecision(step_start_s, dt)) +
          " s (MuJoCo: " + LastMujocoWarning() + "); try a smaller physics.timestep_s");
    }
    if (progress && scene_->time_s() >= next_progress_s) {
      progress(scene_->time_s() / duration, scene_->time_s());
      next_progress_s += 1.0;
    }
    if (observer_ && !observer_->AfterStep(*this)) stopped = true;
  }
  // The final state always closes the trajectory, so scores use the true end point. A run ends
  // between two odometry samples (the controller finishes, the observer stops it); the encoders and
  // the gyro are then read once more at the final instant, so the estimates in the last row
  // describe the same instant as the truth beside it rather than up to a period earlier.
  if (!record_.trajectory.empty() && record_.trajectory.back().time_s == scene_->time_s()) {
    record_.trajectory.pop_back();  // recorded this step, before the final odometry read
  } else {
    SampleSensors();
  }
  ReadOdometryNow();
  record_trajectory();
  cost_.simulated_s = scene_->time_s();
  cost_.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  record_.metrics.Set("run.controller_finished", finished ? 1.0 : 0.0);
  Score();
  if (observer_) observer_->RunFinished(*this);
}

void ExperimentRunner::Score() {
  Metrics& m = record_.metrics;
  m.SetWholeNumber("run.seed", config_.seed);
  // Whole steps times the step, at the step's decimals: MuJoCo's clock is a float sum of the steps
  // (117.62000000002327 for 11762 steps of 0.01 s) and its error grows with the run (s56).
  const double dt = scene_->timestep_s();
  m.Set("run.simulated_s", TimeAtStepPrecision(static_cast<double>(cost_.steps) * dt, dt));
  m.Set("run.steps", static_cast<double>(cost_.steps));
  m.Set("run.world", config_.world_path.filename().string());
  m.Set("run.robot", config_.robot);

  std::vector<msgs::Pose2D> truth;
  for (const auto& sample : record_.trajectory) truth.push_back(sample.truth);
  const msgs::Pose2D& end = truth.back();
  m.Set("truth.final_x_m", end.x_m);
  m.Set("truth.final_y_m", end.y_m);
  m.Set("truth.final_theta_deg", end.theta_rad / kDegToRad);
  for (std::size_t e = 0; e < record_.estimator_names.size(); ++e) {
    std::vector<msgs::Pose2D> estimate;
    for (const auto& sample : record_.trajectory) estimate.push_back(sample.estimates[e]);
    const robot::TrajectoryErrors errors = robot::ScoreTrajectory(truth, estimate);
    const std::string key = "odometry." + record_.estimator_names[e] + ".";
    m.Set(key + "final_error_m", errors.final_error_m);
    m.Set(key + "heading_error_deg", errors.heading_error_deg);
    m.Set(key + "drift_percent", errors.drift_percent);
    m.Set(key + "ate_rms_m", errors.ate_rms_m);
  }
  m.Set("truth.distance_m", robot::ScoreTrajectory(truth, truth).distance_travelled_m);

  if (config_.sensors.laser) {
    long beams = 0, returns = 0, on_walls = 0;
    for (const auto& laser : record_.laser) {
      for (std::size_t i = 0; i < laser.scan.ranges_m.size(); ++i) {
        ++beams;
        returns += laser.scan.IsReturn(i);
        on_walls += laser.hit_segment_ids[i] >= 0;
      }
    }
    m.Set("sensors.laser.scans", static_cast<double>(record_.laser.size()));
    m.Set("sensors.laser.return_fraction", beams ? static_cast<double>(returns) / beams : 0.0);
    m.Set("sensors.laser.wall_hit_fraction", beams ? static_cast<double>(on_walls) / beams : 0.0);
  }
  const auto score_ring = [&](const char* name, const std::vector<msgs::RangeRing>& rings) {
    long readings = 0, echoes = 0;
    for (const auto& ring : rings) {
      for (const auto& reading : ring.readings) {
        ++readings;
        echoes += reading.echo;
      }
    }
    m.Set(std::string("sensors.") + name + ".samples", static_cast<double>(rings.size()));
    m.Set(std::string("sensors.") + name + ".echo_fraction",
          readings ? static_cast<double>(echoes) / readings : 0.0);
  };
  if (config_.sensors.sonar) score_ring("sonar", record_.sonar);
  if (config_.sensors.ir_ring) score_ring("ir_ring", record_.ir_ring);
  if (config_.sensors.ir_scanner) {
    m.Set("sensors.ir_scanner.scans", static_cast<double>(record_.ir_scanner.size()));
  }
  if (config_.sensors.bumpers) {
    long pressed_samples = 0;
    for (const auto& b : record_.bumpers) {
      for (bool pressed : b.pressed) {
        if (pressed) {
          ++pressed_samples;
          break;
        }
      }
    }
    m.Set("sensors.bumpers.contact_samples", static_cast<double>(pressed_samples));
  }
}

}  // namespace plywood::sim
