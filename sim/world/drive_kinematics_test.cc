// Acceptance tests of the drive physics: the MuJoCo robots must roll like ideal differential-drive
// kinematics (what odometry assumes), and Borenstein & Feng's systematic errors E_d and E_b must
// bend the true path exactly as their closed forms say.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "msgs/pose2d.h"
#include "robot/drive/diff_drive_spec.h"
#include "sim/config/config_error.h"
#include "sim/sensors/sensor_sites.h"
#include "sim/world/physical_deviation.h"
#include "sim/world/scene.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim {
namespace {

constexpr double kPi = std::numbers::pi;

// What one open-loop run did: wheel rotations and the true motion of the base.
struct DriveResult {
  double left_rad = 0.0;
  double right_rad = 0.0;
  double heading_rad = 0.0;  // unwrapped true heading change
  double path_m = 0.0;       // length of the true path of the base origin
  msgs::Pose2D end;
  bool finite = true;
  int warnings = 0;  // MuJoCo warnings raised in mjData (contact buffer full, bad qacc, ...)
};

// Commands constant wheel speeds (wl, wr) with linear ramps of `ramp_s` up and down around
// `hold_s` at full speed, then lets the robot settle.
DriveResult Drive(Scene& scene, double wl, double wr, double hold_s, double ramp_s = 0.5) {
  DriveResult run;
  const double left0 = scene.LeftWheelAngleRad(), right0 = scene.RightWheelAngleRad();
  msgs::Pose2D prev = scene.TruePose();
  const double t0 = scene.time_s();
  const double total_s = 2.0 * ramp_s + hold_s + 0.5;
  while (scene.time_s() - t0 < total_s) {
    const double t = scene.time_s() - t0;
    const double k =
        std::clamp(std::min(t / ramp_s, (2.0 * ramp_s + hold_s - t) / ramp_s), 0.0, 1.0);
    scene.SetWheelSpeeds({k * wl, k * wr});
    scene.Step();
    const msgs::Pose2D pose = scene.TruePose();
    if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.theta_rad)) {
      run.finite = false;
      break;
    }
    run.heading_rad += msgs::WrapAngle(pose.theta_rad - prev.theta_rad);
    run.path_m += std::hypot(pose.x_m - prev.x_m, pose.y_m - prev.y_m);
    prev = pose;
  }
  run.end = scene.TruePose();
  run.left_rad = scene.LeftWheelAngleRad() - left0;
  run.right_rad = scene.RightWheelAngleRad() - right0;
  for (int i = 0; i < mjNWARNING; ++i) run.warnings += scene.data()->warning[i].number;
  return run;
}

// A flat floor; `floor_attributes` may override its contact parameters.
std::filesystem::path FloorWorld(const std::string& floor_attributes = "") {
  return testing::WriteFile(testing::MakeTempDir("drive_kinematics") / "floor.xml",
                            "<mujoco>\n  <worldbody>\n    <geom name=\"floor\" type=\"plane\" "
                            "size=\"20 20 0.1\" " +
                                floor_attributes + "/>\n  </worldbody>\n</mujoco>\n");
}

struct RobotCase {
  std::string mjcf;
  robot::DiffDriveSpec spec;
};

RobotCase P3dx() { return {"p3dx.xml", robot::P3dxSpec()}; }
RobotCase MagellanPro() { return {"magellan_pro.xml", robot::MagellanProSpec()}; }

std::unique_ptr<Scene> MakeScene(const RobotCase& robot, double timestep_s,
                                 const PhysicalDeviation& deviation,
                                 const std::string& floor_attributes = "") {
  auto scene = std::make_unique<Scene>(
      SceneOptions{.world_mjcf = FloorWorld(floor_attributes),
                   .robot_mjcf = testing::SourceRoot() / "models" / robot.mjcf,
                   .spawn = {},
                   .timestep_s = timestep_s});
  scene->SetWheelGeometry(DeviatedWheelGeometry(robot.spec, deviation));
  return scene;
}

// Straight 5 m at 0.4 m/s, commanded by nominal kinematics.
DriveResult DriveStraight(Scene& scene, const robot::DiffDriveSpec& spec) {
  const double speed_m_s = 0.4;
  const double w = speed_m_s / spec.wheel_radius_m;
  return Drive(scene, w, w, 5.0 / speed_m_s - 0.5);
}

// 360 deg on the spot at 1 rad/s, commanded by nominal kinematics.
DriveResult SpinOnTheSpot(Scene& scene, const robot::DiffDriveSpec& spec) {
  const double w = 1.0 * spec.track_m / 2.0 / spec.wheel_radius_m;
  return Drive(scene, -w, w, 2.0 * kPi - 0.5);
}

class IdealKinematicsTest : public ::testing::TestWithParam<std::tuple<RobotCase (*)(), double>> {};

TEST_P(IdealKinematicsTest, StraightRunRollsWithoutSlip) {
  const RobotCase robot = std::get<0>(GetParam())();
  const std::unique_ptr<Scene> scene = MakeScene(robot, std::get<1>(GetParam()), {});
  const DriveResult run = DriveStraight(*scene, robot.spec);
  ASSERT_TRUE(run.finite);
  EXPECT_EQ(run.warnings, 0);
  const double r = robot.spec.wheel_radius_m;
  const double wheel_distance_m = r * (run.left_rad + run.right_rad) / 2.0;
  EXPECT_NEAR(wheel_distance_m, 5.0, 0.05);  // the servo tracks the command
  // Measured: -0.10% (P3-DX), -0.07% (Magellan Pro): the soft contact sinks the tire ~0.1 mm.
  EXPECT_NEAR(run.path_m / wheel_distance_m, 1.0, 0.005);
  EXPECT_LT(std::abs(run.end.y_m), 0.005);
  EXPECT_LT(std::abs(run.heading_rad), 0.002);
  EXPECT_NEAR(run.end.x_m, run.path_m, 1e-3);
}

TEST_P(IdealKinematicsTest, SpinOnTheSpotTurnsAsTheWheelsSay) {
  const RobotCase robot = std::get<0>(GetParam())();
  const std::unique_ptr<Scene> scene = MakeScene(robot, std::get<1>(GetParam()), {});
  const DriveResult run = SpinOnTheSpot(*scene, robot.spec);
  ASSERT_TRUE(run.finite);
  EXPECT_EQ(run.warnings, 0);
  const double wheel_heading_rad =
      robot.spec.wheel_radius_m * (run.right_rad - run.left_rad) / robot.spec.track_m;
  EXPECT_NEAR(wheel_heading_rad, 2.0 * kPi, 0.05);
  // Measured: -0.22% for both robots (1 cm contact cylinders; a full-width tire scrubs ~3%).
  EXPECT_NEAR(run.heading_rad / wheel_heading_rad, 1.0, 0.005);
  EXPECT_LT(std::hypot(run.end.x_m, run.end.y_m), 0.005);  // turned about the axle midpoint
}

// How far a site's world pose strays from TruePose() * its robot-frame pose while the robot spins
// up on the spot for 1 s and then arcs forward (read after every step, as the sensors are).
struct SiteLag {
  double worst_m = 0.0;
  double worst_rad = 0.0;
};
SiteLag SpinAndArc(Scene& scene, int site) {
  const msgs::Pose2D X_RS = scene.SitePoseInRobot(site);
  SiteLag lag;
  while (scene.time_s() < 1.5) {
    const double k = std::min(1.0, scene.time_s() / 0.5);
    scene.SetWheelSpeeds(scene.time_s() < 1.0 ? msgs::WheelSpeedCommand{-4.0 * k, 4.0 * k}
                                              : msgs::WheelSpeedCommand{2.0, 4.0});
    scene.Step();
    const Eigen::Isometry3d X_WS = scene.SitePoseInWorld(site);
    const msgs::Pose2D expected = scene.TruePose() * X_RS;
    lag.worst_m = std::max(lag.worst_m, std::hypot(X_WS.translation().x() - expected.x_m,
                                                   X_WS.translation().y() - expected.y_m));
    const double yaw = std::atan2(X_WS.linear()(1, 0), X_WS.linear()(0, 0));
    lag.worst_rad = std::max(lag.worst_rad, std::abs(msgs::WrapAngle(yaw - expected.theta_rad)));
  }
  return lag;
}

// The P3-DX's MJCF with `body_xml` inserted in its base body, written to a temporary file.
std::filesystem::path P3dxWithBodyOnTheBase(const std::string& body_xml, const std::string& name) {
  std::ifstream in(testing::SourceRoot() / "models" / "p3dx.xml");
  std::stringstream text;
  text << in.rdbuf();
  std::string mjcf = text.str();
  const std::string base = "<freejoint name=\"base_free\"/>";
  const size_t at = mjcf.find(base);
  if (at == std::string::npos) throw std::runtime_error("p3dx.xml: no base_free joint");
  mjcf.insert(at + base.size(), body_xml);
  return testing::WriteFile(testing::MakeTempDir("drive_kinematics_robot") / name, mjcf);
}

// The sensors cast from their sites' world poses; the runner logs each scan with TruePose() at the
// same instant (laser.log's "true laser pose", the line scorer's sensor frame). After mj_step,
// site_xpos / site_xmat still describe the state before the integration, so unless the scene
// places the base's sites from qpos they lag TruePose() by one step: 23.5 mrad spinning at
// 2.36 rad/s as here, 4 mm at 0.4 m/s (stop 51: up to 0.13 m on grazing beams of a noise-free
// scan).
TEST_P(IdealKinematicsTest, SensorSitesMoveWithTheTruePoseEveryStep) {
  const RobotCase robot = std::get<0>(GetParam())();
  const std::unique_ptr<Scene> scene = MakeScene(robot, std::get<1>(GetParam()), {});
  const SiteLag lag = SpinAndArc(*scene, *scene->FindSite("sonar_3"));
  // One step behind: 3.8-23.5 mrad and 0.8-4.6 mm (both robots, 10 and 2 ms steps). In step:
  // <= 1.1e-5 rad; the <= 1.9 mm left is the body's tilt on its soft contacts, which moves a site
  // 0.2 m up sideways but barely turns its heading.
  EXPECT_LT(lag.worst_rad, 1e-4);
  EXPECT_LT(lag.worst_m, 2.5e-3);
}

// The same for a sensor site on a body welded to the base (a user robot's mast): its pose comes
// from the bodies, which mj_step places before it integrates, so the scene places them afresh.
TEST(DriveKinematicsTest, SensorSitesOnAChildBodyMoveWithTheTruePoseEveryStep) {
  const std::filesystem::path robot_mjcf = P3dxWithBodyOnTheBase(
      "<body name=\"mast\" pos=\"-0.1 0.05 0.15\" euler=\"0 0 30\">"
      "<site name=\"mast_laser\" pos=\"0.05 0 0.05\" size=\"0.01\"/></body>",
      "p3dx_mast.xml");
  Scene scene(SceneOptions{
      .world_mjcf = FloorWorld(), .robot_mjcf = robot_mjcf, .spawn = {}, .timestep_s = 0.01});
  const int site = *scene.FindSite("mast_laser");
  const msgs::Pose2D X_RS = scene.SitePoseInRobot(site);
  // The mast at (-0.1, 0.05) turned 30 deg, the site 0.05 m along its x axis.
  EXPECT_NEAR(X_RS.x_m, -0.1 + 0.05 * std::cos(kPi / 6.0), 1e-9);
  EXPECT_NEAR(X_RS.y_m, 0.05 + 0.05 * std::sin(kPi / 6.0), 1e-9);
  EXPECT_NEAR(X_RS.theta_rad, kPi / 6.0, 1e-9);
  EXPECT_NEAR(scene.SiteHeightM(site), 0.2, 1e-9);
  // One step behind without the per-step placement: 23.5 mrad.
  const SiteLag lag = SpinAndArc(scene, site);
  EXPECT_LT(lag.worst_rad, 1e-4);
  EXPECT_LT(lag.worst_m, 2.5e-3);
}

// A sensor on a body that turns against the base (a pan unit's hinge) has no fixed pose in the
// robot frame: refused with the robot file and the site named, not placed where it was built.
TEST(DriveKinematicsTest, ASensorSiteBehindAJointIsRefused) {
  const std::filesystem::path robot_mjcf = P3dxWithBodyOnTheBase(
      "<body name=\"pan\" pos=\"0 0 0.3\"><joint name=\"pan\" type=\"hinge\"/>"
      "<inertial pos=\"0 0 0\" mass=\"0.1\" diaginertia=\"1e-4 1e-4 1e-4\"/>"
      "<site name=\"pan_laser\" pos=\"0.05 0 0\" size=\"0.01\"/></body>",
      "p3dx_pan.xml");
  Scene scene(SceneOptions{
      .world_mjcf = FloorWorld(), .robot_mjcf = robot_mjcf, .spawn = {}, .timestep_s = 0.01});
  EXPECT_TRUE(scene.SiteFixedToBase(*scene.FindSite("laser")));
  EXPECT_FALSE(scene.SiteFixedToBase(*scene.FindSite("pan_laser")));
  try {
    RequireSensorSite(scene, "pan_laser", "the laser", 8.0);
    ADD_FAILURE() << "a joint-mounted sensor site was accepted";
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("p3dx_pan.xml"), std::string::npos) << message;
    EXPECT_NE(message.find("pan_laser"), std::string::npos) << message;
    EXPECT_NE(message.find("not fixed to the robot's base body"), std::string::npos) << message;
  }
}

// The robots' tires and casters carry contact priority, so a world's floor settings (here torsional
// and rolling friction, and a slippery sliding coefficient) do not change how they drive.
TEST(DriveKinematicsTest, FloorContactSettingsDoNotChangeTheDrive) {
  for (const RobotCase& robot : {P3dx(), MagellanPro()}) {
    const std::string floor = "condim=\"6\" friction=\"0.2 0.05 0.01\"";
    const std::unique_ptr<Scene> straight_scene = MakeScene(robot, 0.01, {}, floor);
    const DriveResult straight = DriveStraight(*straight_scene, robot.spec);
    const double r = robot.spec.wheel_radius_m;
    EXPECT_NEAR(straight.path_m / (r * (straight.left_rad + straight.right_rad) / 2.0), 1.0, 0.005)
        << robot.mjcf;
    const std::unique_ptr<Scene> spin_scene = MakeScene(robot, 0.01, {}, floor);
    const DriveResult spin = SpinOnTheSpot(*spin_scene, robot.spec);
    EXPECT_NEAR(spin.heading_rad / (r * (spin.right_rad - spin.left_rad) / robot.spec.track_m), 1.0,
                0.005)
        << robot.mjcf;
  }
}

INSTANTIATE_TEST_SUITE_P(RobotsAndTimesteps, IdealKinematicsTest,
                         ::testing::Combine(::testing::Values(&P3dx, &MagellanPro),
                                            ::testing::Values(0.01, 0.002)));

class DeviationTest : public ::testing::TestWithParam<RobotCase (*)()> {};

TEST_P(DeviationTest, LargerRightWheelCurvesLeftAsTheClosedFormSays) {
  const RobotCase robot = GetParam()();
  const PhysicalDeviation deviation{.wheel_diameter_ratio = 1.01};
  const std::unique_ptr<Scene> scene = MakeScene(robot, 0.01, deviation);
  const WheelGeometry g = scene->wheel_geometry();
  ASSERT_NEAR(g.right_radius_m / g.left_radius_m, 1.01, 1e-12);
  const DriveResult run = DriveStraight(*scene, robot.spec);
  ASSERT_TRUE(run.finite);
  // Equal wheel speeds, a larger right wheel: v_r > v_l, so the robot curves left (y > 0).
  EXPECT_GT(run.heading_rad, 0.0);
  EXPECT_GT(run.end.y_m, 0.0);
  // Closed form: dtheta = (r_R dphi_R - r_L dphi_L) / b, curvature = dtheta / ds.
  const double expected_heading_rad =
      (g.right_radius_m * run.right_rad - g.left_radius_m * run.left_rad) / g.track_m;
  EXPECT_NEAR(run.heading_rad / expected_heading_rad, 1.0, 0.05);
  const double expected_curvature_1_m = 2.0 * (g.right_radius_m - g.left_radius_m) /
                                        (g.track_m * (g.right_radius_m + g.left_radius_m));
  EXPECT_NEAR(run.heading_rad / run.path_m / expected_curvature_1_m, 1.0, 0.05);
  // On that arc the lateral offset is (1 - cos theta) / kappa.
  EXPECT_NEAR(run.end.y_m, (1.0 - std::cos(run.heading_rad)) / expected_curvature_1_m,
              0.05 * run.end.y_m);
}

TEST_P(DeviationTest, WiderTrackUnderTurnsByTrackRatio) {
  const RobotCase robot = GetParam()();
  const double e_b = 1.03;
  const std::unique_ptr<Scene> scene = MakeScene(robot, 0.01, {.track_ratio = e_b});
  ASSERT_NEAR(scene->wheel_geometry().track_m, e_b * robot.spec.track_m, 1e-12);
  const DriveResult run = SpinOnTheSpot(*scene, robot.spec);
  ASSERT_TRUE(run.finite);
  const double nominal_heading_rad =
      robot.spec.wheel_radius_m * (run.right_rad - run.left_rad) / robot.spec.track_m;
  EXPECT_NEAR(nominal_heading_rad, 2.0 * kPi, 0.05);
  // Measured: -0.21% against the closed form.
  EXPECT_NEAR(run.heading_rad / (nominal_heading_rad / e_b), 1.0, 0.01);
}

// The P3-DX with single-contact tires: the tire class's 1 cm cylinder (two rim contacts) replaced
// by an ellipsoid of the wheel's radius in the wheel plane and the cylinder's 5 mm half-width along
// the axle (one contact at the tread's centre line; docs/performance.md, "Physics options
// measured").
RobotCase P3dxEllipsoidTires() {
  std::ifstream in(testing::SourceRoot() / "models" / "p3dx.xml");
  std::stringstream text;
  text << in.rdbuf();
  std::string mjcf = text.str();
  const std::string cylinder = "type=\"cylinder\" size=\"0.0975 0.005\" euler=\"90 0 0\"";
  if (const size_t at = mjcf.find(cylinder); at != std::string::npos) {
    mjcf.replace(at, cylinder.size(), "type=\"ellipsoid\" size=\"0.0975 0.005 0.0975\"");
  }
  return {testing::WriteFile(testing::MakeTempDir("drive_kinematics_ellipsoid") / "p3dx.xml", mjcf)
              .string(),
          robot::P3dxSpec()};
}

INSTANTIATE_TEST_SUITE_P(Robots, DeviationTest,
                         ::testing::Values(&P3dx, &MagellanPro, &P3dxEllipsoidTires));

// A deviated ellipsoid tire keeps its rolling radius in both wheel-plane semi-axes (x and z), so
// the contact point under the axle moves with the radius (Scene::SetWheelGeometry).
TEST(DriveKinematicsTest, EllipsoidTiresTakeTheDeviatedRadiusInTheWheelPlane) {
  const RobotCase robot = P3dxEllipsoidTires();
  const std::unique_ptr<Scene> scene = MakeScene(robot, 0.01, {.wheel_diameter_ratio = 1.01});
  const mjModel* m = scene->model();
  const WheelGeometry g = scene->wheel_geometry();
  for (const auto& [name, radius] : {std::pair{"left_wheel_tire", g.left_radius_m},
                                     std::pair{"right_wheel_tire", g.right_radius_m}}) {
    const int tire = mj_name2id(m, mjOBJ_GEOM, name);
    ASSERT_GE(tire, 0);
    ASSERT_EQ(m->geom_type[tire], mjGEOM_ELLIPSOID);
    EXPECT_EQ(m->geom_size[3 * tire], radius);
    EXPECT_EQ(m->geom_size[3 * tire + 1], 0.005);
    EXPECT_EQ(m->geom_size[3 * tire + 2], radius);
    EXPECT_EQ(m->geom_rbound[tire], radius);
    // The tire's lowest point touches the floor: the axle stands at the radius.
    EXPECT_EQ(m->body_pos[3 * m->geom_bodyid[tire] + 2], radius);
  }
  EXPECT_NEAR(g.right_radius_m / g.left_radius_m, 1.01, 1e-12);
}

}  // namespace
}  // namespace plywood::sim
