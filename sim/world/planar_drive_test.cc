// The planar drive (physics.drive: planar): closed forms of its lagged wheel servos, its E_d / E_b
// kinematics, and its walls (the bumper ring's footprint stops the robot and presses the bumpers).
#include "sim/world/planar_drive.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "msgs/pose2d.h"
#include "robot/drive/diff_drive_spec.h"
#include "sim/config/config_error.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"
#include "sim/sensors/bumper_sensor.h"
#include "sim/world/physical_deviation.h"
#include "sim/world/scene.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim {
namespace {

constexpr double kPi = std::numbers::pi;

// A floor, and a 5 cm thick wall whose near face is the plane x = 1 (as bumper_sensor_test's).
std::filesystem::path World(bool wall) {
  return testing::WriteFile(
      testing::MakeTempDir(wall ? "planar_drive_wall" : "planar_drive_floor") / "world.xml",
      std::string("<mujoco>\n  <worldbody>\n    <geom name=\"floor\" type=\"plane\" size=\"5 5 "
                  "0.1\"/>\n") +
          (wall
               ? "    <geom name=\"wall\" type=\"box\" pos=\"1.025 0 0.5\" size=\"0.025 2 0.5\"/>\n"
               : "") +
          "  </worldbody>\n</mujoco>\n");
}

struct RobotCase {
  std::string mjcf;
  robot::DiffDriveSpec spec;
};
RobotCase P3dx() { return {"p3dx.xml", robot::P3dxSpec()}; }
RobotCase MagellanPro() { return {"magellan_pro.xml", robot::MagellanProSpec()}; }

std::unique_ptr<Scene> MakeScene(const RobotCase& robot, DriveMode drive, bool wall = false,
                                 const PhysicalDeviation& deviation = {}, double theta_rad = 0.0) {
  auto scene = std::make_unique<Scene>(
      SceneOptions{.world_mjcf = World(wall),
                   .robot_mjcf = testing::SourceRoot() / "models" / robot.mjcf,
                   .spawn = {.theta_rad = theta_rad},
                   .timestep_s = 0.01,
                   .drive = drive});
  scene->SetWheelGeometry(DeviatedWheelGeometry(robot.spec, deviation));
  return scene;
}

// A planar P3-DX at the origin in a world of a floor and the given static geoms (MJCF lines).
std::unique_ptr<Scene> MakeP3dxSceneAmong(const std::string& name, const std::string& geoms) {
  const std::filesystem::path world = testing::WriteFile(
      testing::MakeTempDir(name) / "world.xml",
      "<mujoco>\n  <worldbody>\n    <geom name=\"floor\" type=\"plane\" size=\"5 5 0.1\"/>\n" +
          geoms + "  </worldbody>\n</mujoco>\n");
  return std::make_unique<Scene>(
      SceneOptions{.world_mjcf = world,
                   .robot_mjcf = testing::SourceRoot() / "models" / "p3dx.xml",
                   .spawn = {},
                   .timestep_s = 0.01,
                   .drive = DriveMode::kPlanar});
}

// The wheel angle after n steps of a constant command c from rest, for a servo whose speed moves
// the fraction a of the way to c each step (explicit Euler of the first-order lag) and then turns
// the wheel by speed x dt: phi_n = c dt sum_{k=1..n} (1 - (1 - a)^k).
double LaggedAngle(double c, double dt, double a, int n) {
  return c * dt * (n - (1.0 - a) * (1.0 - std::pow(1.0 - a, n)) / a);
}

// Runs `steps` steps of constant wheel commands.
void Drive(Scene& scene, double left, double right, int steps) {
  scene.SetWheelSpeeds({left, right});
  for (int i = 0; i < steps; ++i) scene.Step();
}

class PlanarDriveTest : public ::testing::TestWithParam<RobotCase (*)()> {};

// The time constants from the model by hand: P3-DX, m = 8 (chassis) + 0.1 (caster) + 2 x 0.5
// (wheels) = 9.1 kg, Iw = 0.0023765625 (tire about its axle) + 0.05 (armature), kv = 5:
// tau_straight = (Iw + m r^2 / 2) / kv = (0.0523766 + 0.0432534) / 5 = 19.13 ms.
TEST(PlanarDriveTest, P3dxStraightTimeConstantIsTheHandDerivedOne) {
  const std::unique_ptr<Scene> scene = MakeScene(P3dx(), DriveMode::kPlanar);
  const mjModel* m = scene->model();
  const int base = scene->base_body_id();
  EXPECT_NEAR(m->body_subtreemass[base], 9.1, 1e-9);
  const double r = 0.0975;
  const double expected_s = (0.0023765625 + 0.05 + 9.1 * r * r / 2.0) / 5.0;
  // Planar time constants are only reachable through the step response: after one step of a
  // command c from rest the wheels turn at a c with a = dt / tau.
  scene->SetWheelSpeeds({4.0, 4.0});
  scene->Step();
  const double a = (scene->LeftWheelAngleRad() / 0.01) / 4.0;
  EXPECT_NEAR(a, 0.01 / expected_s, 1e-9);
}

TEST_P(PlanarDriveTest, StraightRunTravelsTheLaggedClosedForm) {
  const RobotCase robot = GetParam()();
  const std::unique_ptr<Scene> scene = MakeScene(robot, DriveMode::kPlanar);
  const double c = 0.4 / robot.spec.wheel_radius_m;
  // The lag's factor, from the first step's response.
  Drive(*scene, c, c, 1);
  const double a = scene->LeftWheelAngleRad() / 0.01 / c;
  ASSERT_GT(a, 0.1);
  ASSERT_LT(a, 1.0);
  Drive(*scene, c, c, 299);
  const double phi = LaggedAngle(c, 0.01, a, 300);
  EXPECT_NEAR(scene->LeftWheelAngleRad(), phi, 1e-9);
  EXPECT_NEAR(scene->RightWheelAngleRad(), phi, 1e-9);
  const msgs::Pose2D end = scene->TruePose();
  EXPECT_NEAR(end.x_m, robot.spec.wheel_radius_m * phi, 1e-9);
  EXPECT_NEAR(end.y_m, 0.0, 1e-12);
  EXPECT_NEAR(end.theta_rad, 0.0, 1e-12);
  EXPECT_NEAR(scene->time_s(), 3.0, 1e-9);
  // The lag costs the distance of c (tau - dt) of wheel angle, i.e. the run is that much short.
  EXPECT_NEAR(robot.spec.wheel_radius_m * c * 3.0 - end.x_m,
              robot.spec.wheel_radius_m * c * 0.01 * (1.0 - a) / a, 1e-6);
}

TEST_P(PlanarDriveTest, SpotTurnTurnsTheLaggedClosedForm) {
  const RobotCase robot = GetParam()();
  const std::unique_ptr<Scene> scene = MakeScene(robot, DriveMode::kPlanar);
  const double r = robot.spec.wheel_radius_m, b = robot.spec.track_m;
  const double c = 1.0 * b / 2.0 / r;  // 1 rad/s
  Drive(*scene, -c, c, 1);
  const double a = scene->RightWheelAngleRad() / 0.01 / c;
  ASSERT_GT(a, 0.1);
  ASSERT_LT(a, 1.0);
  Drive(*scene, -c, c, 199);
  const double phi = LaggedAngle(c, 0.01, a, 200);
  EXPECT_NEAR(scene->RightWheelAngleRad(), phi, 1e-9);
  EXPECT_NEAR(scene->LeftWheelAngleRad(), -phi, 1e-9);
  const msgs::Pose2D end = scene->TruePose();
  EXPECT_NEAR(end.theta_rad, 2.0 * r * phi / b, 1e-9);
  EXPECT_NEAR(std::hypot(end.x_m, end.y_m), 0.0, 1e-12);  // about the axle midpoint
}

// The same command step on the floor (MuJoCo's contacts) and in the planar drive: the wheels turn
// alike (the lag is the servo's, with the inertia derived in planar_drive.h), within 1 % from the
// 10th step on. Measured (P3-DX): r x wheel angle after 10 steps 36.35 mm planar vs 36.45 mm on
// the floor, after 2 s 796.350 vs 796.357 mm. On the floor the body slips behind its wheels while
// it accelerates (13.1 mm in the first 0.2 s, 13.7 mm after 2 s; Magellan 13.2 mm after 2 s): that
// slip the planar drive does not model.
TEST_P(PlanarDriveTest, WheelsAnswerACommandStepAsOnTheFloor) {
  const RobotCase robot = GetParam()();
  const double r = robot.spec.wheel_radius_m;
  const double c = 0.4 / r;
  std::vector<double> planar, contact;
  for (const DriveMode mode : {DriveMode::kPlanar, DriveMode::kContact}) {
    const std::unique_ptr<Scene> scene = MakeScene(robot, mode);
    std::vector<double>& out = mode == DriveMode::kPlanar ? planar : contact;
    Drive(*scene, 0.0, 0.0, 50);  // settled on the floor
    const double phi0 = scene->LeftWheelAngleRad();
    for (const int steps : {10, 10, 180}) {
      Drive(*scene, c, c, steps);
      out.push_back(r * (scene->LeftWheelAngleRad() - phi0));
    }
  }
  EXPECT_NEAR(planar[0] / contact[0], 1.0, 0.01) << planar[0] << " vs " << contact[0];
  EXPECT_NEAR(planar[1] / contact[1], 1.0, 0.01) << planar[1] << " vs " << contact[1];
  EXPECT_NEAR(planar[2] / contact[2], 1.0, 1e-4) << planar[2] << " vs " << contact[2];
}

// E_d: a larger right wheel curves the true path left on the exact arc, while the wheel angles
// (what the encoders count, with the nominal radius) say straight.
TEST_P(PlanarDriveTest, WheelDiameterRatioBendsTheTruthAsTheClosedFormSays) {
  const RobotCase robot = GetParam()();
  const std::unique_ptr<Scene> scene =
      MakeScene(robot, DriveMode::kPlanar, false, {.wheel_diameter_ratio = 1.01});
  const WheelGeometry g = scene->wheel_geometry();
  const double c = 0.4 / robot.spec.wheel_radius_m;
  Drive(*scene, c, c, 1000);
  const double phi = scene->LeftWheelAngleRad();
  EXPECT_DOUBLE_EQ(scene->RightWheelAngleRad(), phi);  // the encoders: straight ahead
  const msgs::Pose2D end = scene->TruePose();
  const double heading = (g.right_radius_m - g.left_radius_m) * phi / g.track_m;
  EXPECT_NEAR(end.theta_rad, heading, 1e-9);
  const double curvature = 2.0 * (g.right_radius_m - g.left_radius_m) /
                           (g.track_m * (g.right_radius_m + g.left_radius_m));
  EXPECT_NEAR(end.y_m, (1.0 - std::cos(heading)) / curvature, 1e-9);
  EXPECT_NEAR(end.x_m, std::sin(heading) / curvature, 1e-9);
}

// E_b: a wider track turns the truth 1 / E_b of what the encoders (nominal track) say.
TEST_P(PlanarDriveTest, TrackRatioUnderTurnsByExactlyTheRatio) {
  const RobotCase robot = GetParam()();
  const double e_b = 1.03;
  const std::unique_ptr<Scene> scene =
      MakeScene(robot, DriveMode::kPlanar, false, {.track_ratio = e_b});
  const double r = robot.spec.wheel_radius_m, b = robot.spec.track_m;
  const double c = 1.0 * b / 2.0 / r;
  Drive(*scene, -c, c, 628);
  const double encoder_heading = r * (scene->RightWheelAngleRad() - scene->LeftWheelAngleRad()) / b;
  EXPECT_NEAR(msgs::WrapAngle(scene->TruePose().theta_rad - encoder_heading / e_b), 0.0, 1e-9);
}

// Driven into a wall, the robot stops with its bumper ring touching it, the panels facing the wall
// pressed; backing off releases them.
TEST_P(PlanarDriveTest, DriveIntoAWallStopsAtTheWallWithTheBumperPressed) {
  const RobotCase robot = GetParam()();
  const std::unique_ptr<Scene> scene = MakeScene(robot, DriveMode::kPlanar, true);
  const BumperSensor bumpers(*scene);
  EXPECT_TRUE(scene->PlanarContactBearings().empty());
  const double w = 0.2 / robot.spec.wheel_radius_m;
  double wheel_at_contact = -1.0;
  scene->SetWheelSpeeds({w, w});
  for (int i = 0; i < 600; ++i) {
    scene->Step();
    if (wheel_at_contact < 0.0 && !scene->PlanarContactBearings().empty()) {
      wheel_at_contact = scene->LeftWheelAngleRad();
    }
  }
  // The footprint's front: the ring's farthest vertex ahead (P3-DX 0.218 m; Magellan ~0.211 m).
  double front_m = 0.0;
  {
    const std::unique_ptr<Scene> probe = MakeScene(robot, DriveMode::kPlanar, true);
    const mjModel* m = probe->model();
    const int ring = mj_name2id(m, mjOBJ_GEOM, "bumper_ring");
    const int mesh = m->geom_dataid[ring];
    const mjData* d = probe->data();
    for (int i = 0; i < m->mesh_vertnum[mesh]; ++i) {
      const float* v = m->mesh_vert + 3 * (m->mesh_vertadr[mesh] + i);
      const mjtNum* x = d->geom_xpos + 3 * ring;
      const mjtNum* r = d->geom_xmat + 9 * ring;
      front_m = std::max(front_m, x[0] + r[0] * v[0] + r[1] * v[1] + r[2] * v[2]);
    }
  }
  EXPECT_NEAR(scene->TruePose().x_m, 1.0 - front_m, 1e-5);
  EXPECT_NEAR(scene->TruePose().y_m, 0.0, 1e-12);
  // The wheels stalled with the robot: they turned no more than the last step's fraction after
  // the contact.
  EXPECT_NEAR(scene->LeftWheelAngleRad(), wheel_at_contact, w * 0.01);
  const msgs::Bumpers pressed = bumpers.Sample(*scene);
  // One wall, one contact point (the footprint's nearest): the panel facing the wall, alone.
  const int front = bumpers.PanelAtBearing(0.0);
  for (int i = 0; i < bumpers.panel_count(); ++i) EXPECT_EQ(pressed.pressed[i], i == front) << i;
  Drive(*scene, -w, -w, 100);
  const msgs::Bumpers released = bumpers.Sample(*scene);
  for (bool p : released.pressed) EXPECT_FALSE(p);
  EXPECT_LT(scene->TruePose().x_m, 1.0 - front_m - 0.1);
}

// Pressed against a wall a robot still turns on the spot: its corners swing into the wall, the
// wall pushes it straight back (slip), and the turn is the open floor's closed form. The base
// never goes into the wall, moves only away from it (y stays 0: the push is along the wall's
// normal) and by no more than the footprint's reach beyond its front.
TEST_P(PlanarDriveTest, PressedAgainstAWallItStillTurnsTheSpotTurnClosedForm) {
  const RobotCase robot = GetParam()();
  const std::unique_ptr<Scene> scene = MakeScene(robot, DriveMode::kPlanar, true);
  PlanarObstacles obstacles(scene->model(), scene->data(), scene->base_body_id(), robot.mjcf);
  double front_m = 0.0;
  for (std::size_t i = 0; i < obstacles.footprint_xy().size(); i += 2) {
    front_m = std::max(front_m, obstacles.footprint_xy()[i]);
  }
  const double r = robot.spec.wheel_radius_m, b = robot.spec.track_m;
  Drive(*scene, 0.2 / r, 0.2 / r, 600);  // into the wall
  Drive(*scene, 0.0, 0.0, 200);          // the wheels come to rest
  const msgs::Pose2D at_wall = scene->TruePose();
  ASSERT_NEAR(at_wall.x_m, 1.0 - front_m, 1e-5);
  const double phi_left0 = scene->LeftWheelAngleRad(), phi_right0 = scene->RightWheelAngleRad();
  const double c = 1.0 * b / 2.0 / r;  // 1 rad/s, turning left
  Drive(*scene, -c, c, 1);
  const double a = (scene->RightWheelAngleRad() - phi_right0) / 0.01 / c;
  ASSERT_GT(a, 0.1);
  ASSERT_LT(a, 1.0);
  double max_x = at_wall.x_m;
  for (int i = 1; i < 200; ++i) {
    Drive(*scene, -c, c, 1);
    const msgs::Pose2D pose = scene->TruePose();
    EXPECT_FALSE(obstacles.Overlaps(pose)) << "step " << i;
    EXPECT_NEAR(pose.y_m, 0.0, 1e-12);
    max_x = std::max(max_x, pose.x_m);
  }
  const double phi = LaggedAngle(c, 0.01, a, 200);
  EXPECT_NEAR(scene->RightWheelAngleRad() - phi_right0, phi, 1e-9);
  EXPECT_NEAR(scene->LeftWheelAngleRad() - phi_left0, -phi, 1e-9);
  const msgs::Pose2D end = scene->TruePose();
  EXPECT_NEAR(end.theta_rad, 2.0 * r * phi / b, 1e-9);
  EXPECT_GT(end.theta_rad, 1.5);  // it did turn, by most of 2 rad
  EXPECT_LE(max_x, at_wall.x_m + 1e-12);
  EXPECT_GE(end.x_m, 1.0 - obstacles.reach_m() - 1e-9);
  if (robot.mjcf == "p3dx.xml") {
    // The P3-DX's long rear swings past the wall: it was pushed back by several centimetres.
    EXPECT_LT(end.x_m, at_wall.x_m - 0.02);
  }
}

// With unequal wheels (E_d 1.05) driven straight into a wall and pressed on, the robot turns only
// as its wheels do: each step's change of heading is the true radii's differential turn of the
// wheel angles the step added, (r_R dphi_R - r_L dphi_L) / b, as on open floor. The common part
// of the wheels' motion is what the wall stops; it must not turn the robot while the wheels,
// stopped with it, report no turn (the odometry would see a heading change it cannot explain).
TEST_P(PlanarDriveTest, PressedAgainstAWallUnequalWheelsTurnTheRobotOnlyAsTheyTurn) {
  const RobotCase robot = GetParam()();
  const std::unique_ptr<Scene> scene =
      MakeScene(robot, DriveMode::kPlanar, true, {.wheel_diameter_ratio = 1.05});
  const WheelGeometry g = scene->wheel_geometry();
  ASSERT_GT(g.right_radius_m, g.left_radius_m * 1.04);
  const double c = 0.2 / robot.spec.wheel_radius_m;
  Drive(*scene, c, c, 600);  // into the wall (curving a little: the right wheel is larger)
  ASSERT_FALSE(scene->PlanarContactBearings().empty());
  double turned = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double theta0 = scene->TruePose().theta_rad;
    const double left0 = scene->LeftWheelAngleRad(), right0 = scene->RightWheelAngleRad();
    Drive(*scene, c, c, 1);  // pressed on
    const double wheels_rad = (g.right_radius_m * (scene->RightWheelAngleRad() - right0) -
                               g.left_radius_m * (scene->LeftWheelAngleRad() - left0)) /
                              g.track_m;
    EXPECT_NEAR(scene->TruePose().theta_rad - theta0, wheels_rad, 1e-12) << "step " << i;
    turned += scene->TruePose().theta_rad - theta0;
  }
  EXPECT_LT(std::abs(turned), 1e-4);  // stopped at the wall, so hardly turned
}

// The same against a round column (the disc's push: straight away from its centre): a P3-DX
// driven into a 0.1 m column dead ahead, then turned on the spot, turns the closed form and never
// overlaps the column.
TEST(PlanarDriveTest, PressedAgainstAColumnItStillTurns) {
  const std::unique_ptr<Scene> owned = MakeP3dxSceneAmong(
      "planar_drive_column",
      "    <geom name=\"column\" type=\"cylinder\" pos=\"0.6 0 0.5\" size=\"0.1 0.5\"/>\n");
  Scene& scene = *owned;
  PlanarObstacles obstacles(scene.model(), scene.data(), scene.base_body_id(), "p3dx.xml");
  const double r = robot::P3dxSpec().wheel_radius_m, b = robot::P3dxSpec().track_m;
  Drive(scene, 0.2 / r, 0.2 / r, 400);
  Drive(scene, 0.0, 0.0, 200);
  ASSERT_FALSE(scene.PlanarContactBearings().empty());  // at the column
  const double c = 1.0 * b / 2.0 / r;
  const double theta0 = scene.TruePose().theta_rad;
  for (int i = 0; i < 300; ++i) {
    Drive(scene, c, -c, 1);  // turning right
    EXPECT_FALSE(obstacles.Overlaps(scene.TruePose())) << "step " << i;
  }
  // 3 s at 1 rad/s less the lag's (tau - dt) x 1 rad/s: ~2.98 rad.
  EXPECT_LT(scene.TruePose().theta_rad - theta0, -2.9);
}

// A wall lying on its side (turned 90 deg about y, its sizes to match) and a capsule column are
// the prism and the disc the ground truth holds them as (docs/worlds.md), so the robot stops at
// their faces exactly as at the upright box and the cylinder they equal; the planar drive took
// both for their bounding discs and stopped 1.1 m (the wall) and 0.4 m (the capsule) short of
// what its laser saw, where the contact drive stops at the face.
TEST(PlanarDriveTest, AWallOnItsSideAndACapsuleStopTheRobotWhereTheirUprightTwinsDo) {
  const auto stop_x = [](const std::string& name, const std::string& geom) {
    const std::unique_ptr<Scene> scene = MakeP3dxSceneAmong(name, geom);
    const double w = 0.3 / robot::P3dxSpec().wheel_radius_m;
    Drive(*scene, w, w, 500);
    EXPECT_FALSE(scene->PlanarContactBearings().empty()) << name;  // stopped by the geom
    return scene->TruePose().x_m;
  };
  const double at_wall =
      stop_x("planar_drive_upright_wall",
             "    <geom name=\"wall\" type=\"box\" pos=\"1.025 0 0.5\" size=\"0.025 2 0.5\"/>\n");
  EXPECT_NEAR(stop_x("planar_drive_wall_on_its_side",
                     "    <geom name=\"wall\" type=\"box\" pos=\"1.025 0 0.5\" "
                     "size=\"0.5 2 0.025\" euler=\"0 90 0\"/>\n"),
              at_wall, 1e-9);
  const double at_cylinder =
      stop_x("planar_drive_cylinder",
             "    <geom name=\"post\" type=\"cylinder\" pos=\"1.1 0 0.5\" size=\"0.1 0.5\"/>\n");
  EXPECT_NEAR(stop_x("planar_drive_capsule",
                     "    <geom name=\"post\" type=\"capsule\" pos=\"1.1 0 0.5\" "
                     "size=\"0.1 0.4\"/>\n"),
              at_cylinder, 1e-9);
  EXPECT_GT(at_cylinder, 0.7);  // the post's face at x = 1 less the footprint's front
}

// A turn that the walls leave no room for (the footprint wedged between two walls closer than
// its reach) stays blocked, as before: nothing is pushed through a wall.
TEST(PlanarDriveTest, WedgedBetweenTwoWallsItCannotTurn) {
  const std::unique_ptr<Scene> owned = MakeP3dxSceneAmong(
      "planar_drive_wedge",
      "    <geom name=\"left\" type=\"box\" pos=\"0 0.26 0.5\" size=\"2 0.01 0.5\"/>\n"
      "    <geom name=\"right\" type=\"box\" pos=\"0 -0.26 0.5\" size=\"2 0.01 0.5\"/>\n");
  Scene& scene = *owned;
  PlanarObstacles obstacles(scene.model(), scene.data(), scene.base_body_id(), "p3dx.xml");
  ASSERT_GT(obstacles.reach_m(), 0.25);  // the corridor (0.5 m) is narrower than 2 x reach
  const double c = 1.0 * robot::P3dxSpec().track_m / 2.0 / robot::P3dxSpec().wheel_radius_m;
  Drive(scene, -c, c, 200);
  const msgs::Pose2D end = scene.TruePose();
  EXPECT_FALSE(obstacles.Overlaps(end));
  EXPECT_LT(std::abs(end.theta_rad), 1.0);  // stopped where its corners met both walls
  EXPECT_LT(std::abs(end.y_m), 0.25);
  Drive(scene, -c, c, 100);  // and stays stopped
  EXPECT_NEAR(scene.TruePose().theta_rad, end.theta_rad, 1e-6);
  EXPECT_FALSE(obstacles.Overlaps(scene.TruePose()));
}

// PushOut out of one box turned 30 deg or one disc, from random overlapping poses (shallow to the
// disc wholly inside the footprint, the footprint across the box): the pose ends clear, heading
// kept, moved by the minimum translation, that of brute force (180 directions, each bisected to
// the first clear distance; 2 deg apart, it overshoots the minimum by ~1 - cos(1 deg) = 1.5e-4).
TEST(PlanarDriveTest, PushOutMovesByTheMinimumTranslationOutOfATurnedBoxOrADisc) {
  const std::unique_ptr<Scene> owned = MakeP3dxSceneAmong(
      "planar_push_out",
      "    <geom name=\"box\" type=\"box\" pos=\"0 0 0.5\" size=\"0.4 0.05 0.5\" "
      "euler=\"0 0 30\"/>\n"
      "    <geom name=\"col\" type=\"cylinder\" pos=\"3 0 0.5\" size=\"0.12 0.5\"/>\n");
  Scene& scene = *owned;
  PlanarObstacles obstacles(scene.model(), scene.data(), scene.base_body_id(), "p3dx.xml");
  std::uint64_t state = 12345;
  const auto uniform = [&state](double lo, double hi) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  int checked = 0;
  for (int k = 0; k < 400; ++k) {
    const double cx = k % 2 ? 3.0 : 0.0;
    const msgs::Pose2D pose{cx + uniform(-0.45, 0.45), uniform(-0.45, 0.45), uniform(-3.1, 3.1)};
    if (!obstacles.Overlaps(pose)) continue;
    ++checked;
    double brute = 1e9;
    for (int d = 0; d < 180; ++d) {
      const double a = d * std::numbers::pi / 90.0;
      double lo = 0.0, hi = 1.5;
      const auto at = [&](double t) {
        return msgs::Pose2D{pose.x_m + t * std::cos(a), pose.y_m + t * std::sin(a), pose.theta_rad};
      };
      if (obstacles.Overlaps(at(hi))) continue;
      for (int i = 0; i < 30; ++i) {
        const double mid = (lo + hi) / 2.0;
        (obstacles.Overlaps(at(mid)) ? lo : hi) = mid;
      }
      brute = std::min(brute, hi);
    }
    msgs::Pose2D out = pose;
    if (!obstacles.PushOut(&out, 10.0)) {
      ADD_FAILURE() << "not pushed out k=" << k;
      continue;
    }
    EXPECT_FALSE(obstacles.Overlaps(out));
    EXPECT_EQ(out.theta_rad, pose.theta_rad);
    const double moved = std::hypot(out.x_m - pose.x_m, out.y_m - pose.y_m);
    EXPECT_LE(moved, brute + 1e-6) << "k=" << k;
    EXPECT_GE(moved, brute * (1.0 - 2e-4) - 1e-6) << "k=" << k;
  }
  EXPECT_GT(checked, 100);
}

INSTANTIATE_TEST_SUITE_P(Robots, PlanarDriveTest, ::testing::Values(&P3dx, &MagellanPro));

TEST(PlanarDriveTest, P3dxReversingIntoAWallPressesOnlyRearPanels) {
  const std::unique_ptr<Scene> scene = MakeScene(P3dx(), DriveMode::kPlanar, true, {}, kPi);
  const BumperSensor bumpers(*scene);
  Drive(*scene, -2.0, -2.0, 600);
  const msgs::Bumpers b = bumpers.Sample(*scene);
  EXPECT_TRUE(b.pressed[7]);  // rear centre
  for (int i = 0; i < 5; ++i) EXPECT_FALSE(b.pressed[i]) << "front panel " << i;
  // The rear of the ring (x = -0.307 in the robot frame) at the wall.
  EXPECT_NEAR(scene->TruePose().x_m, 1.0 - 0.307, 1e-5);
}

// A wall-following run in the office never puts the footprint into a wall, and its sonar and
// laser see a level robot.
TEST(PlanarDriveTest, OfficeWallFollowingNeverOverlapsAWall) {
  const std::string yaml =
      "name: planar\nseed: 1\nduration_s: 60\nworld: worlds/office.xml\nrobot: {model: p3dx}\n"
      "controller: {type: wall_following, sensor: sonar, side: left, distance_m: 0.6}\n"
      "sensors: {sonar: {rate_hz: 10}, bumpers: {}, encoders: {}}\n"
      "physics: {drive: planar}\n";
  const ExperimentConfig config = ParseExperimentConfig(yaml, "planar.yaml", testing::SourceRoot());
  ASSERT_EQ(config.physics.drive, DriveMode::kPlanar);
  ExperimentRunner runner(config);
  runner.Run();
  const RunRecord& record = runner.record();
  ASSERT_GT(record.trajectory.size(), 500u);
  Scene& scene = runner.mutable_scene();
  const mjModel* m = scene.model();
  const int base = scene.base_body_id();
  PlanarObstacles obstacles(m, scene.data(), base, "p3dx.xml");
  double path_m = 0.0;
  for (std::size_t i = 0; i < record.trajectory.size(); ++i) {
    EXPECT_FALSE(obstacles.Overlaps(record.trajectory[i].truth))
        << "t = " << record.trajectory[i].time_s;
    if (i > 0) {
      path_m += std::hypot(record.trajectory[i].truth.x_m - record.trajectory[i - 1].truth.x_m,
                           record.trajectory[i].truth.y_m - record.trajectory[i - 1].truth.y_m);
    }
  }
  EXPECT_GT(path_m, 10.0);  // it went round the office rather than sitting at a wall
}

// The planar drive places nothing after a step; a base site's pose is computed from qpos, the
// same as after mj_kinematics (data()).
TEST(PlanarDriveTest, SitePosesAfterAStepAreTheKinematicsOnes) {
  const std::unique_ptr<Scene> scene = MakeScene(P3dx(), DriveMode::kPlanar);
  Drive(*scene, 3.0, 5.0, 137);
  const int laser = *scene->FindSite("laser");
  const Eigen::Isometry3d lazy = scene->SitePoseInWorld(laser);
  scene->data();
  const Eigen::Isometry3d placed = scene->SitePoseInWorld(laser);
  EXPECT_LT((lazy.translation() - placed.translation()).norm(), 1e-12);
  EXPECT_LT((lazy.linear() - placed.linear()).norm(), 1e-12);
  EXPECT_GT(placed.translation().head<2>().norm(), 0.1);  // it did move
  EXPECT_EQ(lazy.linear()(2, 0), 0.0);                    // exactly level
}

// A robot whose footprint starts a step already in a wall (a spawn within the setup check's 1 mm
// tolerance, or PlaceRobot) cannot drive on through it; it can back out.
TEST(PlanarDriveTest, StartingInAWallItCannotDriveThroughButBacksOut) {
  const std::unique_ptr<Scene> scene = MakeScene(P3dx(), DriveMode::kPlanar, true);
  const PlanarObstacles probe(scene->model(), scene->data(), scene->base_body_id(), "p3dx.xml");
  double front_m = 0.0;
  for (std::size_t i = 0; i < probe.footprint_xy().size(); i += 2) {
    front_m = std::max(front_m, probe.footprint_xy()[i]);
  }
  const double x0 = 1.0 - front_m + 0.5e-3;  // the ring 0.5 mm into the wall
  scene->PlaceRobot({x0, 0.0, 0.0});
  Drive(*scene, 4.0, 4.0, 300);
  EXPECT_LE(scene->TruePose().x_m, x0);
  Drive(*scene, 4.0, 3.0, 100);  // curving into it is no better
  EXPECT_LE(scene->TruePose().x_m, x0 + 1e-9);
  Drive(*scene, -4.0, -4.0, 100);
  EXPECT_LT(scene->TruePose().x_m, x0 - 0.1);
}

// A NaN or huge wheel command does what mj_step does with it: every control is zero for the step
// and mjWARN_BADCTRL is raised; the robot brakes rather than its pose becoming NaN.
TEST(PlanarDriveTest, ABadCommandIsZeroAsInMujoco) {
  for (const DriveMode drive : {DriveMode::kContact, DriveMode::kPlanar}) {
    const std::unique_ptr<Scene> scene = MakeScene(P3dx(), drive);
    Drive(*scene, 5.0, 5.0, 100);
    const double x_moving = scene->TruePose().x_m;
    Drive(*scene, std::nan(""), 5.0, 300);
    const msgs::Pose2D end = scene->TruePose();
    EXPECT_TRUE(std::isfinite(end.x_m) && std::isfinite(end.theta_rad)) << ToString(drive);
    EXPECT_GT(end.x_m, x_moving) << ToString(drive);        // it coasted a little
    EXPECT_LT(end.x_m, x_moving + 0.1) << ToString(drive);  // and stopped
    const double wheel = scene->LeftWheelAngleRad();
    Drive(*scene, std::nan(""), 5.0, 50);
    EXPECT_NEAR(scene->LeftWheelAngleRad(), wheel, 1e-2) << ToString(drive);  // at rest
    EXPECT_GT(scene->stepped_data()->warning[mjWARN_BADCTRL].number, 0) << ToString(drive);
  }
}

// After planar steps data() is what mj_forward's position stage gives the renderers: subtree_com
// (the viewer's follow camera tracks it), cameras and lights, besides the bodies and geoms.
TEST(PlanarDriveTest, DataAfterStepsHasTheForwardPositionsForTheRenderers) {
  const std::unique_ptr<Scene> scene = MakeScene(P3dx(), DriveMode::kPlanar);
  Drive(*scene, 3.0, 5.0, 137);
  const mjModel* m = scene->model();
  const mjData* lazy = scene->data();
  MjDataPtr forward(mj_copyData(nullptr, m, lazy));
  mj_forward(m, forward.get());
  for (int i = 0; i < 3 * m->nbody; ++i) {
    EXPECT_NEAR(lazy->xpos[i], forward->xpos[i], 1e-12) << i;
    EXPECT_NEAR(lazy->subtree_com[i], forward->subtree_com[i], 1e-12) << i;
  }
  for (int i = 0; i < 3 * m->ncam; ++i) EXPECT_NEAR(lazy->cam_xpos[i], forward->cam_xpos[i], 1e-12);
  for (int i = 0; i < 3 * m->nlight; ++i) {
    EXPECT_NEAR(lazy->light_xpos[i], forward->light_xpos[i], 1e-12);
  }
  EXPECT_GT(std::hypot(lazy->subtree_com[3 * scene->base_body_id()],
                       lazy->subtree_com[3 * scene->base_body_id() + 1]),
            0.1);  // it did move
}

// physics.drive: planar needs the robot's bumper_ring (its footprint): without it, one line naming
// the robot file and the geom; the contact drive does not need it.
TEST(PlanarDriveTest, ARobotWithoutABumperRingIsAOneLineErrorNamingItsFile) {
  std::ifstream in(testing::SourceRoot() / "models" / "p3dx.xml");
  std::stringstream text;
  text << in.rdbuf();
  std::string xml = text.str();
  const std::string ring = "name=\"bumper_ring\"";
  ASSERT_NE(xml.find(ring), std::string::npos);
  xml.replace(xml.find(ring), ring.size(), "name=\"ring\"");
  const std::filesystem::path robot =
      testing::WriteFile(testing::MakeTempDir("planar_no_ring") / "p3dx_no_ring.xml", xml);
  SceneOptions options;
  options.world_mjcf = World(false);
  options.robot_mjcf = robot;
  EXPECT_NO_THROW(Scene{options});
  options.drive = DriveMode::kPlanar;
  try {
    Scene scene(options);
    ADD_FAILURE() << "a planar scene without a bumper_ring";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("p3dx_no_ring.xml"), std::string::npos) << what;
    EXPECT_NE(what.find("bumper_ring"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(PlanarDriveTest, AnInvalidDriveIsAOneLineErrorNamingTheField) {
  const std::string yaml =
      "name: x\nworld: worlds/hall.xml\nrobot: {model: p3dx}\nphysics: {drive: kinematic}\n";
  try {
    ParseExperimentConfig(yaml, "x.yaml", testing::SourceRoot());
    ADD_FAILURE() << "accepted drive: kinematic";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("physics.drive"), std::string::npos) << what;
    EXPECT_NE(what.find("expected contact or planar, got 'kinematic'"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_EQ(ParseDriveMode("planar"), DriveMode::kPlanar);
  EXPECT_EQ(ToString(ParseDriveMode("contact")), "contact");
}

}  // namespace
}  // namespace plywood::sim
