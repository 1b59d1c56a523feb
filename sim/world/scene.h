#pragma once

#include <Eigen/Geometry>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "msgs/pose2d.h"
#include "msgs/wheel_speed_command.h"
#include "sim/world/drive_mode.h"
#include "sim/world/mujoco_handles.h"
#include "sim/world/near_contact_pairs.h"

namespace plywood::sim {

// Everything that fixes how a world and a robot become one MuJoCo model.
struct SceneOptions {
  std::filesystem::path world_mjcf;  // static geometry only; any hand-written MJCF room
  std::filesystem::path robot_mjcf;  // follows the conventions of models/README.md
  msgs::Pose2D spawn;                // X_WR at t = 0
  double timestep_s = 0.01;
  DriveMode drive = DriveMode::kContact;  // kPlanar: Step() moves the robot without mj_step
};

// The true geometry of the simulated robot's drive, which may differ from the nominal spec the
// robot's software uses (Borenstein's E_d and E_b are ratios of these).
struct WheelGeometry {
  double left_radius_m = 0.0;
  double right_radius_m = 0.0;
  double track_m = 0.0;
};

// A world and a robot compiled into one MuJoCo model, with the handles every sensor and the runner
// need. The robot's geoms all live in geom group kRobotGeomGroup so rays can skip them.
class PlanarDrive;

class Scene {
 public:
  static constexpr int kRobotGeomGroup = 3;
  // How far a tire's lowest point may sit from the floor (z = 0 in the robot frame) when built.
  static constexpr double kWheelOnFloorToleranceM = 1e-3;

  // @throws ConfigError naming the world or robot file when either is missing or does not compile,
  // or when the robot breaks the model conventions (a tire that does not reach the floor, too).
  explicit Scene(const SceneOptions& options);
  ~Scene();

  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  const mjModel* model() const { return model_.get(); }
  // Every geom and site placed. Step() leaves the robot's draw-only geoms (DrawOnlyGeoms: visual
  // wheels, shell, bump panels) and the sites (if StepCanSkipSites) where they were; these place
  // them first (calling thread), bit for bit where mj_step would have put them. In the planar drive
  // Step() places nothing, and these run mj_kinematics, mj_comPos and mj_camlight first (contacts
  // and sensordata stay those of the last mj_forward: the planar drive has none).
  const mjData* data() const {
    PlaceDrawOnlyGeoms();
    return data_.get();
  }
  mjData* mutable_data() {
    PlaceDrawOnlyGeoms();
    return data_.get();
  }
  // The data as the last step left it, the draw-only geoms' and sites' poses possibly stale: for
  // the step loop's reads of the state, contacts and bodies (SitePoseInWorld places a site). In
  // the planar drive only qpos, qvel and time are current.
  const mjData* stepped_data() const { return data_.get(); }

  DriveMode drive() const { return options_.drive; }
  // The planar drive's bumper contacts: bearings (robot frame) of the points of the bumper ring's
  // footprint within kPlanarContactSkinM of a static geom, at the current pose. Empty in the
  // contact drive (the bumpers read MuJoCo's contacts there).
  static constexpr double kPlanarContactSkinM = 1e-3;
  std::vector<double> PlanarContactBearings() const;
  // The planar drive's obstacles held only by their bounding disc (PlanarObstacles); empty in the
  // contact drive.
  std::vector<int> PlanarBoundingDiscGeoms() const;
  // The planar drive's height fields that rise into the bumper ring's height (PlanarObstacles),
  // which it drives through; empty in the contact drive.
  std::vector<int> PlanarRaisedHeightFields() const;

  double time_s() const { return data_->time; }
  double timestep_s() const { return model_->opt.timestep; }

  // Ground-truth pose of the robot's base frame (centre of rotation on the floor).
  msgs::Pose2D TruePose() const;
  // Ground-truth yaw rate about the world's vertical axis.
  double TrueYawRateRadS() const;
  // Puts the robot's base at X_WR (upright, height unchanged) and recomputes the kinematics
  // (mj_forward), without stepping: for sampling sensor readings at chosen poses.
  void PlaceRobot(const msgs::Pose2D& X_WR);

  // Wheel joint angles (rad); positive rotation drives forward.
  double LeftWheelAngleRad() const { return data_->qpos[left_wheel_qpos_]; }
  double RightWheelAngleRad() const { return data_->qpos[right_wheel_qpos_]; }

  // Wheel velocity setpoints, clamped by the actuators' ctrlrange.
  void SetWheelSpeeds(const msgs::WheelSpeedCommand& command);
  // The largest wheel speed both motors accept unclamped, either way (infinite when the robot's
  // file leaves them unlimited).
  double WheelMotorLimitRadS() const;
  void Step();

  // Re-shapes the simulated drive: wheel radii and track as built, not as specified.
  void SetWheelGeometry(const WheelGeometry& geometry);
  WheelGeometry wheel_geometry() const;

  bool IsRobotGeom(int geom_id) const { return model_->geom_group[geom_id] == kRobotGeomGroup; }
  int base_body_id() const { return base_body_; }

  // A site on the robot: its pose in the robot frame (planar part) and in the world (3-D). The
  // robot-frame pose holds for a site on the base or on bodies welded to it (SiteFixedToBase).
  std::optional<int> FindSite(const std::string& name) const;
  bool SiteFixedToBase(int site_id) const;
  msgs::Pose2D SitePoseInRobot(int site_id) const;
  double SiteHeightM(int site_id) const;
  // The site's 3-D pose in the base body's frame (through welded bodies; the model as built).
  Eigen::Isometry3d SitePoseInBase(int site_id) const;
  Eigen::Isometry3d SitePoseInWorld(int site_id) const;

  const std::filesystem::path& world_path() const { return options_.world_mjcf; }
  const std::filesystem::path& robot_path() const { return options_.robot_mjcf; }

 private:
  // The site's position and orientation in the base body's frame, through welded bodies.
  void SiteInBaseFrame(int site_id, double pos[3], double quat[4]) const;
  // @throws ConfigError naming the robot file and the tire whose lowest point is off the floor, or
  // the colliding geom that reaches into it.
  void RequireRobotOnTheFloor() const;
  void MakeNearContactPairs();
  void MakePlanarDrive();
  void PlaceDrawOnlyGeoms() const;
  // Runs MuJoCo with the robot's near contact pairs in place (when the model has them).
  template <typename Call>
  void WithNearPairs(Call call) {
    if (!near_pairs_) return call();
    const NearContactPairs::Active active = near_pairs_->Activate(data_.get());
    call();
  }

  SceneOptions options_;
  MjModelPtr model_;
  MjDataPtr data_;
  int base_body_ = -1;
  int base_qpos_ = -1;
  int left_wheel_body_ = -1, right_wheel_body_ = -1;
  int left_wheel_qpos_ = -1, right_wheel_qpos_ = -1;
  int left_motor_ = -1, right_motor_ = -1;
  int left_tire_ = -1, right_tire_ = -1;
  std::unique_ptr<NearContactPairs> near_pairs_;
  std::vector<int> draw_only_geoms_;       // DrawOnlyGeoms of the model, skipped by Step()
  bool skip_sites_ = false;                // StepCanSkipSites: Step() leaves every site unplaced
  mutable bool draw_only_stale_ = false;   // Step() skipped them (and the sites) since placed
  std::unique_ptr<PlanarDrive> planar_;    // DriveMode::kPlanar only
  mutable bool kinematics_stale_ = false;  // the planar drive moved the robot since mj_kinematics
  // mj_step integrated qpos after placing the bodies: their xpos / xquat are one step behind.
  mutable bool bodies_behind_qpos_ = false;
};

// The MJCF text that includes `world` and `robot` into one model (exposed for tests), with
// `placeholder_pairs` inert contact pairs between the robot's tires for NearContactPairs to reuse.
std::string ComposeSceneMjcf(const std::filesystem::path& world, const std::filesystem::path& robot,
                             int placeholder_pairs = 0);

}  // namespace plywood::sim
