#include "robot/control/square_path_controller.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "robot/drive/diff_drive_kinematics.h"

namespace plywood::robot {
namespace {

constexpr double kDt = 0.01;
constexpr double kDeg = std::numbers::pi / 180.0;

struct Tick {
  double time_s;
  msgs::Pose2D X_WR;  // ground truth at the start of the tick
  msgs::WheelSpeedCommand command;
};

// Closed loop with an ideal unicycle: the commanded wheel speeds are held for one tick and
// integrated exactly. `estimate` maps the true pose to the pose fed back (identity by default).
std::vector<Tick> RunClosedLoop(
    Controller& controller, const DiffDriveSpec& spec, msgs::Pose2D X_WR, double max_time_s,
    const std::function<msgs::Pose2D(const msgs::Pose2D&)>& estimate = {}) {
  std::vector<Tick> ticks;
  for (int i = 0; i * kDt < max_time_s && !controller.Finished(); ++i) {
    const double t = i * kDt;
    ControllerInput input{t, estimate ? estimate(X_WR) : X_WR};
    const msgs::WheelSpeedCommand command = controller.Update(input);
    ticks.push_back({t, X_WR, command});
    const BodyTwist twist = WheelSpeedsToTwist(spec, command);
    X_WR = IntegrateArc(X_WR, twist.linear_m_s * kDt, twist.angular_rad_s * kDt);
  }
  ticks.push_back({ticks.size() * kDt, X_WR, {}});
  return ticks;
}

// Positions where the robot starts a spot turn (zero forward speed, non-zero yaw rate).
std::vector<msgs::Pose2D> TurnPoses(const std::vector<Tick>& ticks, const DiffDriveSpec& spec) {
  std::vector<msgs::Pose2D> poses;
  bool turning = false;
  for (const Tick& tick : ticks) {
    const BodyTwist twist = WheelSpeedsToTwist(spec, tick.command);
    const bool spot_turn = std::abs(twist.linear_m_s) < 1e-12 && std::abs(twist.angular_rad_s) > 0;
    if (spot_turn && !turning) poses.push_back(tick.X_WR);
    turning = spot_turn;
  }
  return poses;
}

struct Case {
  SquareDirection direction;
  msgs::Pose2D X_WR_start;
};

class SquarePathTest : public ::testing::TestWithParam<Case> {};

TEST_P(SquarePathTest, ReturnsToStartWithCornersOnTheSquare) {
  const DiffDriveSpec spec = P3dxSpec();
  SquarePathOptions options;
  options.direction = GetParam().direction;
  SquarePathController controller(spec, options);
  const msgs::Pose2D X_W0 = GetParam().X_WR_start;
  const std::vector<Tick> ticks = RunClosedLoop(controller, spec, X_W0, 200.0);
  ASSERT_TRUE(controller.Finished());

  const msgs::Pose2D& X_WF = ticks.back().X_WR;
  EXPECT_LT(std::hypot(X_WF.x_m - X_W0.x_m, X_WF.y_m - X_W0.y_m), 0.2e-3);
  EXPECT_LT(std::abs(msgs::WrapAngle(X_WF.theta_rad - X_W0.theta_rad)), 0.01 * kDeg);

  // Corners in the start frame: (4,0), (4,+-4), (0,+-4), (0,0); + for ccw (left turns).
  const double sign = GetParam().direction == SquareDirection::kCounterClockwise ? 1.0 : -1.0;
  const std::vector<msgs::Pose2D> X_0C = {{4, 0, 0}, {4, sign * 4, 0}, {0, sign * 4, 0}, {0, 0, 0}};
  const std::vector<msgs::Pose2D> turns = TurnPoses(ticks, spec);
  ASSERT_EQ(turns.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    const msgs::Pose2D expected = X_W0 * X_0C[k];
    EXPECT_NEAR(turns[k].x_m, expected.x_m, 0.2e-3) << "corner " << k;
    EXPECT_NEAR(turns[k].y_m, expected.y_m, 0.2e-3) << "corner " << k;
    // Arriving at corner k the robot still points along leg k (k * 90 deg turned so far).
    EXPECT_NEAR(msgs::WrapAngle(turns[k].theta_rad - X_W0.theta_rad - sign * k * kDeg * 90), 0.0,
                0.01 * kDeg)
        << "corner " << k;
  }
  ASSERT_EQ(controller.corners().size(), 4u);
  EXPECT_NEAR(controller.corners()[2].x_m, (X_W0 * X_0C[1]).x_m, 1e-12);
  EXPECT_NEAR(controller.corners()[2].y_m, (X_W0 * X_0C[1]).y_m, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Directions, SquarePathTest,
                         ::testing::Values(Case{SquareDirection::kClockwise, {0, 0, 0}},
                                           Case{SquareDirection::kCounterClockwise, {0, 0, 0}},
                                           // Legs crossing the +-pi heading wrap.
                                           Case{SquareDirection::kClockwise, {1.5, -2.0, 2.8}},
                                           Case{SquareDirection::kCounterClockwise,
                                                {-3.0, 0.5, -2.9}}));

TEST(SquarePathControllerTest, RespectsSpeedAccelerationAndDwell) {
  const DiffDriveSpec spec = P3dxSpec();
  SquarePathOptions options;
  options.laps = 2;
  options.dwell_s = 1.0;
  SquarePathController controller(spec, options);
  const std::vector<Tick> ticks = RunClosedLoop(controller, spec, {}, 400.0);
  ASSERT_TRUE(controller.Finished());

  double distance_m = 0.0, previous_speed = 0.0, previous_rate = 0.0;
  std::vector<int> still_runs;  // lengths of runs of zero commands
  bool was_still = false;
  const double angular_accel = options.accel_m_s2 / (spec.track_m / 2.0);
  for (std::size_t i = 0; i + 1 < ticks.size(); ++i) {
    const msgs::WheelSpeedCommand& c = ticks[i].command;
    EXPECT_LE(std::abs(c.left_rad_s), spec.max_wheel_speed_rad_s);
    EXPECT_LE(std::abs(c.right_rad_s), spec.max_wheel_speed_rad_s);
    const BodyTwist twist = WheelSpeedsToTwist(spec, c);
    EXPECT_LE(std::abs(twist.linear_m_s), options.speed_m_s + 1e-12);
    EXPECT_LE(std::abs(twist.angular_rad_s), options.turn_rate_rad_s + 1e-12);
    // Speeding up is limited by the ramp (slowing down by the braking curve, plus the final tick).
    EXPECT_LE(std::abs(twist.linear_m_s) - std::abs(previous_speed),
              options.accel_m_s2 * kDt + 1e-12);
    EXPECT_LE(std::abs(twist.angular_rad_s) - std::abs(previous_rate), angular_accel * kDt + 1e-12);
    previous_speed = twist.linear_m_s;
    previous_rate = twist.angular_rad_s;
    distance_m += std::abs(twist.linear_m_s) * kDt;
    const bool still = c.left_rad_s == 0.0 && c.right_rad_s == 0.0;
    if (still && !was_still) still_runs.push_back(0);
    if (still) ++still_runs.back();
    was_still = still;
  }
  EXPECT_NEAR(distance_m, 2 * 4 * 4.0, 1e-3);
  // The first tick cannot size a ramp step (no period measured yet); then 8 legs and 8 turns, each
  // followed by exactly dwell_s of standstill.
  ASSERT_EQ(still_runs.size(), 1u + 16u);
  EXPECT_EQ(still_runs[0], 1);
  for (std::size_t k = 1; k + 1 < still_runs.size(); ++k) EXPECT_EQ(still_runs[k], 100) << k;
  EXPECT_EQ(still_runs.back(), 101);  // plus the tick on which the controller finishes
  EXPECT_LT(std::hypot(ticks.back().X_WR.x_m, ticks.back().X_WR.y_m), 0.2e-3);
}

TEST(SquarePathControllerTest, MeasuresLegsWithTheEstimate) {
  // Odometry that over-reads distance by 2 %: the robot stops when the estimate says 4 m, so the
  // true square has sides of 4 / 1.02 m and still closes.
  const DiffDriveSpec spec = P3dxSpec();
  SquarePathController controller(spec, SquarePathOptions{});
  const auto over_reading = [](const msgs::Pose2D& X) {
    return msgs::Pose2D{1.02 * X.x_m, 1.02 * X.y_m, X.theta_rad};
  };
  const std::vector<Tick> ticks = RunClosedLoop(controller, spec, {}, 200.0, over_reading);
  ASSERT_TRUE(controller.Finished());
  const std::vector<msgs::Pose2D> turns = TurnPoses(ticks, spec);
  ASSERT_EQ(turns.size(), 4u);
  EXPECT_NEAR(turns[0].x_m, 4.0 / 1.02, 0.2e-3);
  EXPECT_NEAR(turns[1].y_m, -4.0 / 1.02, 0.2e-3);
  EXPECT_LT(std::hypot(ticks.back().X_WR.x_m, ticks.back().X_WR.y_m), 0.2e-3);
}

TEST(SquarePathControllerTest, WithoutFinalTurnEndsFacingTheLastLeg) {
  const DiffDriveSpec spec = MagellanProSpec();
  SquarePathOptions options;
  options.side_m = 2.0;
  options.direction = SquareDirection::kCounterClockwise;
  options.final_turn = false;
  SquarePathController controller(spec, options);
  const std::vector<Tick> ticks = RunClosedLoop(controller, spec, {}, 200.0);
  ASSERT_TRUE(controller.Finished());
  EXPECT_EQ(TurnPoses(ticks, spec).size(), 3u);
  EXPECT_NEAR(ticks.back().X_WR.theta_rad, -std::numbers::pi / 2, 0.01 * kDeg);
  EXPECT_LT(std::hypot(ticks.back().X_WR.x_m, ticks.back().X_WR.y_m), 0.2e-3);
  EXPECT_EQ(controller.Update({1000.0, {}}).left_rad_s, 0.0);
}

TEST(SquarePathControllerTest, ParsesDirections) {
  EXPECT_EQ(ParseSquareDirection("cw"), SquareDirection::kClockwise);
  EXPECT_EQ(ParseSquareDirection(ToString(SquareDirection::kCounterClockwise)),
            SquareDirection::kCounterClockwise);
  EXPECT_THROW(ParseSquareDirection("left"), std::invalid_argument);
}

void ExpectThrowsNaming(const SquarePathOptions& options, const std::string& field) {
  try {
    SquarePathController controller(P3dxSpec(), options);
    ADD_FAILURE() << "no exception for " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
  }
}

TEST(SquarePathControllerTest, InvalidOptionsThrowNamingTheField) {
  auto with = [](auto change) {
    SquarePathOptions options;
    change(options);
    return options;
  };
  ExpectThrowsNaming(with([](auto& o) { o.side_m = 0; }), "side_m");
  ExpectThrowsNaming(with([](auto& o) { o.laps = 0; }), "laps");
  ExpectThrowsNaming(with([](auto& o) { o.speed_m_s = -0.2; }), "speed_m_s");
  ExpectThrowsNaming(with([](auto& o) { o.speed_m_s = 5.0; }), "speed_m_s");  // > 12.3 rad/s
  ExpectThrowsNaming(with([](auto& o) { o.turn_rate_rad_s = NAN; }), "turn_rate_rad_s");
  ExpectThrowsNaming(with([](auto& o) { o.accel_m_s2 = 0; }), "accel_m_s2");
  ExpectThrowsNaming(with([](auto& o) { o.dwell_s = -1; }), "dwell_s");
  ExpectThrowsNaming(with([](auto& o) { o.heading_gain_per_s = -1; }), "heading_gain_per_s");
  ExpectThrowsNaming(with([](auto& o) { o.cross_track_gain_rad_per_m = -1; }),
                     "cross_track_gain_rad_per_m");
  ExpectThrowsNaming(with([](auto& o) { o.position_tolerance_m = 0; }), "position_tolerance_m");
  ExpectThrowsNaming(with([](auto& o) { o.heading_tolerance_rad = 0; }), "heading_tolerance_rad");
}

}  // namespace
}  // namespace plywood::robot
