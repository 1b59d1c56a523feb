#include "robot/control/wall_following_controller.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "robot/drive/diff_drive_kinematics.h"

namespace plywood::robot {
namespace {

constexpr double kDt = 0.01;
constexpr double kDeg = std::numbers::pi / 180.0;

// An infinite wall x = c (vertical) or y = c.
struct Wall {
  bool vertical;
  double c_m;
};

// Range along a ray from (x, y) at world angle a to the nearest wall, or +inf.
double CastRay(const std::vector<Wall>& walls, double x, double y, double a) {
  double range = std::numeric_limits<double>::infinity();
  for (const Wall& wall : walls) {
    const double along = wall.vertical ? std::cos(a) : std::sin(a);
    const double gap = wall.vertical ? wall.c_m - x : wall.c_m - y;
    if (std::abs(along) < 1e-12) continue;
    const double t = gap / along;
    if (t > 0.0) range = std::min(range, t);
  }
  return range;
}

std::vector<msgs::Pose2D> P3dxSonarPoses() {
  // models/p3dx.xml, sites sonar_0..sonar_15.
  const double d[16][3] = {
      {0.069, 0.136, 90},    {0.114, 0.119, 50},     {0.148, 0.078, 30},     {0.166, 0.027, 10},
      {0.166, -0.027, -10},  {0.148, -0.078, -30},   {0.114, -0.119, -50},   {0.069, -0.136, -90},
      {-0.157, -0.136, -90}, {-0.203, -0.119, -130}, {-0.237, -0.078, -150}, {-0.255, -0.027, -170},
      {-0.255, 0.027, 170},  {-0.237, 0.078, 150},   {-0.203, 0.119, 130},   {-0.157, 0.136, 90}};
  std::vector<msgs::Pose2D> poses;
  for (const auto& p : d) poses.push_back({p[0], p[1], p[2] * kDeg});
  return poses;
}

std::vector<msgs::Pose2D> MagellanSonarPoses() {
  std::vector<msgs::Pose2D> poses;
  for (int i = 0; i < 16; ++i) {
    const double a = i * 22.5 * kDeg;
    poses.push_back({0.203 * std::cos(a), 0.203 * std::sin(a), a});
  }
  return poses;
}

// Ideal sonar: each transducer reports the range along its axis (0.15 - 5 m).
msgs::RangeRing Sonar(const std::vector<Wall>& walls, const std::vector<msgs::Pose2D>& X_RS,
                      const msgs::Pose2D& X_WR) {
  msgs::RangeRing ring;
  ring.range_min_m = 0.15;
  ring.range_max_m = 5.0;
  for (const msgs::Pose2D& pose : X_RS) {
    const msgs::Pose2D X_WS = X_WR * pose;
    const double r = CastRay(walls, X_WS.x_m, X_WS.y_m, X_WS.theta_rad);
    ring.readings.push_back({pose, r, r >= ring.range_min_m && r <= ring.range_max_m});
  }
  return ring;
}

// SICK-like scan: 181 beams over 180 deg, 8 m, mounted 21 mm ahead of the centre.
msgs::LaserScan Laser(const std::vector<Wall>& walls, const msgs::Pose2D& X_WR) {
  msgs::LaserScan scan;
  scan.angle_min_rad = -std::numbers::pi / 2.0;
  scan.angle_increment_rad = kDeg;
  scan.range_min_m = 0.02;
  scan.range_max_m = 8.0;
  scan.X_RS = {0.021, 0.0, 0.0};
  const msgs::Pose2D X_WS = X_WR * scan.X_RS;
  for (int i = 0; i < 181; ++i) {
    const double r = CastRay(walls, X_WS.x_m, X_WS.y_m, X_WS.theta_rad + scan.BeamAngleRad(i));
    scan.ranges_m.push_back(std::min(r, scan.range_max_m));
  }
  return scan;
}

struct Result {
  msgs::Pose2D X_WR;
  double closest_wall_m = std::numeric_limits<double>::infinity();
};

Result RunClosedLoop(WallFollowingController& controller, const DiffDriveSpec& spec,
                     const std::vector<Wall>& walls, const std::vector<msgs::Pose2D>& sonar_poses,
                     bool laser, msgs::Pose2D X_WR, double time_s) {
  Result result;
  for (int i = 0; i * kDt < time_s; ++i) {
    msgs::RangeRing ring = Sonar(walls, sonar_poses, X_WR);
    msgs::LaserScan scan = Laser(walls, X_WR);
    ring.time_s = scan.time_s = i * kDt;
    ControllerInput input{i * kDt, X_WR};
    if (laser) {
      input.laser = &scan;
    } else {
      input.sonar = &ring;
    }
    const msgs::WheelSpeedCommand command = controller.Update(input);
    EXPECT_LE(std::abs(command.left_rad_s), spec.max_wheel_speed_rad_s);
    EXPECT_LE(std::abs(command.right_rad_s), spec.max_wheel_speed_rad_s);
    const BodyTwist twist = WheelSpeedsToTwist(spec, command);
    X_WR = IntegrateArc(X_WR, twist.linear_m_s * kDt, twist.angular_rad_s * kDt);
    for (const Wall& wall : walls) {
      result.closest_wall_m = std::min(result.closest_wall_m,
                                       std::abs((wall.vertical ? X_WR.x_m : X_WR.y_m) - wall.c_m));
    }
  }
  result.X_WR = X_WR;
  return result;
}

TEST(WallFollowingControllerTest, SonarLeftWallConvergesToTheSetDistance) {
  const DiffDriveSpec spec = P3dxSpec();
  WallFollowingController controller(spec, WallFollowingOptions{});
  const Result r = RunClosedLoop(controller, spec, {{false, 1.0}}, P3dxSonarPoses(), false,
                                 {0.0, 0.0, 0.3}, 40.0);
  EXPECT_NEAR(r.X_WR.y_m, 1.0 - 0.5, 1e-3);
  EXPECT_NEAR(r.X_WR.theta_rad, 0.0, 0.1 * kDeg);
  EXPECT_GT(r.X_WR.x_m, 8.0);  // it kept driving forward at about 0.25 m/s
  ASSERT_TRUE(controller.wall().has_value());
  EXPECT_NEAR(controller.wall()->distance_m, 0.5, 1e-3);
  EXPECT_NEAR(controller.wall()->angle_rad, 0.0, 0.1 * kDeg);
}

TEST(WallFollowingControllerTest, SonarRightWallOnAMagellanPro) {
  const DiffDriveSpec spec = MagellanProSpec();
  WallFollowingOptions options;
  options.side = WallSide::kRight;
  options.distance_m = 0.7;
  WallFollowingController controller(spec, options);
  const Result r = RunClosedLoop(controller, spec, {{false, -1.0}}, MagellanSonarPoses(), false,
                                 {0.0, 0.1, -0.4}, 40.0);
  EXPECT_NEAR(r.X_WR.y_m, -1.0 + 0.7, 1e-3);
  EXPECT_NEAR(r.X_WR.theta_rad, 0.0, 0.1 * kDeg);
  EXPECT_GT(r.X_WR.x_m, 8.0);
}

TEST(WallFollowingControllerTest, LaserFindsAndFollowsADistantWall) {
  const DiffDriveSpec spec = P3dxSpec();
  WallFollowingOptions options;
  options.sensor = WallSensor::kLaser;
  WallFollowingController controller(spec, options);
  // Wall 1.8 m away on the left, robot pointing slightly away from it.
  const Result r =
      RunClosedLoop(controller, spec, {{false, 1.0}}, {}, true, {0.0, -0.8, -0.2}, 50.0);
  EXPECT_NEAR(r.X_WR.y_m, 0.5, 1e-3);
  EXPECT_NEAR(r.X_WR.theta_rad, 0.0, 0.1 * kDeg);
}

TEST(WallFollowingControllerTest, TurnsAwayAtAnInnerCorner) {
  // Left wall y = 1 meets a wall x = 4 ahead: the robot turns right and follows x = 4 downwards.
  const DiffDriveSpec spec = P3dxSpec();
  WallFollowingController controller(spec, WallFollowingOptions{});
  const Result r = RunClosedLoop(controller, spec, {{false, 1.0}, {true, 4.0}}, P3dxSonarPoses(),
                                 false, {0.0, 0.5, 0.0}, 60.0);
  EXPECT_NEAR(r.X_WR.x_m, 4.0 - 0.5, 2e-3);
  EXPECT_NEAR(r.X_WR.theta_rad, -std::numbers::pi / 2.0, 0.2 * kDeg);
  EXPECT_LT(r.X_WR.y_m, -3.0);
  EXPECT_GT(r.closest_wall_m, 0.3);  // never closer than the P3-DX's half length
}

// Echoes older than wall_memory_s count only for the way ahead (CollectPoints sorts them about an
// anchor pose and re-sorts when the pose moves away): one echo heard 3 s ago must block the lane
// from any pose that has it close ahead, after small moves and after jumps of the estimate alike,
// and must not block it from poses that have it behind or beyond the reach.
TEST(WallFollowingControllerTest, AnOldEchoAheadBlocksTheLaneFromAnyPose) {
  const DiffDriveSpec spec = P3dxSpec();
  const WallFollowingOptions options;  // front_clearance_m 0.8, memory 10 s, wall memory 2 s
  WallFollowingController controller(spec, options);
  // One transducer facing ahead hears a post 3 m ahead of the origin at t = 0; later rings are
  // silent (specular misses), so the post is remembered, not seen again.
  msgs::RangeRing ring;
  ring.range_min_m = 0.15;
  ring.range_max_m = 5.0;
  ring.readings.push_back({{0.0, 0.0, 0.0}, 3.0, true});
  ControllerInput input{0.0, {0.0, 0.0, 0.0}, &ring};
  controller.Update(input);
  const msgs::WheelSpeedCommand turn_away =
      TwistToWheelSpeeds(spec, {0.0, -options.max_turn_rate_rad_s});
  ring.readings[0].echo = false;
  struct Case {
    double x_m, y_m, theta_rad;
    bool blocked;
  };
  // Each pose a tick of 20 ms later; a silent ring every fifth tick.
  const std::vector<Case> cases = {
      {2.5, 0.0, 0.0, true},      // 0.5 m ahead
      {2.52, 0.01, 0.0, true},    // within the anchor slack
      {2.55, -0.02, 0.05, true},  // beyond it
      {4.0, 0.0, 0.0, false},     // behind: clear, and nothing beside turns it
      {2.4, 0.1, 0.0, true},      // a jump back
      {2.4, 1.5, 0.0, false},     // beside, far off the lane and the window
      {3.0, -0.7, 1.0, false},    // beside, facing away from it
      {2.3, 0.0, 0.1, true},      // ahead again, slightly turned
      {-2.0, 0.0, 0.0, false},    // 5 m before it: beyond the reach
      {2.35, 0.05, -0.1, true},   // and back
      {3.02, -0.25, 0.0, false},  // beside in the lane, 2 cm behind
      {3.02, -0.25, 0.1, true},   // turned towards it by less than the anchor's turn: ahead
  };
  double t = 3.0;
  for (std::size_t i = 0; i < cases.size(); ++i, t += 0.02) {
    ring.time_s = std::floor(t * 5.0 + 1e-9) / 5.0;  // 5 Hz rings here, all after t = 2 s
    input = {t, {cases[i].x_m, cases[i].y_m, cases[i].theta_rad}, &ring};
    const msgs::WheelSpeedCommand command = controller.Update(input);
    if (cases[i].blocked) {
      EXPECT_EQ(command.left_rad_s, turn_away.left_rad_s) << "case " << i;
      EXPECT_EQ(command.right_rad_s, turn_away.right_rad_s) << "case " << i;
    } else {
      EXPECT_NE(command.left_rad_s, turn_away.left_rad_s) << "case " << i;
    }
  }
}

TEST(WallFollowingControllerTest, WaitsForDataAndFinishesAfterItsDuration) {
  const DiffDriveSpec spec = P3dxSpec();
  WallFollowingOptions options;
  options.duration_s = 2.0;
  WallFollowingController controller(spec, options);
  const msgs::WheelSpeedCommand none = controller.Update({0.0, {}});
  EXPECT_EQ(none.left_rad_s, 0.0);
  EXPECT_EQ(none.right_rad_s, 0.0);
  const msgs::RangeRing ring = Sonar({{false, 1.0}}, P3dxSonarPoses(), {});
  ControllerInput input{1.0, {}, &ring};
  controller.Update(input);
  input.time_s = 1.5;
  const msgs::WheelSpeedCommand moving = controller.Update(input);
  EXPECT_GT(moving.left_rad_s + moving.right_rad_s, 0.0);
  EXPECT_FALSE(controller.Finished());
  input.time_s = 2.0;
  EXPECT_EQ(controller.Update(input).left_rad_s, 0.0);
  EXPECT_TRUE(controller.Finished());
}

TEST(WallFollowingControllerTest, ParsesNames) {
  EXPECT_EQ(ParseWallSide("right"), WallSide::kRight);
  EXPECT_EQ(ParseWallSensor(ToString(WallSensor::kLaser)), WallSensor::kLaser);
  EXPECT_THROW(ParseWallSide("up"), std::invalid_argument);
  EXPECT_THROW(ParseWallSensor("ir"), std::invalid_argument);
}

void ExpectThrowsNaming(const WallFollowingOptions& options, const std::string& field) {
  try {
    WallFollowingController controller(P3dxSpec(), options);
    ADD_FAILURE() << "no exception for " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
  }
}

TEST(WallFollowingControllerTest, InvalidOptionsThrowNamingTheField) {
  auto with = [](auto change) {
    WallFollowingOptions options;
    change(options);
    return options;
  };
  ExpectThrowsNaming(with([](auto& o) { o.distance_m = 0; }), "distance_m");
  ExpectThrowsNaming(with([](auto& o) { o.speed_m_s = -1; }), "speed_m_s");
  ExpectThrowsNaming(with([](auto& o) { o.accel_m_s2 = 0; }), "accel_m_s2");
  ExpectThrowsNaming(with([](auto& o) { o.max_turn_rate_rad_s = 0; }), "max_turn_rate_rad_s");
  ExpectThrowsNaming(with([](auto& o) { o.distance_gain_rad_per_m = 0; }),
                     "distance_gain_rad_per_m");
  ExpectThrowsNaming(with([](auto& o) { o.angle_gain_per_s = NAN; }), "angle_gain_per_s");
  ExpectThrowsNaming(with([](auto& o) { o.max_approach_angle_rad = 2.0; }),
                     "max_approach_angle_rad");
  ExpectThrowsNaming(with([](auto& o) { o.side_window_rad = 0; }), "side_window_rad");
  ExpectThrowsNaming(with([](auto& o) { o.front_window_rad = 0; }), "front_window_rad");
  ExpectThrowsNaming(with([](auto& o) { o.max_wall_range_m = 0.4; }), "max_wall_range_m");
  ExpectThrowsNaming(with([](auto& o) { o.front_clearance_m = 0; }), "front_clearance_m");
  ExpectThrowsNaming(with([](auto& o) { o.lane_half_width_m = 0; }), "lane_half_width_m");
  ExpectThrowsNaming(with([](auto& o) { o.memory_s = -1; }), "memory_s");
  ExpectThrowsNaming(with([](auto& o) { o.wall_memory_s = 20; }), "wall_memory_s");
  ExpectThrowsNaming(with([](auto& o) { o.duration_s = -1; }), "duration_s");
}

// s54: the windows are half-angles compared through their cosines, so one beyond pi wrapped round:
// front_window_rad 7 ran byte-identical to 7 - 2 pi = 0.717 rad, exit 0.
TEST(WallFollowingControllerTest, AWindowWiderThanAHalfTurnIsRefused) {
  WallFollowingOptions options;
  options.front_window_rad = 7.0;
  ExpectThrowsNaming(options, "front_window_rad");
  options.front_window_rad = 0.35;
  options.side_window_rad = 4.0;
  ExpectThrowsNaming(options, "side_window_rad");
  options.side_window_rad = std::numbers::pi;  // every point on the side: still a window
  options.front_window_rad = std::numbers::pi;
  EXPECT_NO_THROW(WallFollowingController(P3dxSpec(), options));
}

}  // namespace
}  // namespace plywood::robot
