#include "robot/control/waypoint_controller.h"

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

struct Tick {
  msgs::Pose2D X_WR;
  BodyTwist twist;
  msgs::WheelSpeedCommand command;
};

// Closed loop with an ideal unicycle fed back a perfect pose.
std::vector<Tick> RunClosedLoop(Controller& controller, const DiffDriveSpec& spec,
                                msgs::Pose2D X_WR, double max_time_s) {
  std::vector<Tick> ticks;
  for (int i = 0; i * kDt < max_time_s && !controller.Finished(); ++i) {
    const msgs::WheelSpeedCommand command = controller.Update({i * kDt, X_WR});
    const BodyTwist twist = WheelSpeedsToTwist(spec, command);
    ticks.push_back({X_WR, twist, command});
    X_WR = IntegrateArc(X_WR, twist.linear_m_s * kDt, twist.angular_rad_s * kDt);
  }
  ticks.push_back({X_WR, {}, {}});
  return ticks;
}

double ClosestApproach(const std::vector<Tick>& ticks, const Waypoint& p) {
  double closest = std::numeric_limits<double>::infinity();
  for (const Tick& t : ticks) {
    closest = std::min(closest, std::hypot(t.X_WR.x_m - p.x_m, t.X_WR.y_m - p.y_m));
  }
  return closest;
}

WaypointOptions Zigzag() {
  WaypointOptions options;
  // Includes a waypoint straight behind the robot's heading and a sharp reversal.
  options.waypoints = {{2, 0}, {2, 2}, {0, 2}, {-1, -1}, {3, -1}, {3, -0.5}};
  return options;
}

TEST(WaypointControllerTest, VisitsEveryWaypointInOrderAndStopsOnTheLast) {
  const DiffDriveSpec spec = P3dxSpec();
  const WaypointOptions options = Zigzag();
  WaypointController controller(spec, options);
  const std::vector<Tick> ticks = RunClosedLoop(controller, spec, {0, 0, std::numbers::pi}, 300.0);
  ASSERT_TRUE(controller.Finished());
  EXPECT_EQ(controller.reached_count(), options.waypoints.size());

  // In order: the time of closest approach to each waypoint increases along the list.
  std::size_t previous_tick = 0;
  for (const Waypoint& p : options.waypoints) {
    EXPECT_LE(ClosestApproach(ticks, p), options.reach_tolerance_m) << p.x_m << ", " << p.y_m;
    std::size_t first_inside = ticks.size();
    for (std::size_t i = previous_tick; i < ticks.size(); ++i) {
      if (std::hypot(ticks[i].X_WR.x_m - p.x_m, ticks[i].X_WR.y_m - p.y_m) <=
          options.reach_tolerance_m) {
        first_inside = i;
        break;
      }
    }
    ASSERT_LT(first_inside, ticks.size()) << p.x_m << ", " << p.y_m;
    previous_tick = first_inside;
  }

  // Stops on the last waypoint, at rest: the last command before finishing is a crawl.
  const msgs::Pose2D& X_WF = ticks.back().X_WR;
  EXPECT_LT(std::hypot(X_WF.x_m - 3.0, X_WF.y_m + 0.5), 0.1 * options.reach_tolerance_m);
  EXPECT_LE(std::abs(ticks[ticks.size() - 2].twist.linear_m_s), options.accel_m_s2 * kDt + 1e-12);
  for (const Tick& t : ticks) {
    EXPECT_LE(std::abs(t.command.left_rad_s), spec.max_wheel_speed_rad_s);
    EXPECT_LE(std::abs(t.command.right_rad_s), spec.max_wheel_speed_rad_s);
    EXPECT_LE(t.twist.linear_m_s, options.speed_m_s + 1e-12);
    EXPECT_GE(t.twist.linear_m_s, 0.0);
    EXPECT_LE(std::abs(t.twist.angular_rad_s), options.max_turn_rate_rad_s + 1e-12);
  }
  EXPECT_EQ(controller.Update({1e3, X_WF}).left_rad_s, 0.0);
}

TEST(WaypointControllerTest, TurnsOnTheSpotTowardsAWaypointBehind) {
  const DiffDriveSpec spec = P3dxSpec();
  WaypointOptions options;
  options.waypoints = {{-3, 0}};
  WaypointController controller(spec, options);
  const std::vector<Tick> ticks = RunClosedLoop(controller, spec, {0, 0, 0.1}, 60.0);
  ASSERT_TRUE(controller.Finished());
  // Until the bearing error is below half the threshold the robot does not move off the spot.
  for (const Tick& t : ticks) {
    const double error = std::abs(msgs::WrapAngle(std::numbers::pi - t.X_WR.theta_rad));
    if (error < options.turn_in_place_above_rad / 2.0) break;
    EXPECT_EQ(t.twist.linear_m_s, 0.0);
    EXPECT_NEAR(std::hypot(t.X_WR.x_m, t.X_WR.y_m), 0.0, 1e-12);
  }
  EXPECT_NEAR(ticks.back().X_WR.x_m, -3.0, 0.1 * options.reach_tolerance_m);
  EXPECT_NEAR(ticks.back().X_WR.y_m, 0.0, 0.1 * options.reach_tolerance_m);
}

TEST(WaypointControllerTest, LoopsForever) {
  const DiffDriveSpec spec = MagellanProSpec();
  WaypointOptions options;
  options.waypoints = {{1, 0}, {1, 1}, {0, 1}, {0, 0}};
  options.loop = true;
  WaypointController controller(spec, options);
  const std::vector<Tick> ticks = RunClosedLoop(controller, spec, {}, 60.0);
  EXPECT_FALSE(controller.Finished());
  // Each lap is about 4 m plus slow corners; 60 s at 0.3 m/s covers at least two laps.
  EXPECT_GE(controller.reached_count(), 2 * options.waypoints.size());
  for (const Waypoint& p : options.waypoints) {
    EXPECT_LE(ClosestApproach(ticks, p), options.reach_tolerance_m);
  }
}

TEST(WaypointControllerTest, PassesSeveralWaypointsWithinReachAtOnce) {
  const DiffDriveSpec spec = P3dxSpec();
  WaypointOptions options;
  options.waypoints = {{0.01, 0}, {0.02, 0.01}, {1, 0}};
  WaypointController controller(spec, options);
  controller.Update({0.0, {}});
  EXPECT_EQ(controller.target_index(), 2u);
  EXPECT_EQ(controller.reached_count(), 2u);
}

void ExpectThrowsNaming(const WaypointOptions& options, const std::string& field) {
  try {
    WaypointController controller(P3dxSpec(), options);
    ADD_FAILURE() << "no exception for " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
  }
}

TEST(WaypointControllerTest, InvalidOptionsThrowNamingTheField) {
  auto with = [](auto change) {
    WaypointOptions options = Zigzag();
    change(options);
    return options;
  };
  ExpectThrowsNaming(with([](auto& o) { o.waypoints.clear(); }), "waypoints");
  ExpectThrowsNaming(with([](auto& o) { o.waypoints[1].y_m = NAN; }), "waypoints");
  ExpectThrowsNaming(with([](auto& o) { o.speed_m_s = 0; }), "speed_m_s");
  ExpectThrowsNaming(with([](auto& o) { o.max_turn_rate_rad_s = -1; }), "max_turn_rate_rad_s");
  ExpectThrowsNaming(with([](auto& o) { o.accel_m_s2 = INFINITY; }), "accel_m_s2");
  ExpectThrowsNaming(with([](auto& o) { o.heading_gain_per_s = 0; }), "heading_gain_per_s");
  ExpectThrowsNaming(with([](auto& o) { o.turn_in_place_above_rad = 0; }),
                     "turn_in_place_above_rad");
  ExpectThrowsNaming(with([](auto& o) { o.reach_tolerance_m = 0; }), "reach_tolerance_m");
}

}  // namespace
}  // namespace plywood::robot
