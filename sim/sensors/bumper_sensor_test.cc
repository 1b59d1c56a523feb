#include "sim/sensors/bumper_sensor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/world/scene.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim {
namespace {

// A floor and a 5 cm thick wall whose near face is the plane x = 1 (normal -x).
std::filesystem::path WallWorld() {
  return testing::WriteFile(testing::MakeTempDir("bumper_sensor") / "wall.xml", R"(<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <geom name="wall" type="box" pos="1.025 0 0.5" size="0.025 2 0.5"/>
  </worldbody>
</mujoco>
)");
}

Scene MakeSceneFacing(const std::string& robot, double theta_rad) {
  return Scene({.world_mjcf = WallWorld(),
                .robot_mjcf = testing::SourceRoot() / "models" / robot,
                .spawn = {.theta_rad = theta_rad},
                .timestep_s = 0.01});
}

std::vector<int> PressedPanels(const msgs::Bumpers& bumpers) {
  std::vector<int> pressed;
  for (std::size_t i = 0; i < bumpers.pressed.size(); ++i) {
    if (bumpers.pressed[i]) pressed.push_back(static_cast<int>(i));
  }
  return pressed;
}

// Drives with constant wheel speeds for `duration_s`; returns the panels ever pressed.
std::vector<bool> DriveAndWatch(Scene& scene, const BumperSensor& bumpers, double left_rad_s,
                                double right_rad_s, double duration_s) {
  std::vector<bool> ever(bumpers.panel_count(), false);
  scene.SetWheelSpeeds({left_rad_s, right_rad_s});
  const double end_s = scene.time_s() + duration_s;
  while (scene.time_s() < end_s) {
    scene.Step();
    const msgs::Bumpers b = bumpers.Sample(scene);
    for (int i = 0; i < bumpers.panel_count(); ++i) ever[i] = ever[i] || b.pressed[i];
  }
  return ever;
}

TEST(BumperSensorTest, ValidateNamesTheField) {
  EXPECT_NO_THROW(BumperSensorOptions{}.Validate());
  try {
    BumperSensorOptions{.rate_hz = 0.0}.Validate();
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("rate_hz:", 0), 0u) << e.what();
  }
}

TEST(BumperSensorTest, P3dxFrontPanelsPressAgainstAWallAndStopTheRobot) {
  Scene scene = MakeSceneFacing("p3dx.xml", 0.0);
  const BumperSensor bumpers(scene);
  ASSERT_EQ(bumpers.panel_count(), 10);
  const msgs::Bumpers at_rest = bumpers.Sample(scene);
  EXPECT_EQ(at_rest.pressed.size(), 10u);
  EXPECT_TRUE(PressedPanels(at_rest).empty());
  // 0.2 m/s: free for the first 0.78 m (front bumper at x = 0.218), then pushing into the wall.
  const double w = 0.2 / 0.0975;
  DriveAndWatch(scene, bumpers, w, w, 6.0);
  const std::vector<int> pressed = PressedPanels(bumpers.Sample(scene));
  EXPECT_NE(std::find(pressed.begin(), pressed.end(), 2), pressed.end());  // front centre
  for (int panel : pressed) EXPECT_LE(panel, 4) << "only front panels face the wall";
  // The bumper, not the chassis, met the wall, and it held the robot back.
  EXPECT_NEAR(scene.TruePose().x_m, 1.0 - 0.218, 0.01);
  // Backing off releases the switches.
  DriveAndWatch(scene, bumpers, -w, -w, 1.0);
  EXPECT_TRUE(PressedPanels(bumpers.Sample(scene)).empty());
}

TEST(BumperSensorTest, P3dxRearPanelPressesWhenReversingIntoAWall) {
  Scene scene = MakeSceneFacing("p3dx.xml", std::numbers::pi);
  const BumperSensor bumpers(scene);
  const double w = 0.2 / 0.0975;
  DriveAndWatch(scene, bumpers, -w, -w, 6.0);
  const std::vector<int> pressed = PressedPanels(bumpers.Sample(scene));
  EXPECT_NE(std::find(pressed.begin(), pressed.end(), 7), pressed.end());  // rear centre
  for (int panel : pressed) EXPECT_GE(panel, 5) << "only rear panels face the wall";
}

TEST(BumperSensorTest, MagellanPanelFacingTheWallPresses) {
  Scene scene = MakeSceneFacing("magellan_pro.xml", 0.0);
  const BumperSensor bumpers(scene);
  ASSERT_EQ(bumpers.panel_count(), 16);
  // 0.19 m/s; the front panel (x = 0.211) reaches the wall after 0.79 m.
  DriveAndWatch(scene, bumpers, 2.5, 2.5, 6.0);
  const std::vector<int> pressed = PressedPanels(bumpers.Sample(scene));
  ASSERT_FALSE(pressed.empty());
  EXPECT_NE(std::find(pressed.begin(), pressed.end(), 0), pressed.end());
  for (int panel : pressed) EXPECT_TRUE(panel <= 2 || panel >= 14) << panel;
  EXPECT_NEAR(scene.TruePose().x_m, 1.0 - 0.211, 0.01);
}

TEST(BumperSensorTest, PanelArcsAreCentredOnThePanels) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  Scene magellan = MakeSceneFacing("magellan_pro.xml", 0.0);
  const BumperSensor ring(magellan);
  for (int i = 0; i < 16; ++i) {
    // Panel i faces 22.5 i deg and owns +-11.25 deg around it.
    EXPECT_EQ(ring.PanelAtBearing((22.5 * i - 11.0) * kDeg), i);
    EXPECT_EQ(ring.PanelAtBearing((22.5 * i + 11.0) * kDeg), i);
  }
  Scene p3dx = MakeSceneFacing("p3dx.xml", 0.3);  // the robot's own heading does not matter
  const BumperSensor bumpers(p3dx);
  EXPECT_EQ(bumpers.PanelAtBearing(0.0), 2);
  EXPECT_EQ(bumpers.PanelAtBearing(std::numbers::pi), 7);
  EXPECT_EQ(bumpers.PanelAtBearing(-std::numbers::pi), 7);
  // Panel centres seen from the base origin: atan2(0.083, 0.182) = 24.5 deg and
  // atan2(0.150, 0.110) = 53.7 deg in front, 143.1 and 163.0 deg behind; arcs meet halfway
  // (12.3, 39.1, 98.4, 171.5 deg).
  EXPECT_EQ(bumpers.PanelAtBearing(12.0 * kDeg), 2);
  EXPECT_EQ(bumpers.PanelAtBearing(13.0 * kDeg), 3);
  EXPECT_EQ(bumpers.PanelAtBearing(-38.0 * kDeg), 1);
  EXPECT_EQ(bumpers.PanelAtBearing(-40.0 * kDeg), 0);
  EXPECT_EQ(bumpers.PanelAtBearing(98.0 * kDeg), 4);
  EXPECT_EQ(bumpers.PanelAtBearing(99.0 * kDeg), 5);
  EXPECT_EQ(bumpers.PanelAtBearing(-99.0 * kDeg), 9);
  EXPECT_EQ(bumpers.PanelAtBearing(172.0 * kDeg), 7);
  EXPECT_EQ(bumpers.PanelAtBearing(-170.0 * kDeg), 8);
}

// Places the robot with heading `theta_rad` so that it reaches `depth_m` into the wall (face
// x = 1) with its outermost point `reach_m` from the origin along +x, then runs collision.
void PlaceAgainstWall(Scene& scene, double theta_rad, double reach_m, double depth_m) {
  const mjModel* m = scene.model();
  mjData* d = scene.mutable_data();
  mjtNum* q = d->qpos + m->jnt_qposadr[m->body_jntadr[scene.base_body_id()]];
  q[0] = 1.0 - reach_m + depth_m;
  q[1] = 0.0;
  q[3] = std::cos(theta_rad / 2.0);
  q[4] = q[5] = 0.0;
  q[6] = std::sin(theta_rad / 2.0);
  mj_forward(m, d);
}

TEST(BumperSensorTest, MagellanPanelFacingAFlatWallIsTheOnlyOnePressed) {
  Scene scene = MakeSceneFacing("magellan_pro.xml", 0.0);
  const BumperSensor bumpers(scene);
  for (int i = 0; i < 16; ++i) {
    // Heading -22.5 i deg turns panel i (its face 0.211 m out) towards the wall.
    PlaceAgainstWall(scene, -22.5 * i * std::numbers::pi / 180.0, 0.211, 0.002);
    EXPECT_EQ(PressedPanels(bumpers.Sample(scene)), std::vector<int>{i}) << "panel " << i;
  }
}

TEST(BumperSensorTest, P3dxCentrePanelsFacingAFlatWallAreTheOnesPressed) {
  Scene scene = MakeSceneFacing("p3dx.xml", 0.0);
  const BumperSensor bumpers(scene);
  PlaceAgainstWall(scene, 0.0, 0.218, 0.002);  // front face at x = 0.218
  EXPECT_EQ(PressedPanels(bumpers.Sample(scene)), std::vector<int>{2});
  PlaceAgainstWall(scene, std::numbers::pi, 0.307, 0.002);  // rear face at x = -0.307
  EXPECT_EQ(PressedPanels(bumpers.Sample(scene)), std::vector<int>{7});
  PlaceAgainstWall(scene, 0.0, 0.218, -0.002);  // 2 mm short of the wall
  EXPECT_TRUE(PressedPanels(bumpers.Sample(scene)).empty());
}

TEST(BumperSensorTest, NothingPressesWhileDrivingInTheOpen) {
  for (const char* robot : {"p3dx.xml", "magellan_pro.xml"}) {
    Scene scene = MakeSceneFacing(robot, std::numbers::pi);  // away from the wall
    const BumperSensor bumpers(scene);
    for (bool p : DriveAndWatch(scene, bumpers, 3.0, 3.0, 1.0)) EXPECT_FALSE(p) << robot;
    for (bool p : DriveAndWatch(scene, bumpers, -3.0, 3.0, 2.0)) EXPECT_FALSE(p) << robot;
    for (bool p : DriveAndWatch(scene, bumpers, -3.0, -3.0, 0.5)) EXPECT_FALSE(p) << robot;
  }
}

}  // namespace
}  // namespace plywood::sim
