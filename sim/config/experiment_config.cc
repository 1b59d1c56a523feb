#include "sim/config/experiment_config.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "msgs/shortest_number.h"
#include "perception/geometric_map/range_fusion.h"
#include "perception/lines/what_each_line_needs.h"
#include "perception/logs/regular_file.h"
#include "sim/config/config_archive.h"
#include "sim/config/config_error.h"
#include "sim/config/config_fields.h"
#include "sim/config/folder_behind_links.h"
#include "sim/config/plugin_loader.h"
#include "sim/config/robot_catalog.h"
#include "sim/config/utf8_text.h"
#include "sim/config/yaml_alias_expansion.h"
#include "sim/config/yaml_document.h"
#include "sim/config/yaml_fields.h"
#include "sim/config/yaml_nul_characters.h"
#include "sim/config/yaml_tags.h"
#include "sim/runner/out_of_memory.h"
#include "sim/world/mujoco_handles.h"
#include "sim/world/world_spawns.h"

namespace plywood::sim {
namespace {

// Relative paths resolve against the YAML's folder first, then the data root (so experiments in
// experiments/ can say "worlds/office.xml"). Absolute paths are taken as they are.
std::filesystem::path ResolvePath(const std::string& text, const std::filesystem::path& base_dir,
                                  const YamlFields& fields, const std::string& key) {
  // A folder or a device there is named as such: "no such file: /tmp" misled (bench --world /tmp).
  const std::filesystem::path given(text);
  if (given.is_absolute()) {
    if (!perception::IsRegularFile(given)) {
      fields.Fail(key, perception::WhyNotARegularFile(given) + ": " + text);
    }
    return given.lexically_normal();
  }
  for (const auto& base : {base_dir, DataRoot()}) {
    const std::filesystem::path candidate = (base / given).lexically_normal();
    if (perception::IsRegularFile(candidate)) return candidate;
  }
  for (const auto& base : {base_dir, DataRoot()}) {
    const std::filesystem::path candidate = (base / given).lexically_normal();
    std::error_code refused;
    if (std::filesystem::exists(candidate, refused)) {
      fields.Fail(key, perception::WhyNotARegularFile(candidate) + ": " + candidate.string());
    }
  }
  fields.Fail(key, "no such file: " + text + " (looked in " + base_dir.string() + " and " +
                       DataRoot().string() + ")");
}

// A world may name free spots as <custom><numeric name="spawn_0" data="x_m y_m yaw_deg"/>; the
// first is where a robot starts when the experiment gives no spawn (else the origin).
SpawnPose WorldDefaultSpawn(const std::filesystem::path& world) {
  MjModelPtr model;
  try {
    model = LoadModelFromFile(world.string());
  } catch (const OutOfMemory&) {
    throw;  // not the file's fault: said as such
  } catch (const std::exception&) {
    return {};  // the scene reports the compile error with its full context
  }
  if (const auto problem = WorldSpawnProblem(model.get(), 0)) {
    throw ConfigError(world.string(), "spawn_0", *problem);
  }
  const std::optional<std::array<double, 3>> spawn = WorldSpawn(model.get(), 0);
  if (!spawn) return {};
  const auto [x, y, theta] = *spawn;
  return {x, y, theta};
}

// Short names a user may write for long keys: sensors.laser.sigma_m is the laser's
// range_noise_sigma_m (the name sweeps and other simulators use). The resolved config.yaml always
// spells the long key.
void NormaliseAliases(YAML::Node root, const std::string& source) {
  if (!root.IsMap()) return;
  YAML::Node sensors = root["sensors"];
  if (!sensors.IsMap()) return;
  YAML::Node laser = sensors["laser"];
  if (!laser.IsMap() || !laser["sigma_m"]) return;
  if (laser["range_noise_sigma_m"]) {
    throw ConfigError(source, "sensors.laser.sigma_m",
                      "give either sigma_m or range_noise_sigma_m, not both");
  }
  laser["range_noise_sigma_m"] = laser["sigma_m"];
  laser.remove("sigma_m");
}

// "--set sensors.laser.sigma_m=V" sets the long key, whatever the file spelled.
std::string AliasedAssignment(const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos) return assignment;  // refused by ApplyOverride
  return CanonicalKeyPath(assignment.substr(0, equals)) + assignment.substr(equals);
}

// `plugins: [libmine.so, ...]`: each file resolved like `world` and loaded (plugin_loader.h).
void ReadPlugins(YamlFields& top, const std::filesystem::path& base_dir, ExperimentConfig& config) {
  if (!top.Has("plugins")) return;
  const YAML::Node list = top.Raw("plugins");
  if (!list.IsSequence()) top.Fail("plugins", "expected a list of shared library files");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string key = "plugins[" + std::to_string(i) + "]";
    if (!list[i].IsScalar()) top.Fail(key, "expected the path of a shared library");
    const std::filesystem::path library = ResolvePath(list[i].Scalar(), base_dir, top, key);
    try {
      LoadPlugin(library);
    } catch (const std::invalid_argument& e) {
      top.Fail(key, e.what());
    }
    config.plugins.push_back(library);
  }
}

// A relative controller.weights_file is read from the data root (models/sonar_net_v1.txt), but one
// that names a file beside the experiment is that file, as `world` and `plugins` resolve: a network
// retrained into a copy of the experiment's folder under the shipped name ran the data root's
// network instead (seed001_room_1, 20 s: grid_error 0.0045 where the folder's network gives
// 0.0357), exit 0 (s46). Such a file is named by its absolute path, so config.yaml and a sweep's
// hash of the weights read it wherever they run; a path the data root holds keeps its text.
void ResolveWeightsBesideTheExperiment(const std::filesystem::path& base_dir,
                                       ControllerConfig& controller) {
  if (controller.type != "sonar_explorer" || controller.sonar_explorer.sonar_model != "net") return;
  std::string& text = controller.sonar_explorer.weights_file;
  const std::filesystem::path given(text);
  if (text.empty() || given.is_absolute()) return;
  const std::filesystem::path beside = (base_dir / given).lexically_normal();
  if (!perception::IsRegularFile(beside)) return;
  std::error_code error;
  if (std::filesystem::equivalent(beside, DataRoot() / given, error)) return;
  text = beside.string();
}

constexpr double kMaxSimulationSteps = 1e8;
// Below this a step bound failure is blamed on the timestep rather than the duration.
constexpr double kMinTimestepS = 1e-4;

void RequirePositiveFinite(const char* field, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(std::string(field) + ": must be a finite number > 0, got " +
                                FormatNumber(value));
  }
}

// A deep copy of `node` whose empty mappings and sequences are in flow style (`{}`, `[]`). The
// protocol's section is written as it was read, and yaml-cpp keeps the style it parsed, except
// that a section the file did not have is a fresh mapping in block style, written as `{}` on a
// line of its own, which reads back as flow: config.yaml would not read back to the same text.
YAML::Node WithEmptyContainersInFlowStyle(const YAML::Node& node) {
  YAML::Node copy = YAML::Clone(node);
  std::vector<YAML::Node> pending{copy};
  while (!pending.empty()) {
    YAML::Node current = pending.back();
    pending.pop_back();
    if (!current.IsMap() && !current.IsSequence()) continue;
    if (current.size() == 0) current.SetStyle(YAML::EmitterStyle::Flow);
    for (auto entry : current) pending.push_back(current.IsMap() ? entry.second : entry);
  }
  return copy;
}

// A sensor, the controller or the trajectory sampled faster than the physics step would get one
// sample per step (SensorSchedule skips the rest): the run would hold fewer samples than the file
// asks for, and a rate of 1e300 Hz never left the schedule's catch-up loop. Refused at load; the
// controller's rate only when there is a controller (not idle).
void RequireRatesTheClockCanKeep(const YamlFields& top, const ExperimentConfig& config) {
  const double step_rate_hz = 1.0 / config.physics.timestep_s;
  const auto require = [&](const std::string& field, double rate_hz) {
    // A subnormal rate (1e-320 Hz) has an infinite period: its schedule's times, and every figure
    // computed from its samples, became NaN (metrics.json null, exit 0).
    if (!std::isfinite(1.0 / rate_hz)) {
      top.Fail(field, "its period 1 / rate_hz is not a finite number of seconds, got " +
                          FormatNumber(rate_hz));
    }
    // A period longer than the run samples only at t = 0: the rate means nothing, and the gyro's
    // one read at the end, off its schedule, carried the noise of a mean over the part of its
    // period that had passed, sigma * sqrt(period / elapsed): at 1e-300 Hz an EKF ate_rms_m of
    // 1e142 m in a 2 s run. Runs shorter than 1 s (smoke runs) keep every rate of 1 Hz or more.
    const double longest_period_s = std::max(config.duration_s, 1.0);
    if (rate_hz * longest_period_s < 1.0 - 1e-9) {
      const std::string floor =
          config.duration_s >= 1.0
              ? msgs::SixDigitNumberAtLeast(1.0 / longest_period_s) +
                    " Hz (one period within duration_s = " + FormatNumber(config.duration_s) + " s)"
              : std::string("1 Hz (the floor for runs shorter than 1 s)");
      top.Fail(field, "must be at least " + floor +
                          ": a longer period samples only at t = 0, got " + FormatNumber(rate_hz));
    }
    if (rate_hz <= step_rate_hz * (1.0 + 1e-9)) return;
    // Six digits, rounded down: 1 / 0.0333 s is "30.03 Hz", not 30.030030030030026, and the
    // printed limit is itself accepted.
    top.Fail(field, "must be at most 1 / physics.timestep_s = " +
                        msgs::SixDigitNumberAtMost(step_rate_hz) +
                        " Hz (one sample per physics step), got " + FormatNumber(rate_hz));
  };
  const SensorSuiteConfig& sensors = config.sensors;
  if (sensors.laser) require("sensors.laser.rate_hz", sensors.laser->rate_hz);
  if (sensors.sonar) require("sensors.sonar.rate_hz", sensors.sonar->rate_hz);
  if (sensors.ir_ring) require("sensors.ir_ring.rate_hz", sensors.ir_ring->rate_hz);
  if (sensors.ir_scanner) require("sensors.ir_scanner.rate_hz", sensors.ir_scanner->rate_hz);
  if (sensors.encoders) require("sensors.encoders.rate_hz", sensors.encoders->rate_hz);
  if (sensors.gyro) require("sensors.gyro.rate_hz", sensors.gyro->rate_hz);
  if (sensors.bumpers) require("sensors.bumpers.rate_hz", sensors.bumpers->rate_hz);
  // An idle robot has no controller to schedule: its rate (the default 50 Hz unless written) must
  // not refuse a coarser step, e.g. physics.timestep_s: 0.04 (docs: <= 0.05) with no controller.
  if (config.controller.type != "idle") require("controller.rate_hz", config.controller.rate_hz);
  require("output.trajectory_rate_hz", config.output.trajectory_rate_hz);
}

// The time of the physics step that takes sample k of a `rate_hz` schedule: the first step at or
// after k / rate_hz (sim::SensorSchedule; the controller ticks alike).
double SampleStepTimeS(double k, double rate_hz, double step_s) {
  return std::ceil(k / rate_hz / step_s - 1e-9) * step_s;
}

// A waypoint is passed when the pose the controller sees at one of its ticks is within
// reach_tolerance_m of it; at speed_m_s those poses lie speed * period apart along the path, so
// only a tolerance of at least half that is sure to catch a waypoint driven through. Below it the
// robot misses, stops, turns about and creeps back (at 0.4 m/s and 50 Hz, 1e-3 m drove 4.67 m of
// default's tour in 20 s where 0.1 m drove 5.04 m), and below the step of one tick from rest it
// circled its first waypoint to the end of the run, exit 0 (1e-5 m, s49's left item). The period
// is the longest between two ticks: the schedule fires on the first physics step at or after each
// ideal time.
void RequireWaypointsAControlPeriodCanReach(const YamlFields& top, const ExperimentConfig& config) {
  if (config.controller.type != "waypoints") return;
  const robot::WaypointOptions& waypoints = config.controller.waypoints;
  const double step_s = config.physics.timestep_s;
  const double period_s = SampleStepTimeS(1.0, config.controller.rate_hz, step_s);
  const double per_tick_m = waypoints.speed_m_s * period_s;
  if (waypoints.reach_tolerance_m >= per_tick_m / 2.0) return;
  top.Fail("controller.reach_tolerance_m",
           msgs::ShortestNumber(waypoints.reach_tolerance_m) + " m is less than half the " +
               msgs::ShortestNumber(per_tick_m) +
               " m the robot drives between two control ticks (controller.speed_m_s " +
               msgs::ShortestNumber(waypoints.speed_m_s) + " m/s at controller.rate_hz " +
               msgs::ShortestNumber(config.controller.rate_hz) + " Hz, a tick every " +
               msgs::ShortestNumber(period_s) +
               " s): a waypoint driven through at speed is missed, and the robot turns back or "
               "circles it; give at least " +
               msgs::ShortestNumber(per_tick_m / 2.0) + " m, a higher rate_hz or a lower speed");
}

// A cruise speed at which the robot moves at all, as its own encoders see it: one count of the
// nominal encoder_ticks_per_rev (2 pi wheel_radius_m / ticks of rim) within the whole run.
// speed_m_s: 1e-308 ran and drove 8e-6 m in 20 s, exit 0 (s55's left item): no odometry, no map,
// nothing a figure could be made from. The bound is the run's own length, not a taste for slow
// speeds: a speed that moves the wheels less than one count per control tick still moves them by
// many in a run, and is accepted. The ramp to that speed alike (accel_m_s2: 1e-308 drove the same
// 8e-6 m), and the spot turns' top rate (max_turn_rate_rad_s: 1e-308 drove 1.37 m of default's
// tour, never turning; the sonar explorer's turn_rate_rad_s alike, s57). A heading gain is bounded
// the same way through the largest rate it can ask for, at a bearing error of half a turn
// (heading_gain_per_s: 1e-308 drove default's tour straight on, as the turn rate did, s57).
void RequireMotionTheEncodersCanCount(const YamlFields& top, const ExperimentConfig& config) {
  const ControllerConfig& controller = config.controller;
  const robot::DiffDriveSpec& nominal = config.nominal;
  double speed_m_s = 0.0;
  // The ramp's limit as the key gives it, and the rim's m/s2 per unit of it: the sonar explorer
  // limits the wheels' rad/s2, the others the rim's m/s2.
  double accel = 0.0, rim_m_per_accel_unit = 1.0;
  std::string accel_field = "controller.accel_m_s2", accel_unit = "m/s2";
  // The top yaw rate, where the controller has one: its wheels turn opposite ways at
  // turn_rate x track_m / 2 of rim.
  double turn_rate_rad_s = std::numeric_limits<double>::infinity();
  std::string turn_field = "controller.max_turn_rate_rad_s";
  // The gain that steers towards a bearing (yaw rate per radian of error), where the controller
  // has one that must steer: square_path's may be 0 (its turns are its own; the gain only trims).
  double gain_per_s = std::numeric_limits<double>::infinity();
  std::string gain_field = "controller.heading_gain_per_s";
  if (controller.type == "waypoints") {
    speed_m_s = controller.waypoints.speed_m_s;
    accel = controller.waypoints.accel_m_s2;
    turn_rate_rad_s = controller.waypoints.max_turn_rate_rad_s;
    gain_per_s = controller.waypoints.heading_gain_per_s;
  } else if (controller.type == "square_path") {
    speed_m_s = controller.square_path.speed_m_s;
    accel = controller.square_path.accel_m_s2;
    turn_rate_rad_s = controller.square_path.turn_rate_rad_s;
    turn_field = "controller.turn_rate_rad_s";
  } else if (controller.type == "wall_following") {
    speed_m_s = controller.wall_following.speed_m_s;
    accel = controller.wall_following.accel_m_s2;
    turn_rate_rad_s = controller.wall_following.max_turn_rate_rad_s;
    gain_per_s = controller.wall_following.angle_gain_per_s;
    gain_field = "controller.angle_gain_per_s";
  } else if (controller.type == "sonar_explorer") {
    speed_m_s = controller.sonar_explorer.speed_m_s;
    turn_rate_rad_s = controller.sonar_explorer.turn_rate_rad_s;
    turn_field = "controller.turn_rate_rad_s";
    accel = controller.sonar_explorer.max_wheel_accel_rad_s2;
    rim_m_per_accel_unit = nominal.wheel_radius_m;
    accel_field = "controller.max_wheel_accel_rad_s2";
    accel_unit = "rad/s2";
  } else {
    return;
  }
  const double count_m =
      2.0 * std::numbers::pi * nominal.wheel_radius_m / nominal.encoder_ticks_per_rev;
  const double run_s = config.duration_s;
  const double floor_m_s = count_m / run_s;
  const std::string one_count = "one encoder count (" + msgs::SixDigitNumber(count_m) +
                                " m of rim: robot.nominal.encoder_ticks_per_rev " +
                                std::to_string(nominal.encoder_ticks_per_rev) +
                                ", wheel_radius_m " + msgs::ShortestNumber(nominal.wheel_radius_m) +
                                ") in the whole run (duration_s = " + FormatNumber(run_s) + " s)";
  // Every check below reads "<given> turns the wheels<where> less than <count>: <what never
  // happens> as far as its encoders can measure; give at least <least>". <count> is one count in
  // the whole run for a rate, one count alone for an angle.
  const auto fail_short_of = [&](const std::string& count, bool short_of_count,
                                 const std::string& field, const std::string& given,
                                 const std::string& where, const std::string& never, double least,
                                 const std::string& unit) {
    if (!short_of_count) return;
    top.Fail(field, given + " turns the wheels" + where + " less than " + count + ": " + never +
                        " as far as its encoders can measure; give at least " +
                        msgs::SixDigitNumberAtLeast(least) + " " + unit);
  };
  const auto fail_short_of_one_count = [&](auto&&... args) { fail_short_of(one_count, args...); };
  fail_short_of_one_count(speed_m_s < floor_m_s, "controller.speed_m_s",
                          msgs::ShortestNumber(speed_m_s) + " m/s", "", "the robot never moves",
                          floor_m_s, "m/s");
  const double half_track_m = nominal.track_m / 2.0;
  const std::string at_half_track =
      " (" + msgs::ShortestNumber(half_track_m) + " m from the centre: robot.nominal.track_m / 2)";
  fail_short_of_one_count(turn_rate_rad_s * half_track_m < floor_m_s, turn_field,
                          msgs::ShortestNumber(turn_rate_rad_s) + " rad/s", at_half_track,
                          controller.type == "sonar_explorer"
                              ? "its spot turns (to face each target, away from a wall ahead) "
                                "never turn the robot"
                              : "the robot never turns",
                          floor_m_s / half_track_m, "rad/s");
  // The largest bearing error is half a turn: gain x pi is the fastest the gain can steer.
  fail_short_of_one_count(gain_per_s * std::numbers::pi * half_track_m < floor_m_s, gain_field,
                          msgs::ShortestNumber(gain_per_s) +
                              " /s asks for at most gain x pi rad of heading error = " +
                              msgs::SixDigitNumber(gain_per_s * std::numbers::pi) + " rad/s, which",
                          at_half_track, "the gain never steers the robot",
                          floor_m_s / (std::numbers::pi * half_track_m), "/s");
  // The wall follower's distance term asks for a heading towards (or away from) the wall of gain x
  // the distance error, capped at max_approach_angle_rad, and the angle gain turns the robot to
  // that heading and holds it. The error is at most the larger of distance_m (at the wall) and
  // max_wall_range_m - distance_m (farther, the wall is not followed): below one count of turn
  // at that error the term never steers the robot towards its distance as far as its encoders can
  // measure. An angle, not a rate: the run's length does not enter. distance_gain_rad_per_m 1e-308
  // held seed003_generated 0.87 m from the nearest wall where 1.5 holds 0.64 m (s57's left item).
  if (controller.type == "wall_following") {
    const robot::WallFollowingOptions& wall = controller.wall_following;
    const double error_m = std::max(wall.distance_m, wall.max_wall_range_m - wall.distance_m);
    const double heading_rad =
        std::min(wall.distance_gain_rad_per_m * error_m, wall.max_approach_angle_rad);
    fail_short_of("one encoder count (" + msgs::SixDigitNumber(count_m) + " m of rim)",
                  heading_rad * half_track_m < count_m, "controller.distance_gain_rad_per_m",
                  msgs::ShortestNumber(wall.distance_gain_rad_per_m) +
                      " rad/m asks for a heading towards the wall of at most gain x " +
                      msgs::ShortestNumber(error_m) +
                      " m (the largest distance error: the larger of distance_m and "
                      "max_wall_range_m - distance_m) = " +
                      msgs::SixDigitNumber(heading_rad) + " rad, which",
                  at_half_track, "the distance term never steers the robot towards its distance",
                  count_m / (half_track_m * error_m), "rad/m");
  }
  // From rest at accel a, the rim covers a t^2 / 2 by t: less than one count by the run's end.
  fail_short_of_one_count(
      !(0.5 * accel * rim_m_per_accel_unit * run_s * run_s >= count_m), accel_field,
      msgs::ShortestNumber(accel) + " " + accel_unit + " from rest", "", "the robot never moves",
      2.0 * count_m / (run_s * run_s) / rim_m_per_accel_unit, accel_unit);
}

// A gyro step coarser than the turns the robot can make: with quantisation_rad_s at least twice
// the fastest yaw rate its wheels allow (2 max_wheel_speed_rad_s wheel_radius_m / track_m), every
// rate it can turn at rounds to the same step (0 without bias), and the gyro-based estimators
// integrate nothing of the turns: ekf_calibration at 15 and 35 rad/s gave the same -177 deg
// heading error for the gyro estimator (19 deg with no quantisation), exit 0 (s56).
void RequireAGyroStepFinerThanTheTurns(const YamlFields& top, const ExperimentConfig& config) {
  if (!config.sensors.gyro || config.sensors.gyro->quantisation_rad_s == 0.0) return;
  const robot::DiffDriveSpec& nominal = config.nominal;
  const double fastest_rad_s =
      2.0 * nominal.max_wheel_speed_rad_s * nominal.wheel_radius_m / nominal.track_m;
  const double step_rad_s = config.sensors.gyro->quantisation_rad_s;
  if (step_rad_s < 2.0 * fastest_rad_s) return;
  top.Fail("sensors.gyro.quantisation_rad_s",
           msgs::ShortestNumber(step_rad_s) + " rad/s is at least twice the fastest turn robot '" +
               config.robot + "' can make (" + msgs::SixDigitNumber(fastest_rad_s) +
               " rad/s: 2 x max_wheel_speed_rad_s " +
               msgs::ShortestNumber(nominal.max_wheel_speed_rad_s) + " x wheel_radius_m " +
               msgs::ShortestNumber(nominal.wheel_radius_m) + " / track_m " +
               msgs::ShortestNumber(nominal.track_m) +
               "): every rate it can turn at rounds to one step, and the gyro sees no turn; give "
               "less than " +
               msgs::SixDigitNumberAtMost(2.0 * fastest_rad_s) + " rad/s");
}

// Seed 003's map fuses each IR scan with the sonar ring nearest in time, if one is at most
// geometric_map.max_sonar_age_s away (eval/geometric_map/geometric_map_run.cc). With rates whose
// samples do not meet (the defaults, IR 2 Hz and sonar 3.125 Hz, against 0.1 s) some scans have no
// ring and were mapped from the IR alone under the name 'fused', exit 0: seed003_ir_panels gave
// 485 sonar points where rings at the scanner's rate give 663, precision 0.69 instead of 0.64,
// and at 0.5 Hz neither IR-invisible panel was mapped. The samples are found as SensorSchedule
// takes them: the first physics step at or after k / rate_hz.
void RequireASonarRingForEveryIrScan(const YamlFields& top, const ExperimentConfig& config) {
  const GeometricMapConfig& map = config.geometric_map;
  if (!map.given || map.options.fusion.source == perception::RangeSource::kIrOnly ||
      !config.sensors.sonar || !config.sensors.ir_scanner) {
    return;
  }
  const double step_s = config.physics.timestep_s;
  const double ir_hz = config.sensors.ir_scanner->rate_hz;
  const double sonar_hz = config.sensors.sonar->rate_hz;
  // The pattern repeats with the rates' common period: the first 1e5 scans show every phase of
  // any two rates a file would give.
  const double scans = std::min(std::floor(config.duration_s * ir_hz + 1e-9) + 1.0, 1e5);
  double missing = 0.0, first_missing_s = 0.0, farthest_s = 0.0;
  for (double k = 0.0; k < scans; ++k) {
    const double t = SampleStepTimeS(k, ir_hz, step_s);
    const double j = std::round(t * sonar_hz);
    double nearest_s = std::numeric_limits<double>::infinity();
    for (const double ring : {j - 1.0, j, j + 1.0}) {
      if (ring < 0.0) continue;
      const double ring_s = SampleStepTimeS(ring, sonar_hz, step_s);
      if (ring_s > config.duration_s + 1e-9) continue;
      nearest_s = std::min(nearest_s, std::abs(ring_s - t));
    }
    farthest_s = std::max(farthest_s, nearest_s);
    if (nearest_s <= map.max_sonar_age_s + 1e-9) continue;
    if (missing == 0.0) first_missing_s = t;
    ++missing;
  }
  if (missing == 0.0) return;
  top.Fail("geometric_map.max_sonar_age_s",
           msgs::ShortestNumber(map.max_sonar_age_s) + " s, but with sensors.sonar.rate_hz " +
               msgs::ShortestNumber(sonar_hz) + " and sensors.ir_scanner.rate_hz " +
               msgs::ShortestNumber(ir_hz) + ", " + msgs::ShortestNumber(missing) + " of " +
               (scans < 1e5 ? "the " : "the first ") + msgs::ShortestNumber(scans) +
               " IR scans (the first at t = " + msgs::ShortestNumber(first_missing_s) +
               " s) have no sonar ring that close, and the map would take them without the "
               "sonar: give the sonar the scanner's rate (or a whole multiple of it), or "
               "max_sonar_age_s at least " +
               msgs::ShortestNumber(std::round(farthest_s * 1e9) / 1e9) + " s");
}

// The simulated robot is built from its model's wheels, deviated by robot.deviation
// (ExperimentRunner); robot.nominal is what its software believes. A nominal wheel radius or track
// other than the model's was no robot the docs describe (E_d keeps the mean diameter nominal,
// E_b = b_actual / b_nominal) and an odometry error no ratio recorded: a 3 s wheel script with
// robot.nominal.wheel_radius_m 0.5 on the P3-DX's 0.0975 m wheels drove the same 0.145 m while the
// encoder odometry read 415 % drift, config.yaml saying deviation 1, 1, exit 0 (s50). The catalog's
// nominal is the model's (0.0975 / 0.33 m, 0.0762 / 0.32 m: models/*.xml's wheel bodies).
void RequireTheModelsWheelGeometry(const YamlFields& top, const ExperimentConfig& config) {
  const robot::DiffDriveSpec& model = FindRobot(config.robot).nominal;
  const std::pair<const char*, std::pair<double, double>> lengths[] = {
      {"wheel_radius_m", {config.nominal.wheel_radius_m, model.wheel_radius_m}},
      {"track_m", {config.nominal.track_m, model.track_m}}};
  for (const auto& [field, values] : lengths) {
    const auto [given, built] = values;
    if (std::abs(given - built) <= 1e-9 * built) continue;
    top.Fail(std::string("robot.nominal.") + field,
             msgs::ShortestNumber(given) + " m, but the '" + config.robot +
                 "' is simulated with its model's " + msgs::ShortestNumber(built) +
                 " m (robot.deviation's ratios are taken from it), so the odometry and "
                 "controllers would be off by a factor " +
                 msgs::ShortestNumber(given / built) +
                 " that no figure records: give a build error with robot.deviation "
                 "(wheel_diameter_ratio, track_ratio) and leave the nominal geometry out");
  }
}

// An estimator's counter_modulus unwraps each encoder increment the short way round, which is
// right only while a wheel turns at most half the modulus between two samples: with a counter of
// 256 ticks (8 bits) read at 10 Hz, square_hall's 0.2 m/s drive wrapped every interval and the
// encoder estimate's ate_rms_m was 2.26 m instead of 0.050, exit 0 (s45). So the modulus must hold
// the most a wheel can turn in an interval: max_wheel_speed_rad_s over one period of the encoders
// and one physics step (a sample lands on a step), plus a tick of quantisation.
void RequireCountersThatHoldAnInterval(const YamlFields& top, const ExperimentConfig& config) {
  if (!config.sensors.encoders) return;
  const double interval_s = 1.0 / config.sensors.encoders->rate_hz + config.physics.timestep_s;
  const double ticks_per_rev = config.sensors.encoders->ticks_per_rev;
  const double most_ticks = std::ceil(config.nominal.max_wheel_speed_rad_s * interval_s *
                                      ticks_per_rev / (2.0 * std::numbers::pi)) +
                            1.0;
  const std::pair<const char*, const robot::IncrementOptions*> estimators[] = {
      {"encoder", &config.odometry.encoder.increments},
      {"gyro", &config.odometry.gyro.increments},
      {"fused", &config.odometry.fused.increments},
      {"weighted", &config.odometry.weighted.increments},
      {"ekf", &config.odometry.ekf.increments}};
  for (const auto& [name, increments] : estimators) {
    const std::uint64_t modulus = increments->counter_modulus;
    if (modulus == 0 || static_cast<double>(modulus / 2) >= most_ticks) continue;
    if (std::find(config.odometry.enabled.begin(), config.odometry.enabled.end(), name) ==
        config.odometry.enabled.end()) {
      continue;
    }
    top.Fail(
        std::string("odometry.") + name + ".counter_modulus",
        "a counter of " + std::to_string(modulus) +
            " ticks wraps within one encoder interval: at robot.nominal.max_wheel_speed_rad_s (" +
            FormatNumber(config.nominal.max_wheel_speed_rad_s) + " rad/s) a wheel turns up to " +
            FormatNumber(most_ticks) + " ticks (of " + FormatNumber(ticks_per_rev) +
            " per revolution) between two samples at sensors.encoders.rate_hz " +
            FormatNumber(config.sensors.encoders->rate_hz) +
            ", and an increment is unwrapped the short way round, so at most half the "
            "counter: give at least " +
            FormatNumber(2.0 * most_ticks) + ", or 0 (no wrap)");
  }
}

// The odometry and the controllers turn ticks into wheel angles with robot.nominal's count, not
// the sensor's: an encoder of another count (the docs' 800 on a P3-DX, whose nominal is 39000)
// scaled every encoder figure by the ratio, exit 0 (s49: square_hall's drift 0.71 % -> 72.5 %).
// The sensor's count defaults to the nominal's, so robot.nominal.encoder_ticks_per_rev sets both.
void RequireEncodersTheOdometryCounts(const YamlFields& top, const ExperimentConfig& config) {
  if (!config.sensors.encoders) return;
  const int sensor = config.sensors.encoders->ticks_per_rev;
  const int nominal = config.nominal.encoder_ticks_per_rev;
  if (sensor == nominal) return;
  top.Fail(
      "sensors.encoders.ticks_per_rev",
      std::to_string(sensor) + " ticks per revolution, but the odometry and controllers " +
          "convert ticks with robot.nominal.encoder_ticks_per_rev = " + std::to_string(nominal) +
          " (robot '" + config.robot + "'), so every encoder figure would be off by a factor " +
          msgs::ShortestNumber(static_cast<double>(nominal) / sensor) +
          ": set robot.nominal.encoder_ticks_per_rev instead (the sensor takes its count)");
}

// A line is drawn from the points of one laser scan: a count above the laser's beams, or a minimum
// length above twice its range (no two returns lie farther apart), finds no line in any scan; a
// run gave recall 0 and precision 1 of nothing, exit 0 (s60: `lines.split_and_merge.min_points:
// 1000` with the 361-beam laser, `min_length_m: 1e300`). The replay's check of the same counts
// (s58) against a log's fullest scan. Single runs and seed 000's rig, whose scan is the pair of
// its two back-to-back lasers at one site (s63: 1000 points ran there, recall 0); seed 004's
// RANSAC fits a run's cloud.
void RequireLinesOneScanCanHold(const YamlFields& top, const ExperimentConfig& config) {
  if (!config.lines.given || !config.sensors.laser) return;
  const bool rig = config.protocol == "seed000_rooms";
  if (config.protocol != "single" && !rig) return;
  const LaserOptions& laser = *config.sensors.laser;
  const int beams = laser.BeamCount();
  const int points = rig ? 2 * beams : beams;
  const std::string of_a_scan =
      rig ? " points of the rig's scan pair (two back-to-back lasers of " + std::to_string(beams) +
                " beams each: sensors.laser fov_deg / resolution_deg + 1): a line is drawn from "
                "one pair's points"
          : " beams of a scan (sensors.laser fov_deg / resolution_deg + 1): a line is drawn from "
            "one scan's points";
  for (const std::string& extractor : config.lines.extractors) {
    const std::string section = "lines." + extractor + ".";
    for (const auto& [key, count] :
         perception::PointsEachLineNeeds(config.lines.options, extractor)) {
      if (count <= points) continue;
      top.Fail(section + key,
               std::to_string(count) + " is more than the " + std::to_string(points) + of_a_scan +
                   ", so none could be found; give at most " + std::to_string(points));
    }
    const double shortest_m = perception::ShortestLineKeptM(config.lines.options, extractor);
    if (shortest_m <= 2.0 * laser.range_max_m) continue;
    top.Fail(section + "min_length_m",
             msgs::ShortestNumber(shortest_m) +
                 " m is more than twice sensors.laser.range_max_m (" +
                 msgs::ShortestNumber(laser.range_max_m) +
                 " m): no two returns of a scan lie farther apart, so no line could be found");
  }
}

// Seed 003's map draws each segment from one IR scan's points, and scores only surfaces hit by
// segmentation.min_line_points beams in one scan: a count above the scanner's beams mapped nothing
// and, after the whole run, was refused as "geometric_map: no wall surface was hit by 10000
// beams", naming the section, not the key (s62).
void RequireMapLinesOneScanCanHold(const YamlFields& top, const ExperimentConfig& config) {
  if (!config.geometric_map.given || !config.sensors.ir_scanner) return;
  const int beams = config.sensors.ir_scanner->BeamCount();
  const int count = config.geometric_map.options.segmentation.min_line_points;
  if (count <= beams) return;
  top.Fail("geometric_map.segmentation.min_line_points",
           std::to_string(count) + " is more than the " + std::to_string(beams) +
               " beams of an IR scan (sensors.ir_scanner fov_deg / resolution_deg): a segment is "
               "drawn from one scan's points, so none could be found; give at most " +
               std::to_string(beams));
}

// A single run applies odometry.calibration only to the estimators' geometry: with none running
// a calibration changed no figure, exit 0 (s60; `odometry: {calibration: {track_ratio: 1.01}}`
// ran with no odometry in metrics.json). The identity is what config.yaml records for a run
// without estimators, so it stays accepted; the UMBmark and gain protocols drive with it
// themselves.
void RequireAnEstimatorForTheCalibration(const YamlFields& top, const ExperimentConfig& config) {
  const robot::OdometryCalibration& calibration = config.odometry.calibration;
  if (config.protocol != "single" || !config.odometry.enabled.empty()) return;
  if (calibration.wheel_diameter_ratio == 1.0 && calibration.track_ratio == 1.0) return;
  top.Fail("odometry.calibration",
           "wheel_diameter_ratio " + msgs::ShortestNumber(calibration.wheel_diameter_ratio) +
               " and track_ratio " + msgs::ShortestNumber(calibration.track_ratio) +
               " calibrate the odometry estimators, but none runs (" +
               (config.sensors.encoders ? "odometry names none" : "sensors.encoders is off") +
               "), so they would change no figure: enable one, e.g. odometry.encoder: {} with "
               "sensors.encoders");
}

}  // namespace

void SpawnPose::Validate() const {
  if (!(std::abs(theta_deg) <= kMaxSpawnTurnDeg)) {
    throw std::invalid_argument(
        "theta_deg: must be in [-360, 360] deg (one turn either way holds every heading), got " +
        FormatNumber(theta_deg));
  }
}

void PhysicsOptions::Validate() const {
  RequirePositiveFinite("timestep_s", timestep_s);
  if (timestep_s > 0.05) {
    throw std::invalid_argument("timestep_s: must be <= 0.05 s for stable wheel contact, got " +
                                FormatNumber(timestep_s));
  }
}

void OutputOptions::Validate() const {
  RequirePositiveFinite("trajectory_rate_hz", trajectory_rate_hz);
  if (snapshot_size_px < 64 || snapshot_size_px > 8192) {
    throw std::invalid_argument("snapshot_size_px: must be in 64..8192, got " +
                                std::to_string(snapshot_size_px));
  }
}

ExperimentConfig ParseExperimentConfig(const std::string& yaml_text, const std::string& source,
                                       const std::filesystem::path& base_dir,
                                       const std::vector<std::string>& overrides) {
  YAML::Node root = LoadOneYamlDocument(yaml_text, source);
  if (!root.IsDefined() || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  RejectAliasExpansion(root, source);
  RejectDuplicateKeys(root, source);
  // An override (or the sigma_m alias below) changes one place only, even where the file wrote an
  // alias of an anchored value.
  root = CopyWithoutSharedNodes(root);
  NormaliseAliases(root, source);
  // Read before the overrides: whether the file itself wrote the odometry section (see below).
  const bool file_gives_odometry = root.IsMap() && std::as_const(root)["odometry"].IsDefined();
  std::vector<std::string> set_keys;
  for (const std::string& assignment : overrides) {
    if (!root.IsMap()) break;  // reported below as "expected a mapping"
    const std::string aliased = AliasedAssignment(assignment);
    ApplyOverride(root, aliased, "--set " + assignment);
    // A whole mapping given by --set (`sensors.laser={sigma_m: 0.02}`) reads as the file would.
    NormaliseAliases(root, "--set " + assignment);
    set_keys.push_back(aliased.substr(0, aliased.find('=')));
  }
  RejectNonStandardTags(root, source);  // after the overrides: a --set value may carry one too
  RejectNulCharacters(root, source);

  ExperimentConfig config;
  config.source_file = source;
  config.set_keys = set_keys;
  YamlFields top(root, source, "");
  ReadPlugins(top, base_dir, config);
  config.name = std::filesystem::path(source).stem().string();
  top.Get("name", &config.name);
  // The name becomes a folder under runs/: it must stay one folder there.
  if (config.name.empty() || config.name.find_first_of("/\\") != std::string::npos ||
      config.name == "." || config.name.find("..") != std::string::npos) {
    top.Fail("name",
             "must be a plain folder name (no '/', '\\' or '..'), got '" + config.name + "'");
  }
  // config.yaml records the name as YAML text, which must be UTF-8 (a name of Latin-1 bytes, or
  // the stem of a file so named, wrote a config.yaml other YAML readers refuse).
  if (!IsUtf8(config.name)) {
    top.Fail("name",
             "'" + EscapeHighBytes(config.name) + "' is not UTF-8 text (config.yaml records it): " +
                 (top.Has("name") ? "write it in UTF-8" : "rename the file or give a name:"));
  }
  top.Get("seed", &config.seed);
  top.Get("protocol", &config.protocol);
  if (config.protocol != "single") {
    if (!top.Has(config.protocol))
      config.protocol_options = YAML::Node(YAML::NodeType::Map);
    else
      config.protocol_options = YAML::Clone(top.Raw(config.protocol));
  }
  top.Get("duration_s", &config.duration_s);
  if (!std::isfinite(config.duration_s) || config.duration_s <= 0.0) {
    top.Fail("duration_s", "must be a finite number > 0, got " + FormatNumber(config.duration_s));
  }
  if (!top.Has("world")) top.Fail("world", "missing: give the world's MJCF file");
  top.Get("world", &config.world);
  // metrics.json records the world file's name (run.world) as JSON text: bytes that are not UTF-8
  // (a file named in Latin-1) were written as U+FFFD, a name no file has.
  if (!IsUtf8(config.world)) {
    top.Fail("world", "the path '" + EscapeHighBytes(config.world) +
                          "' is not UTF-8 text (metrics.json records it): rename the file");
  }
  config.world_path = ResolvePath(config.world, base_dir, top, "world");

  YamlFields robot = top.Child("robot");
  robot.Get("model", &config.robot);
  try {
    config.nominal = FindRobot(config.robot).nominal;
  } catch (const std::invalid_argument& e) {
    robot.Fail("model", e.what());
  }
  if (robot.Has("spawn")) {
    YamlFields spawn = robot.Child("spawn");
    // The world's spawn_0 is the default of the whole pose, so a spawn given in part takes the rest
    // from it: `--set robot.spawn.theta_deg=90` on an experiment without a spawn moved the robot
    // from seed001_room_2's spawn_0 (-0.8, -0.5) to the origin without a word (s46).
    if (!spawn.Has("x_m") || !spawn.Has("y_m") || !spawn.Has("theta_deg")) {
      config.spawn = WorldDefaultSpawn(config.world_path);
    }
    ReadOptions(spawn, config.spawn);
  } else {
    config.spawn = WorldDefaultSpawn(config.world_path);
  }
  ReadOptions(robot.Child("nominal"), config.nominal);
  ReadOptions(robot.Child("deviation"), config.deviation);
  robot.Finish();
  RequireTheModelsWheelGeometry(top, config);

  ReadOptions(top.Child("physics"), config.physics);
  // A run shorter than one step simulates nothing, and would report its figures (an ATE of 0 m)
  // as if it had run.
  if (config.duration_s < config.physics.timestep_s) {
    top.Fail("duration_s", "must be at least one physics step (physics.timestep_s = " +
                               FormatNumber(config.physics.timestep_s) + " s), got " +
                               FormatNumber(config.duration_s));
  }
  // The work is bounded up front: a run of more steps would take days (and beyond 9.2e18 the step
  // count no longer fits a long).
  if (config.duration_s / config.physics.timestep_s > kMaxSimulationSteps) {
    const bool step_is_odd = config.physics.timestep_s < kMinTimestepS;
    top.Fail(step_is_odd ? "physics.timestep_s" : "duration_s",
             "duration_s / physics.timestep_s = " +
                 // ShortestNumber: a quotient past DBL_MAX (duration_s 1e308) reads "inf"
                 // steps; FormatNumber, made for JSON, wrote "null steps".
                 msgs::ShortestNumber(std::ceil(config.duration_s / config.physics.timestep_s)) +
                 " steps, more than the limit of " + FormatNumber(kMaxSimulationSteps));
  }
  ReadControllerConfig(top.Child("controller"), config.nominal, config.controller);
  ResolveWeightsBesideTheExperiment(base_dir, config.controller);
  ReadSensorSuiteConfig(top.Child("sensors"), config.nominal, config.sensors);
  if (top.Has("odometry")) {
    ReadOdometryConfig(top.Child("odometry"), config.nominal, config.odometry);
    // An override of one key under an odometry section the file does not have changes that key
    // only: the section starts from its default, so `--set odometry.ekf.gyro_gain=1` (a profile
    // line, a sweep axis) adds the EKF beside the encoder estimator instead of dropping it, and
    // `--set odometry.calibration.track_ratio=1.01` calibrates it instead of leaving no estimator
    // (s60). `--set 'odometry={ekf: {}}'` gives the whole section, as the file would.
    const bool whole_section_set =
        std::find(set_keys.begin(), set_keys.end(), "odometry") != set_keys.end();
    const std::vector<std::string>& enabled = config.odometry.enabled;
    if (!file_gives_odometry && !whole_section_set && config.sensors.encoders &&
        std::find(enabled.begin(), enabled.end(), "encoder") == enabled.end()) {
      // The first column, as KnownEstimators() orders them.
      config.odometry.enabled.insert(config.odometry.enabled.begin(), "encoder");
    }
  } else if (config.sensors.encoders) {
    config.odometry.enabled = {"encoder"};
  }
  RequireAnEstimatorForTheCalibration(top, config);
  if (top.Has("lines")) ReadLinesConfig(top.Child("lines"), config.lines);
  if (top.Has("geometric_map")) {
    ReadGeometricMapConfig(top.Child("geometric_map"), config.geometric_map);
  }
  ReadOptions(top.Child("output"), config.output);
  RequireRatesTheClockCanKeep(top, config);
  RequireMotionTheEncodersCanCount(top, config);
  RequireAGyroStepFinerThanTheTurns(top, config);
  RequireWaypointsAControlPeriodCanReach(top, config);
  RequireASonarRingForEveryIrScan(top, config);
  RequireCountersThatHoldAnInterval(top, config);
  RequireLinesOneScanCanHold(top, config);
  RequireMapLinesOneScanCanHold(top, config);
  RequireEncodersTheOdometryCounts(top, config);
  top.Finish();
  return config;
}

ExperimentConfig LoadExperimentConfig(const std::filesystem::path& yaml_path,
                                      const std::vector<std::string>& overrides) {
  std::error_code error;
  if (!std::filesystem::exists(yaml_path, error)) {
    throw ConfigError(yaml_path.string(), "",
                      perception::WhyNotARegularFile(yaml_path, "experiment file"));
  }
  if (!std::filesystem::is_regular_file(yaml_path, error)) {
    throw ConfigError(yaml_path.string(), "", "not a regular file (a folder?)");
  }
  std::ifstream in(yaml_path, std::ios::binary);
  if (!in) {
    throw ConfigError(yaml_path.string(), "",
                      std::string("cannot read the experiment file: ") + std::strerror(errno));
  }
  std::stringstream text;
  text << in.rdbuf();
  return ParseExperimentConfig(text.str(), yaml_path.string(), FolderBehindLinks(yaml_path),
                               overrides);
}

void RequireOdometryEstimator(const ExperimentConfig& config, const std::string& field,
                              const std::string& what_uses_the_pose) {
  if (!config.odometry.enabled.empty()) return;
  throw ConfigError(
      config.source_file, field,
      what_uses_the_pose + " at the odometry pose, but the run has no odometry estimator (" +
          (config.odometry.given ? "odometry: names none" : "sensors.encoders is off") +
          "), so it would be the true pose: enable one, e.g. odometry: {encoder: {}} "
          "with sensors.encoders");
}

std::string CanonicalKeyPath(const std::string& key_path) {
  if (key_path == "sensors.laser.sigma_m") return "sensors.laser.range_noise_sigma_m";
  return key_path;
}

std::string ExperimentConfigToYaml(const ExperimentConfig& const_config) {
  ExperimentConfig config = const_config;  // the archives take mutable references
  YAML::Node root(YAML::NodeType::Map);
  root["name"] = config.name;
  root["seed"] = config.seed;
  if (!config.plugins.empty()) {
    YAML::Node plugins(YAML::NodeType::Sequence);
    for (const auto& library : config.plugins) plugins.push_back(library.string());
    root["plugins"] = plugins;
  }
  if (config.protocol != "single") {
    root["protocol"] = config.protocol;
    root[config.protocol] = WithEmptyContainersInFlowStyle(config.protocol_options);
  }
  root["duration_s"] = FormatNumber(config.duration_s);
  root["world"] = config.world_path.string();
  YAML::Node robot(YAML::NodeType::Map);
  robot["model"] = config.robot;
  robot["spawn"] = WriteOptions(config.spawn);
  robot["nominal"] = WriteOptions(config.nominal);
  robot["deviation"] = WriteOptions(config.deviation);
  root["robot"] = robot;
  root["physics"] = WriteOptions(config.physics);
  root["controller"] = WriteControllerConfig(config.controller);
  root["sensors"] = WriteSensorSuiteConfig(config.sensors);
  root["odometry"] = WriteOdometryConfig(config.odometry);
  if (config.lines.given) root["lines"] = WriteLinesConfig(config.lines);
  if (config.geometric_map.given) {
    root["geometric_map"] = WriteGeometricMapConfig(config.geometric_map);
  }
  root["output"] = WriteOptions(config.output);
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

}  // namespace plywood::sim
