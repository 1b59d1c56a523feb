#include "viewer/run_replay.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <thread>

#include "eval/score/csv_table.h"
#include "eval/score/run_directory.h"
#include "eval/score/run_world_check.h"
#include "msgs/angle_units.h"
#include "perception/logs/carmen_log.h"
#include "render/geom_footprint.h"
#include "render/overlay.h"
#include "sim/config/config_error.h"
#include "sim/config/robot_catalog.h"
#include "sim/runner/format_number.h"
#include "sim/runner/run_directory.h"
#include "sim/sensors/sonar_sensor.h"
#include "viewer/run_content.h"
#include "viewer/run_maps_file.h"
#include "viewer/scene_overlays.h"

#if PLYWOOD_HAS_IMGUI
#include <imgui.h>
#endif

namespace plywood::viewer {
namespace {

// The index of the last element whose time is at or before t_s (0 when none is).
template <typename Vector, typename TimeOf>
std::size_t LastAtOrBefore(const Vector& items, double t_s, TimeOf time_of) {
  const auto it = std::upper_bound(items.begin(), items.end(), t_s,
                                   [&](double t, const auto& item) { return t < time_of(item); });
  return it == items.begin() ? 0 : static_cast<std::size_t>(it - items.begin() - 1);
}

// sonar.csv as the run writes it (sim/runner/run_writer.cc): time_s, then one column per
// transducer of the ring, each empty (no echo) or a range the sonar can report. Anything else was
// drawn without a word: a range of -5 as a beam pointing backwards, 1e300 as one across the
// screen, a 17th column as a transducer at the robot's centre (s63).
std::vector<msgs::RangeRing> ReadSonarCsv(const std::filesystem::path& path,
                                          const sim::SonarOptions& sonar) {
  const eval::CsvTable table = eval::ReadCsv(path, {.header = true, .rows_required = false});
  if (table.header.empty() || table.header.front() != "time_s") {
    throw sim::ConfigError(path.string(), "time_s", "expected a header starting with time_s");
  }
  const std::size_t transducers = sim::SonarSensor::DefaultSiteNames().size();
  if (!table.rows.empty()) {
    bool named = table.header.size() == 1 + transducers;
    for (std::size_t c = 1; named && c < table.header.size(); ++c) {
      named = table.header[c] == "range_" + std::to_string(c - 1) + "_m";
    }
    if (!named) {
      throw sim::ConfigError(path.string(), "header",
                             "expected time_s, then range_0_m .. range_" +
                                 std::to_string(transducers - 1) + "_m (one column per sonar of " +
                                 "the ring), got " + std::to_string(table.header.size()) +
                                 " columns");
    }
  }
  std::vector<msgs::RangeRing> rings;
  for (const eval::CsvRow& row : table.rows) {
    msgs::RangeRing ring;
    ring.time_s = table.Number(row, 0, "time_s");
    ring.range_max_m = sonar.range_max_m;
    for (std::size_t c = 1; c < row.fields.size(); ++c) {
      msgs::RangeReading reading;
      reading.echo = !row.fields[c].empty();
      if (reading.echo) {
        reading.range_m = table.Number(row, c, table.header[c]);
        if (!(reading.range_m >= sonar.range_min_m && reading.range_m <= sonar.range_max_m)) {
          table.Fail(row, table.header[c],
                     "must be in [" + sim::FormatNumber(sonar.range_min_m) + ", " +
                         sim::FormatNumber(sonar.range_max_m) +
                         "] m (config.yaml's sensors.sonar range_min_m and range_max_m), got " +
                         sim::FormatNumber(reading.range_m));
        }
      }
      ring.readings.push_back(reading);
    }
    if (!rings.empty() && ring.time_s < rings.back().time_s) {
      table.Fail(row, "time_s", "times must not decrease");
    }
    rings.push_back(std::move(ring));
  }
  return rings;
}

}  // namespace

double RunReplayData::start_s() const { return trajectories.front().poses.front().time_s; }
double RunReplayData::end_s() const { return trajectories.front().poses.back().time_s; }

RunReplayData LoadRunReplay(const std::filesystem::path& run_dir) {
  sim::RequireFinishedRun(run_dir);
  RunReplayData data;
  data.config = eval::LoadRunConfig(run_dir, "plywood view");
  data.config_yaml = run_dir / "config.yaml";
  data.walls = eval::ReadWallsCsv(
      eval::RunFile(run_dir, "walls.csv", "the run's walls, to check its world is unchanged"));
  const std::filesystem::path trajectory =
      eval::RunFile(run_dir, "trajectory.csv", "the run's trajectory");
  data.trajectories = eval::ReadTrajectoryFile(trajectory, "truth");
  if (data.trajectories.empty() || data.trajectories.front().name != "truth") {
    throw sim::ConfigError(trajectory.string(), "truth_x_m",
                           "the ground truth columns are missing");
  }
  if (const std::filesystem::path log = run_dir / "laser.log"; std::filesystem::exists(log)) {
    for (perception::CarmenLaserRecord& r : perception::ReadCarmenLog(log).lasers) {
      // The frame at t shows the last scan at or before t, found by bisection: scans out of time
      // order showed another moment's scan, at its own pose, without a word (s63). A run writes
      // them in order, as sonar.csv's rings.
      if (!data.laser.empty() && r.scan.time_s < data.laser.back().time_s) {
        throw sim::ConfigError(log.string() + ":" + std::to_string(r.line_number), "ipc_timestamp",
                               sim::FormatNumber(r.scan.time_s) +
                                   " s comes before the previous scan's " +
                                   sim::FormatNumber(data.laser.back().time_s) +
                                   " s: a run logs its scans in time order");
      }
      data.laser.push_back({r.scan.time_s, r.X_WL, std::move(r.scan)});
    }
  }
  if (std::filesystem::exists(run_dir / "sonar.csv") && data.config.sensors.sonar) {
    data.sonar = ReadSonarCsv(run_dir / "sonar.csv", *data.config.sensors.sonar);
  }
  if (std::filesystem::exists(run_dir / "cognitive_map.json")) {
    data.map = ReadCognitiveMapFile(run_dir / "cognitive_map.json");
  }
  if (std::filesystem::exists(run_dir / "geometric_map.json")) {
    data.geometric_map = ReadGeometricMapFile(run_dir / "geometric_map.json");
  }
  return data;
}

msgs::Pose2D PoseAt(const eval::NamedTrajectory& trajectory, double t_s) {
  const auto& poses = trajectory.poses;
  if (t_s <= poses.front().time_s) return poses.front().pose;
  if (t_s >= poses.back().time_s) return poses.back().pose;
  const std::size_t i = LastAtOrBefore(poses, t_s, [](const auto& p) { return p.time_s; });
  const perception::TimedPose& a = poses[i];
  const perception::TimedPose& b = poses[i + 1];
  if (a.time_s == t_s) return a.pose;
  const double f = (t_s - a.time_s) / (b.time_s - a.time_s);
  const double turn = std::remainder(b.pose.theta_rad - a.pose.theta_rad, 2.0 * std::numbers::pi);
  return {a.pose.x_m + f * (b.pose.x_m - a.pose.x_m), a.pose.y_m + f * (b.pose.y_m - a.pose.y_m),
          std::remainder(a.pose.theta_rad + f * turn, 2.0 * std::numbers::pi)};
}

ReplayViewer::ReplayViewer(RunReplayData data, const WindowOptions& window)
    : data_(std::move(data)) {
  const sim::RobotCatalogEntry& robot = sim::FindRobot(data_.config.robot);
  sim::SceneOptions options;
  options.world_mjcf = data_.config.world_path;
  options.robot_mjcf = robot.mjcf;
  options.spawn = data_.trajectories.front().poses.front().pose;
  options.timestep_s = data_.config.physics.timestep_s;
  scene_ = std::make_unique<sim::Scene>(options);
  eval::RequireWorldAsTheRunSawIt(*scene_, data_.config, data_.walls, data_.config_yaml,
                                  "a replay would show the run in another world");
  for (const std::string& name : sim::SonarSensor::DefaultSiteNames()) {
    const std::optional<int> site = scene_->FindSite(name);
    sonar_X_RS_.push_back(site ? scene_->SitePoseInRobot(*site) : msgs::Pose2D{});
    if (site && name == "sonar_0") sonar_height_m_ = scene_->SiteHeightM(*site);
  }
  if (const std::optional<int> site = scene_->FindSite("laser")) {
    laser_height_m_ = scene_->SiteHeightM(*site);
  }
  window_ = std::make_unique<ViewerWindow>(scene_->model(), window);
  controls_ = std::make_unique<ViewControls>(data_.config.nominal);
  window_->SetKeyHandler([this](int key, int action, int) {
    controls_->HandleKey(key, action);
    if (action == GLFW_RELEASE) return;
    if (key == GLFW_KEY_COMMA) time_s_ -= 1.0;
    if (key == GLFW_KEY_PERIOD) time_s_ += 1.0;
  });
  world_ = render::StaticGeometryExtent(scene_->model()).bounds;
  time_s_ = data_.start_s();
}

ReplayViewer::~ReplayViewer() = default;

FrameContent ReplayViewer::ContentAt(double t_s) const {
  FrameContent content;
  content.time_s = t_s;
  for (std::size_t k = 0; k < data_.trajectories.size(); ++k) {
    const eval::NamedTrajectory& trajectory = data_.trajectories[k];
    PathView path;
    path.label = trajectory.name;
    const render::Rgb colour =
        k == 0 ? render::colours::kBlack
               : render::colours::kPalette[(k - 1) % std::size(render::colours::kPalette)];
    path.rgba[0] = colour.r / 255.0f;
    path.rgba[1] = colour.g / 255.0f;
    path.rgba[2] = colour.b / 255.0f;
    for (const perception::TimedPose& p : trajectory.poses) {
      if (p.time_s > t_s) break;
      path.points_W.emplace_back(p.pose.x_m, p.pose.y_m);
    }
    const msgs::Pose2D now = PoseAt(trajectory, t_s);
    path.points_W.emplace_back(now.x_m, now.y_m);
    content.paths.push_back(std::move(path));
  }
  if (!data_.laser.empty() && data_.laser.front().time_s <= t_s) {
    const RunReplayData::Scan& s =
        data_.laser[LastAtOrBefore(data_.laser, t_s, [](const auto& x) { return x.time_s; })];
    LaserView view;
    view.X_WS = s.X_WS;
    view.height_m = laser_height_m_;
    view.range_max_m = s.scan.range_max_m;
    view.ranges_m = s.scan.ranges_m;
    for (std::size_t i = 0; i < s.scan.ranges_m.size(); ++i) {
      view.angles_rad.push_back(s.scan.BeamAngleRad(i));
    }
    content.laser = std::move(view);
  }
  if (!data_.sonar.empty() && data_.sonar.front().time_s <= t_s) {
    msgs::RangeRing ring =
        data_.sonar[LastAtOrBefore(data_.sonar, t_s, [](const auto& r) { return r.time_s; })];
    for (std::size_t i = 0; i < ring.readings.size() && i < sonar_X_RS_.size(); ++i) {
      ring.readings[i].X_RS = sonar_X_RS_[i];
    }
    const msgs::Pose2D X_WR = PoseAt(data_.trajectories.front(), ring.time_s);
    RingView view{X_WR,
                  sonar_height_m_,
                  data_.config.sensors.sonar->beam_half_angle_deg * kDegToRad,
                  ring,
                  {}};
    view.kinds = ClassifyRing(*scene_, X_WR, sonar_height_m_, view.ring);
    content.sonar = std::move(view);
  }
  // The files hold the final maps only: shown whole at any time.
  content.map = data_.map;
  content.geometric_map = data_.geometric_map;
  return content;
}

void ReplayViewer::ShowAt(double t_s) {
  time_s_ = std::clamp(t_s, data_.start_s(), data_.end_s());
  scene_->PlaceRobot(PoseAt(data_.trajectories.front(), time_s_));
  const FrameContent content = ContentAt(time_s_);
  mjvScene& scene = window_->BeginFrame(scene_->mutable_data());
  AddOverlays(scene, window_->overlay_primitives(), content, *controls_, world_);
  char clock[160];
  std::snprintf(clock, sizeof(clock), "replay\t%s\nsimulated time\t%.2f / %.2f s%s",
                data_.config.name.c_str(), time_s_, data_.end_s(),
                controls_->paused() ? "\nstate\tpaused" : "");
  const double start = data_.start_s(), end = data_.end_s();
  double* time = &time_s_;
  window_->Finish(controls_->help() ? ViewControls::HelpText() : "F1\thelp", clock, [=] {
#if PLYWOOD_HAS_IMGUI
    ImGui::SetNextWindowPos(ImVec2(10, ImGui::GetIO().DisplaySize.y - 60), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(ImGui::GetIO().DisplaySize.x - 20, 0), ImGuiCond_Always);
    ImGui::Begin("timeline", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize);
    float t = static_cast<float>(*time);
    ImGui::SetNextItemWidth(-1);
    if (ImGui::SliderFloat("##t", &t, static_cast<float>(start), static_cast<float>(end),
                           "t = %.2f s")) {
      *time = t;
    }
    ImGui::End();
#else
    (void)time;
    (void)start;
    (void)end;
#endif
  });
}

void ReplayViewer::Run() {
  using Clock = std::chrono::steady_clock;
  auto last = Clock::now();
  while (!window_->CloseRequested()) {
    window_->PollEvents();
    const auto now = Clock::now();
    const double wall_dt = std::chrono::duration<double>(now - last).count();
    last = now;
    if (!controls_->paused()) {
      const double factor = controls_->SpeedFactor() > 0 ? controls_->SpeedFactor() : 100.0;
      time_s_ += factor * wall_dt;
      if (time_s_ >= data_.end_s()) controls_->set_paused(true);
    }
    if (controls_->TakeFollowRequest()) {
      window_->SetPreset(CameraPreset::kFollow, scene_->base_body_id());
    }
    ShowAt(time_s_);
    std::this_thread::sleep_for(std::chrono::milliseconds(15));
  }
}

}  // namespace plywood::viewer
