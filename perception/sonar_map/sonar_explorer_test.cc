#include "perception/sonar_map/sonar_explorer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "msgs/bumpers.h"
#include "msgs/range_ring.h"
#include "robot/control/controller.h"
#include "robot/drive/diff_drive_kinematics.h"
#include "robot/drive/diff_drive_spec.h"

namespace plywood::perception {
namespace {

constexpr double kDt = 0.01;
constexpr int kSonars = 16;

SonarExplorerOptions ClassicalOptions() {
  SonarExplorerOptions options;
  options.sonar_model = "classical";
  return options;
}

std::unique_ptr<SonarExplorer> MakeExplorer(const SonarExplorerOptions& options) {
  return std::make_unique<SonarExplorer>(robot::MagellanProSpec(), options,
                                         std::make_shared<ClassicalSonarModel>());
}

// A 16-transducer ring (radius 0.2 m) at the centre of a 3 x 3 m room, facing +x: every
// transducer hears the wall its axis meets.
msgs::RangeRing RoomRing(double time_s) {
  constexpr double kHalf = 1.5;
  msgs::RangeRing ring;
  ring.time_s = time_s;
  ring.range_min_m = 0.15;
  ring.range_max_m = 5.0;
  for (int i = 0; i < kSonars; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kSonars;
    msgs::RangeReading r;
    r.X_RS = {0.2 * std::cos(a), 0.2 * std::sin(a), a};
    double range = 1e9;
    if (std::cos(a) > 1e-12) range = std::min(range, (kHalf - r.X_RS.x_m) / std::cos(a));
    if (std::cos(a) < -1e-12) range = std::min(range, (-kHalf - r.X_RS.x_m) / std::cos(a));
    if (std::sin(a) > 1e-12) range = std::min(range, (kHalf - r.X_RS.y_m) / std::sin(a));
    if (std::sin(a) < -1e-12) range = std::min(range, (-kHalf - r.X_RS.y_m) / std::sin(a));
    r.range_m = range;
    r.echo = true;
    ring.readings.push_back(r);
  }
  return ring;
}

msgs::Bumpers Pressed(double time_s, int panel) {
  msgs::Bumpers bumpers;
  bumpers.time_s = time_s;
  bumpers.pressed.assign(kSonars, false);
  if (panel >= 0) bumpers.pressed[panel] = true;
  return bumpers;
}

// Feeds the explorer ticks kDt apart, a new ring every 0.1 s, the robot standing at the origin.
class Driver {
 public:
  explicit Driver(SonarExplorer& explorer) : explorer_(explorer) {}

  // One tick; `bumpers` may be null.
  msgs::WheelSpeedCommand Tick(const msgs::Bumpers* bumpers = nullptr) {
    const double t = tick_ * kDt;
    if (tick_ % 10 == 0) ring_ = RoomRing(t);
    robot::ControllerInput input;
    input.time_s = t;
    input.sonar = &ring_;
    input.bumpers = bumpers;
    ++tick_;
    return explorer_.Update(input);
  }
  double time_s() const { return tick_ * kDt; }  // of the next tick

 private:
  SonarExplorer& explorer_;
  msgs::RangeRing ring_;
  int tick_ = 0;
};

double Speed(const msgs::WheelSpeedCommand& c) {
  return robot::WheelSpeedsToTwist(robot::MagellanProSpec(), c).linear_m_s;
}

TEST(SonarExplorerTest, FirstCommandIsZeroAndWheelSpeedsChangeAtMostTheAccelerationLimit) {
  SonarExplorerOptions options = ClassicalOptions();
  options.max_wheel_accel_rad_s2 = 2.0;  // below the follower's own ramp, so the limit binds
  auto explorer = MakeExplorer(options);
  Driver driver(*explorer);
  msgs::WheelSpeedCommand last = driver.Tick();
  // dt = 0 at the first call: no step can be taken from rest.
  EXPECT_EQ(last.left_rad_s, 0.0);
  EXPECT_EQ(last.right_rad_s, 0.0);
  const double step = options.max_wheel_accel_rad_s2 * kDt;
  int at_limit = 0;
  double fastest = 0.0;
  for (int k = 1; k < 300; ++k) {
    // A front bump at 1.5 s stops the wheels at once; from there the back-off ramps up.
    const msgs::Bumpers bump = Pressed(driver.time_s(), 0);
    const msgs::WheelSpeedCommand c = driver.Tick(k == 150 ? &bump : nullptr);
    SCOPED_TRACE(k);
    if (k == 150) {
      // From forward speed to zero, then one step towards the back-off (backwards), in one tick.
      EXPECT_GT(Speed(last), 0.05);
      EXPECT_NEAR(c.left_rad_s, -step, 1e-12);
      EXPECT_NEAR(c.right_rad_s, -step, 1e-12);
      last = c;
      continue;
    }
    const double dl = std::abs(c.left_rad_s - last.left_rad_s);
    const double dr = std::abs(c.right_rad_s - last.right_rad_s);
    EXPECT_LE(dl, step + 1e-12);
    EXPECT_LE(dr, step + 1e-12);
    if (std::max(dl, dr) > step - 1e-12) ++at_limit;
    fastest = std::max(fastest, Speed(c));
    last = c;
  }
  EXPECT_GT(fastest, 0.05);  // the follower did drive
  EXPECT_GT(at_limit, 10);   // and the limit did hold it back
  EXPECT_EQ(explorer->rings_integrated(), 30);
}

TEST(SonarExplorerTest, FrontBumpBacksOffAtTheBackOffSpeedWithinTheBackOffTime) {
  SonarExplorerOptions options = ClassicalOptions();
  // The driver never moves the pose, so the contact would stay ahead for ever (next test).
  options.perimeter_avoids_contacts = false;
  auto explorer = MakeExplorer(options);
  Driver driver(*explorer);
  double v = 0.0;
  for (int k = 0; k < 100; ++k) v = Speed(driver.Tick());
  ASSERT_GT(v, 0.05);  // driving forward when the bump comes
  const msgs::Bumpers front = Pressed(driver.time_s(), 0);
  const msgs::Bumpers none = Pressed(driver.time_s(), -1);
  const int window = static_cast<int>(std::lround(options.bump_back_off_s / kDt));
  bool reached = false;
  for (int k = 0; k < window; ++k) {
    SCOPED_TRACE(k);
    const double now = Speed(driver.Tick(k == 0 ? &front : &none));
    if (!reached) {
      // Stopped at once, then ramped towards the back-off: the speed always falls.
      EXPECT_LT(now, v);
      reached = std::abs(now + options.bump_back_off_speed_m_s) < 1e-9;
    } else {
      // Speeds are held exactly once both wheels reached their target.
      EXPECT_NEAR(now, -options.bump_back_off_speed_m_s, 1e-9);
    }
    v = now;
  }
  EXPECT_TRUE(reached);
  // The back-off is over: the follower drives forward again.
  for (int k = 0; k < 100; ++k) v = Speed(driver.Tick(&none));
  EXPECT_GT(v, 0.0);
}

// Issue 14, generator seed 4: the follower, with the wall on its left and none in view, drives
// straight on after backing off from a corner the sonar does not hear (inside its blanking range)
// and touched it again, 31 times in world 36 seed 3. The point touched stays in the corridor ahead
// here (the pose never moves): after the back-off the robot turns on the spot away from it, to the
// right for a contact on its left and to the left for one on its right, and does not drive on.
TEST(SonarExplorerTest, ContactPointAheadTurnsTheFollowerOnTheSpotAwayFromIt) {
  for (const int panel : {1, kSonars - 1}) {
    SCOPED_TRACE(panel);
    SonarExplorerOptions options = ClassicalOptions();
    auto explorer = MakeExplorer(options);
    Driver driver(*explorer);
    double v = 0.0;
    for (int k = 0; k < 100; ++k) v = Speed(driver.Tick());
    ASSERT_GT(v, 0.05);  // driving forward when the bump comes
    const msgs::Bumpers bump = Pressed(driver.time_s(), panel);
    const msgs::Bumpers none = Pressed(driver.time_s(), -1);
    driver.Tick(&bump);
    // Past the back-off and the ramp to the new command.
    while (driver.time_s() < 1.0 + options.bump_back_off_s + 1.0) driver.Tick(&none);
    for (int k = 0; k < 100; ++k) {
      const msgs::WheelSpeedCommand c = driver.Tick(&none);
      const robot::BodyTwist twist = robot::WheelSpeedsToTwist(robot::MagellanProSpec(), c);
      EXPECT_NEAR(twist.linear_m_s, 0.0, 1e-9) << k;
      // Left panels (1) lie at positive bearings: turn right, away from the point.
      EXPECT_NEAR(twist.angular_rad_s,
                  panel == 1 ? -options.turn_rate_rad_s : options.turn_rate_rad_s, 1e-9)
          << k;
    }
    EXPECT_FALSE(explorer->perimeter_done());
  }
}

TEST(SonarExplorerTest, WithoutTheBumpStopTheLimitHoldsThroughABump) {
  SonarExplorerOptions options = ClassicalOptions();
  options.bump_stops_wheels = false;
  auto explorer = MakeExplorer(options);
  Driver driver(*explorer);
  msgs::WheelSpeedCommand last{};
  for (int k = 0; k < 100; ++k) last = driver.Tick();
  ASSERT_GT(Speed(last), 0.05);
  const msgs::Bumpers front = Pressed(driver.time_s(), 0);
  const double step = options.max_wheel_accel_rad_s2 * kDt;
  for (int k = 0; k < 50; ++k) {
    const msgs::WheelSpeedCommand c = driver.Tick(k == 0 ? &front : nullptr);
    EXPECT_LE(std::abs(c.left_rad_s - last.left_rad_s), step + 1e-12) << k;
    EXPECT_LE(std::abs(c.right_rad_s - last.right_rad_s), step + 1e-12) << k;
    last = c;
  }
}

TEST(SonarExplorerTest, RearBumpBacksOffForwards) {
  const SonarExplorerOptions options = ClassicalOptions();
  auto explorer = MakeExplorer(options);
  Driver driver(*explorer);
  for (int k = 0; k < 100; ++k) driver.Tick();
  const msgs::Bumpers rear = Pressed(driver.time_s(), kSonars / 2);
  const msgs::Bumpers none = Pressed(driver.time_s(), -1);
  const int window = static_cast<int>(std::lround(options.bump_back_off_s / kDt));
  double v = 0.0;
  for (int k = 0; k < window; ++k) {
    v = Speed(driver.Tick(k == 0 ? &rear : &none));
    EXPECT_GT(v, 0.0) << k;
  }
  // Held at the back-off speed (not the follower's) by the end of the window.
  EXPECT_NEAR(v, options.bump_back_off_speed_m_s, 1e-9);
}

// Issue 14, generator seed 5: a side panel's centre has cosine 0 up to rounding (-2e-16 for the
// right one), and the right panel backed the robot off forwards, along and into the face it had
// met while driving forward, for the whole back-off (world 7 seed 1: a 1.6 s contact, +11.7 deg of
// encoder heading). Met while driving forward, either side panel backs the robot off backwards.
TEST(SonarExplorerTest, SidePanelMetDrivingForwardBacksOffBackwardsOnEitherSide) {
  for (const int panel : {kSonars / 4, 3 * kSonars / 4}) {
    SCOPED_TRACE(panel);
    SonarExplorerOptions options = ClassicalOptions();
    options.perimeter_avoids_contacts = false;
    auto explorer = MakeExplorer(options);
    Driver driver(*explorer);
    double v = 0.0;
    for (int k = 0; k < 100; ++k) v = Speed(driver.Tick());
    ASSERT_GT(v, 0.05);  // driving forward when the bump comes
    const msgs::Bumpers side = Pressed(driver.time_s(), panel);
    const msgs::Bumpers none = Pressed(driver.time_s(), -1);
    const int window = static_cast<int>(std::lround(options.bump_back_off_s / kDt));
    for (int k = 0; k < window; ++k) {
      v = Speed(driver.Tick(k == 0 ? &side : &none));
      EXPECT_LE(v, 0.0) << k;
    }
    EXPECT_NEAR(v, -options.bump_back_off_speed_m_s, 1e-9);
  }
}

// Issue 14, generator seed 30 world 32: the robot stood in a ~0.5 m diagonal gap between two box
// corners; the front right panel touched one, the back-off along the axis drove the rear left panel
// into the other, whose back-off drove the front right panel into the first, for the whole run
// (112 contacts). A contact on the opposite half of the body while backing off is a wedge: the
// robot turns on the spot (the body is round: nothing is touched) until its axis lies along the
// gap, perpendicular to the line through the two contact points, facing the side of that line it
// stands on. Here the pose follows the commands (no slip). The first contact, and its panel still
// pressed with a neighbour on the same half, back off as before.
TEST(SonarExplorerTest, OppositeContactWhileBackingOffTurnsOnTheSpotAlongTheGap) {
  SonarExplorerOptions options = ClassicalOptions();
  options.perimeter_avoids_contacts = false;
  auto explorer = MakeExplorer(options);
  const robot::DiffDriveSpec spec = robot::MagellanProSpec();
  const double contact_radius = options.robot_radius_m + 0.02;  // where the explorer puts a contact
  msgs::Pose2D pose;
  msgs::RangeRing ring;
  int k = 0;
  const auto tick = [&](const msgs::Bumpers* bumpers) {
    const double t = k * kDt;
    if (k % 10 == 0) ring = RoomRing(t);
    ++k;
    robot::ControllerInput input;
    input.time_s = t;
    input.sonar = &ring;
    input.bumpers = bumpers;
    input.X_WR_estimate = pose;
    const robot::BodyTwist twist = robot::WheelSpeedsToTwist(spec, explorer->Update(input));
    pose.x_m += twist.linear_m_s * std::cos(pose.theta_rad) * kDt;
    pose.y_m += twist.linear_m_s * std::sin(pose.theta_rad) * kDt;
    pose.theta_rad += twist.angular_rad_s * kDt;
    return twist;
  };
  robot::BodyTwist twist;
  while (k < 100) twist = tick(nullptr);
  ASSERT_GT(twist.linear_m_s, 0.05);  // driving forward when the bump comes
  constexpr int kFrontRight = 14, kRearLeft = 6;
  const auto panel_point = [&](int panel) {
    const double a = pose.theta_rad + 2.0 * std::numbers::pi * panel / kSonars;
    return Eigen::Vector2d(pose.x_m + contact_radius * std::cos(a),
                           pose.y_m + contact_radius * std::sin(a));
  };
  const Eigen::Vector2d first = panel_point(kFrontRight);
  const msgs::Bumpers front_right = Pressed(k * kDt, kFrontRight);
  msgs::Bumpers same_half = Pressed(k * kDt, kFrontRight);
  same_half.pressed[kFrontRight - 1] = true;
  const msgs::Bumpers none = Pressed(k * kDt, -1);
  // 0.8 s of back-off, the first 0.3 s with the panel (and its neighbour) still pressed.
  for (int j = 0; j < 80; ++j) {
    twist = tick(j == 0 ? &front_right : j < 30 ? &same_half : &none);
    EXPECT_LE(twist.linear_m_s, 0.0) << j;
    EXPECT_FALSE(explorer->turning_out_of_wedge()) << j;
  }
  EXPECT_NEAR(twist.linear_m_s, -options.bump_back_off_speed_m_s, 1e-9);
  const Eigen::Vector2d here(pose.x_m, pose.y_m);
  const Eigen::Vector2d second = panel_point(kRearLeft);
  ASSERT_LT((first - here).dot(second - here), 0.0);  // the opposite half
  // The gap's axis, facing the robot's side of the line through the two contacts.
  Eigen::Vector2d along_gap(first.y() - second.y(), second.x() - first.x());
  if (along_gap.dot(here - first) < 0.0) along_gap = -along_gap;
  const double wanted = std::atan2(along_gap.y(), along_gap.x());
  const double turn = msgs::WrapAngle(wanted - pose.theta_rad);
  ASSERT_GT(std::abs(turn), 0.5);
  const msgs::Bumpers rear_left = Pressed(k * kDt, kRearLeft);
  const int turn_start = k;
  // The second panel stays pressed for 0.5 s: the robot turns against it.
  for (int j = 0; j < 1000; ++j) {
    const msgs::Pose2D before = pose;
    twist = tick(j < 50 ? &rear_left : &none);
    if (!explorer->turning_out_of_wedge()) {
      // Aligned as DriveTo counts it (0.2 rad), on the spot where the second contact came.
      EXPECT_LT(std::abs(msgs::WrapAngle(before.theta_rad - wanted)), 0.2 + 0.01);
      EXPECT_NEAR(before.x_m, here.x(), 1e-9);
      EXPECT_NEAR(before.y_m, here.y(), 1e-9);
      break;
    }
    ASSERT_NEAR(twist.linear_m_s, 0.0, 1e-9) << j;    // on the spot
    ASSERT_GT(twist.angular_rad_s * turn, 0.0) << j;  // the short way round
    ASSERT_LE(std::abs(twist.angular_rad_s), options.turn_rate_rad_s + 1e-9) << j;
  }
  EXPECT_FALSE(explorer->turning_out_of_wedge()) << "still turning after 10 s";
  EXPECT_LT((k - turn_start) * kDt, std::abs(turn) / options.turn_rate_rad_s + 1.0);
}

// The same wedge met right after the back-off: the first contact's back-off ran its full time with
// nothing pressed, and the rear panel touches as the wheels ramp down from it. Main backed off
// from it forwards, into the first contact again. Here the pose never moves (the wheels are held,
// or the encoders do not see the turn): the turn is given up after twice its time at the turn
// rate plus one back-off, so that it cannot spin for ever.
TEST(SonarExplorerTest, OppositeContactRightAfterTheBackOffTurnsInsteadOfBackingOffAgain) {
  SonarExplorerOptions options = ClassicalOptions();
  options.perimeter_avoids_contacts = false;
  auto explorer = MakeExplorer(options);
  Driver driver(*explorer);
  for (int k = 0; k < 100; ++k) driver.Tick();
  constexpr int kFrontRight = 14, kRearLeft = 7;  // 157.5 deg apart
  const msgs::Bumpers front_right = Pressed(driver.time_s(), kFrontRight);
  const msgs::Bumpers rear_left = Pressed(driver.time_s(), kRearLeft);
  const msgs::Bumpers none = Pressed(driver.time_s(), -1);
  driver.Tick(&front_right);
  const double back_off_end = driver.time_s() - kDt + options.bump_back_off_s;
  while (driver.time_s() < back_off_end - kDt / 2.0) EXPECT_LT(Speed(driver.Tick(&none)), 0.0);
  driver.Tick(&rear_left);
  EXPECT_TRUE(explorer->turning_out_of_wedge());
  const double turn_start = driver.time_s() - kDt;
  // The pose stays at the origin, heading 0: the gap's axis, facing the robot's side of the line
  // through the two contacts.
  const double contact_radius = options.robot_radius_m + 0.02;
  const auto panel_point = [&](int panel) {
    const double a = 2.0 * std::numbers::pi * panel / kSonars;
    return Eigen::Vector2d(contact_radius * std::cos(a), contact_radius * std::sin(a));
  };
  const Eigen::Vector2d first = panel_point(kFrontRight), second = panel_point(kRearLeft);
  Eigen::Vector2d along_gap(first.y() - second.y(), second.x() - first.x());
  if (along_gap.dot(-first) < 0.0) along_gap = -along_gap;
  const double turn = std::atan2(along_gap.y(), along_gap.x());
  ASSERT_GT(std::abs(turn), 0.5);
  const double give_up =
      turn_start + 2.0 * std::abs(turn) / options.turn_rate_rad_s + options.bump_back_off_s;
  const robot::DiffDriveSpec spec = robot::MagellanProSpec();
  while (explorer->turning_out_of_wedge() && driver.time_s() < give_up + 1.0) {
    const robot::BodyTwist twist = robot::WheelSpeedsToTwist(spec, driver.Tick(&none));
    if (!explorer->turning_out_of_wedge()) break;
    ASSERT_NEAR(twist.linear_m_s, 0.0, 1e-9) << driver.time_s();    // neither back nor forwards
    ASSERT_GT(twist.angular_rad_s * turn, 0.0) << driver.time_s();  // the short way round
  }
  EXPECT_FALSE(explorer->turning_out_of_wedge());
  EXPECT_NEAR(driver.time_s() - kDt, give_up, kDt + 1e-9);
}

TEST(SonarExplorerTest, RearBumpFromRestRampsUpToTheBackOffSpeed) {
  const SonarExplorerOptions options = ClassicalOptions();
  auto explorer = MakeExplorer(options);
  robot::ControllerInput input;  // no sonar ring yet: the follower commands zero
  input.time_s = 0.0;
  EXPECT_EQ(Speed(explorer->Update(input)), 0.0);
  const msgs::Bumpers rear = Pressed(kDt, kSonars / 2);
  input.bumpers = &rear;
  const robot::DiffDriveSpec spec = robot::MagellanProSpec();
  double v = 0.0;
  for (int k = 1; k <= 50; ++k) {
    input.time_s = k * kDt;
    const msgs::WheelSpeedCommand c = explorer->Update(input);
    // Both wheels ramp together from rest: by one step a tick until the target.
    const double wheel = std::min(k * options.max_wheel_accel_rad_s2 * kDt,
                                  options.bump_back_off_speed_m_s / spec.wheel_radius_m);
    EXPECT_NEAR(c.left_rad_s, wheel, 1e-9) << k;
    EXPECT_NEAR(c.right_rad_s, wheel, 1e-9) << k;
    v = Speed(c);
  }
  EXPECT_NEAR(v, options.bump_back_off_speed_m_s, 1e-9);
}

// The range along a ray from (x, y) at bearing a to the first face of the 3 x 3 m room or of the
// axis-parallel box [bx0, bx1] x [by0, by1].
double RangeToRoomOrBox(double x, double y, double a, double bx0, double by0, double bx1,
                        double by1) {
  constexpr double kHalf = 1.5;
  const double c = std::cos(a), s = std::sin(a);
  double range = 1e9;
  if (c > 1e-12) range = std::min(range, (kHalf - x) / c);
  if (c < -1e-12) range = std::min(range, (-kHalf - x) / c);
  if (s > 1e-12) range = std::min(range, (kHalf - y) / s);
  if (s < -1e-12) range = std::min(range, (-kHalf - y) / s);
  // Slab test against the box.
  double t0 = 0.0, t1 = 1e9;
  for (const auto& [o, d, lo, hi] :
       {std::array<double, 4>{x, c, bx0, bx1}, std::array<double, 4>{y, s, by0, by1}}) {
    if (std::abs(d) < 1e-12) {
      if (o < lo || o > hi) return range;
      continue;
    }
    const double ta = (lo - o) / d, tb = (hi - o) / d;
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
  }
  return t0 <= t1 ? std::min(range, t0) : range;
}

// Issue 14, generator seed 4: the follower turns on the spot until the lane ahead is clear by
// front_clearance + wall_distance (1.3 m). In a round room 1.8 m across no heading ever is, and it
// turned for the whole 150 s perimeter (worlds 22, 24 and 32 of generator seed 4, world 17 of seed
// 1: ~10,000 deg in a run). The robot here moves as commanded (no slip): the perimeter ends once
// it has turned perimeter_stuck_turn_rad on the spot, and not before.
TEST(SonarExplorerTest, FollowerTurningOnTheSpotForTwoTurnsEndsThePerimeter) {
  constexpr double kRoomRadius = 0.9;
  const SonarExplorerOptions options = ClassicalOptions();
  auto explorer = MakeExplorer(options);
  const robot::DiffDriveSpec spec = robot::MagellanProSpec();
  robot::ControllerInput input;
  msgs::RangeRing ring;
  msgs::Pose2D pose;
  double turned = 0.0, turned_when_done = -1.0;
  Eigen::Vector2d start(0.0, 0.0);
  double farthest = 0.0;
  for (int k = 0; k < 4000 && turned_when_done < 0.0; ++k) {
    const double t = k * kDt;
    if (k % 10 == 0) {
      ring = RoomRing(t);
      for (msgs::RangeReading& r : ring.readings) {
        // From the transducer along its axis to the round wall: |p + s d| = R.
        const msgs::Pose2D X_WS = pose * r.X_RS;
        const Eigen::Vector2d p(X_WS.x_m, X_WS.y_m);
        const Eigen::Vector2d d(std::cos(X_WS.theta_rad), std::sin(X_WS.theta_rad));
        const double b = p.dot(d);
        r.range_m = -b + std::sqrt(b * b - (p.squaredNorm() - kRoomRadius * kRoomRadius));
      }
    }
    input.time_s = t;
    input.sonar = &ring;
    input.X_WR_estimate = pose;
    const msgs::WheelSpeedCommand c = explorer->Update(input);
    if (explorer->perimeter_done()) {
      turned_when_done = turned;
      break;
    }
    const robot::BodyTwist twist = robot::WheelSpeedsToTwist(spec, c);
    pose.x_m += twist.linear_m_s * std::cos(pose.theta_rad) * kDt;
    pose.y_m += twist.linear_m_s * std::sin(pose.theta_rad) * kDt;
    pose.theta_rad += twist.angular_rad_s * kDt;
    turned += std::abs(twist.angular_rad_s) * kDt;
    farthest = std::max(farthest, std::hypot(pose.x_m, pose.y_m));
  }
  ASSERT_GE(turned_when_done, 0.0) << "still following after 40 s";
  EXPECT_LT(farthest, options.robot_radius_m);  // it never got anywhere
  EXPECT_GE(turned_when_done, options.perimeter_stuck_turn_rad);
  EXPECT_LT(turned_when_done, options.perimeter_stuck_turn_rad + 0.1);
}

// Issue 14: exploration ends "map_complete" only when no obstacle is left to go round. A robot
// that stands where the sonar never looked (the cells under its body are inside every
// transducer's blanking range, so they stay unknown: here it never moves, in world 17 of the
// generated rooms it had come to rest there) found no cell it could step to, skipped every
// circuit corner as "as near as it gets", reached no place and no frontier, and declared the map
// complete on the spot with the box in the map never gone round.
TEST(SonarExplorerTest, RobotOnCellsTheSonarNeverSawDoesNotDeclareTheMapComplete) {
  SonarExplorerOptions options = ClassicalOptions();
  options.perimeter_max_s = 1.0;  // straight on to the circuits: the robot here never moves
  auto explorer = MakeExplorer(options);
  constexpr double kBx0 = 0.5, kBy0 = 0.3, kBx1 = 1.0, kBy1 = 1.0;  // a box NE of the robot
  msgs::RangeRing ring;
  robot::ControllerInput input;
  bool moved = false;
  for (int k = 0; k < 500; ++k) {
    const double t = k * kDt;
    if (k % 10 == 0) {
      ring = RoomRing(t);
      for (msgs::RangeReading& r : ring.readings)
        r.range_m =
            RangeToRoomOrBox(r.X_RS.x_m, r.X_RS.y_m, r.X_RS.theta_rad, kBx0, kBy0, kBx1, kBy1);
    }
    input.time_s = t;
    input.sonar = &ring;
    const msgs::WheelSpeedCommand c = explorer->Update(input);
    if (t > options.perimeter_max_s + 0.5)
      moved = moved || c.left_rad_s != 0.0 || c.right_rad_s != 0.0;
  }
  const CognitiveMap map = explorer->PlanningMap();
  ASSERT_EQ(map.obstacles.size(), 1u);
  EXPECT_LT(map.obstacles[0].x0, kBx1);  // the box, seen
  EXPECT_GT(map.obstacles[0].x1, kBx0);
  EXPECT_FALSE(explorer->Finished()) << explorer->end_reason();
  EXPECT_TRUE(moved);  // it sets off round the box (turning first)
}

// A cell model that calls two cells straight ahead of the robot occupied whatever the ring says,
// as the network kept the spike an oblique transducer heard (issue 14 rounds 65b, 66a), and says
// nothing elsewhere.
class SpikeAheadModel final : public SonarCellModel {
 public:
  double Probability(const msgs::RangeRing&, const Eigen::Vector2d& p_R) const override {
    return SpikeAhead(p_R) ? 0.95 : 0.5;
  }
  static bool SpikeAhead(const Eigen::Vector2d& p_R) {
    return p_R.x() > 0.41 && p_R.x() < 0.5 && std::abs(p_R.y()) < 0.02;
  }
};

// The same spike across a corridor 0.7 m wide (walls north and south, closed 0.35 m behind the
// robot) whose only unknown end lies 0.7 m ahead, past it: on the heard cells, the spike keeps
// every way to that frontier closer than squeeze_clearance_m to it.
class SpikeInCorridorModel final : public SonarCellModel {
 public:
  double Probability(const msgs::RangeRing&, const Eigen::Vector2d& p) const override {
    const bool side_wall = std::abs(p.y()) >= 0.35 && std::abs(p.y()) <= 0.45 && p.x() >= -0.45;
    const bool end_wall = p.x() >= -0.45 && p.x() <= -0.35 && std::abs(p.y()) <= 0.45;
    if (side_wall || end_wall || SpikeAheadModel::SpikeAhead(p)) return 0.95;
    return p.x() > -0.35 && std::abs(p.y()) < 0.35 ? 0.05 : 0.5;
  }
};

// Cell edges 0.01 m off the forward axis (the grid starts at the pose less this): the axis runs
// inside one row of cells, the spike's, and every ring's forward axis passes through it to the
// wall 1.3 m off.
constexpr double kHalfExtentAxisInOneRow = 3.99;

// The follower's speed over the ticks from 1 s to 2 s (the perimeter phase), the robot standing at
// the origin of the 3 x 3 m room facing +x with the spike ahead.
double SlowestForwardWithSpikeAhead(bool last_frontier_through_axis_free) {
  SonarExplorerOptions options = ClassicalOptions();
  options.last_frontier_through_axis_free = last_frontier_through_axis_free;
  options.grid_half_extent_m = kHalfExtentAxisInOneRow;
  SonarExplorer explorer(robot::MagellanProSpec(), options, std::make_shared<SpikeAheadModel>());
  Driver driver(explorer);
  double slowest = std::numeric_limits<double>::infinity();
  while (driver.time_s() < 2.0) {
    const double v = Speed(driver.Tick());
    if (driver.time_s() > 1.0) slowest = std::min(slowest, v);
  }
  return slowest;
}

struct CorridorRun {
  bool finished = false;
  std::string end_reason;
  std::vector<std::string> goals;  // the details of the goal events, in order
};

// 10 s in the corridor, the perimeter cut short so that the planner's tiers run.
CorridorRun RunInCorridorWithSpike(bool last_frontier_through_axis_free) {
  SonarExplorerOptions options = ClassicalOptions();
  options.last_frontier_through_axis_free = last_frontier_through_axis_free;
  options.grid_half_extent_m = kHalfExtentAxisInOneRow;
  options.perimeter_max_s = 1.0;
  SonarExplorer explorer(robot::MagellanProSpec(), options,
                         std::make_shared<SpikeInCorridorModel>());
  Driver driver(explorer);
  while (driver.time_s() < 10.0 && !explorer.Finished()) driver.Tick();
  CorridorRun run{explorer.Finished(), explorer.end_reason(), {}};
  for (const ExplorationEvent& e : explorer.events())
    if (e.kind == "goal") run.goals.push_back(e.detail);
  return run;
}

TEST(SonarExplorerTest, AxisFreeCellsAreFreeOnlyWhenNoFrontierIsLeftOtherwise) {
  // While the perimeter runs the map rules as ever, the option on or off: the map check sees the
  // spike in the body's corridor and turns the robot on the spot (round 65b's rule, on always,
  // drove on through it).
  EXPECT_NEAR(SlowestForwardWithSpikeAhead(false), 0.0, 1e-9);
  EXPECT_NEAR(SlowestForwardWithSpikeAhead(true), 0.0, 1e-9);
  // Off: no frontier can be reached past the spike, and the map is declared complete.
  const CorridorRun off = RunInCorridorWithSpike(false);
  EXPECT_TRUE(off.finished);
  EXPECT_EQ(off.end_reason, "map_complete");
  EXPECT_EQ(std::count(off.goals.begin(), off.goals.end(), "frontier"), 0);
  // On: there, and only there, the last tier takes the spike the forward axis saw floor through
  // for free, and the robot sets off for the frontier past it; no tier before it found one.
  const CorridorRun on = RunInCorridorWithSpike(true);
  EXPECT_FALSE(on.finished) << on.end_reason;
  EXPECT_EQ(std::count(on.goals.begin(), on.goals.end(), "frontier"), 0);
  EXPECT_GE(std::count(on.goals.begin(), on.goals.end(), "frontier_through_axis_free"), 1);
}

// Issue 14 round 66c: a pocket 1.15 x 1.15 m whose only way out is the diagonal gap between two
// box corners at its south-east corner, as in generated world 10 of seed 193: the north-east corner
// of the box south of it (its face y 0.1, x up to 1.0) and the south-west corner of the box east of
// it (its face x 1.4, y from 0.5), 0.4 m apart along each axis, 0.566 m apart (1.41 times the
// body's width, 0.4 m); behind the gap a second room (1.0 to 2.0, -0.7 to 0.5). Corners and faces
// lie on cell edges: the corner cells' centres are 9 cells apart along each axis, and the cells
// more than 5 cells (robot_radius_m + front_margin_m, 0.25 m, the body's clearance) from both make
// a way through that a path can take (no corner is cut), the cells 6 cells (squeeze_clearance_m)
// from both none. The robot starts at (0.7, 0.8), on the gap's bisector; the coordinates below are
// shifted to put it at the origin.
struct Box {
  double x0, y0, x1, y1;
  bool Contains(const Eigen::Vector2d& p) const {
    return p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1;
  }
};
constexpr double kShiftX = -0.7, kShiftY = -0.8;
const std::array<Box, 6> kPocketWalls = {{
    {0.15 + kShiftX, 1.25 + kShiftY, 2.1 + kShiftX, 1.35 + kShiftY},  // north
    {0.15 + kShiftX, -0.8 + kShiftY, 2.1 + kShiftX, -0.7 + kShiftY},  // south
    {0.15 + kShiftX, 0.1 + kShiftY, 0.25 + kShiftX, 1.25 + kShiftY},  // west
    {2.0 + kShiftX, -0.7 + kShiftY, 2.1 + kShiftX, 1.25 + kShiftY},   // east
    {0.15 + kShiftX, -0.7 + kShiftY, 1.0 + kShiftX, 0.1 + kShiftY},   // the box south of the pocket
    {1.4 + kShiftX, 0.5 + kShiftY, 2.0 + kShiftX, 1.25 + kShiftY},    // the box east of it
}};

// The distance along the ray from `from` in direction `u` (unit) to the first wall, or infinity.
double RayToWalls(const Eigen::Vector2d& from, const Eigen::Vector2d& u) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Box& b : kPocketWalls) {
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    const double lo[2] = {b.x0, b.y0}, hi[2] = {b.x1, b.y1};
    bool miss = false;
    for (int k = 0; k < 2 && !miss; ++k) {
      if (std::abs(u[k]) < 1e-12) {
        miss = from[k] < lo[k] || from[k] > hi[k];
        continue;
      }
      double a = (lo[k] - from[k]) / u[k], c = (hi[k] - from[k]) / u[k];
      if (a > c) std::swap(a, c);
      t0 = std::max(t0, a);
      t1 = std::min(t1, c);
      miss = t0 > t1;
    }
    if (!miss) nearest = std::min(nearest, t0);
  }
  return nearest;
}

// A cell model that knows the walls: a cell of the grid's window round the robot that the robot
// can see (the line to the cell meets no wall short of its last 0.1 m, a wall's depth) is occupied
// in a wall and free elsewhere; every other cell gets no update. The pose is the driver's.
class PocketModel final : public SonarCellModel {
 public:
  explicit PocketModel(const msgs::Pose2D* pose) : pose_(pose) {}
  double Probability(const msgs::RangeRing&, const Eigen::Vector2d& p_R) const override {
    const double c = std::cos(pose_->theta_rad), s = std::sin(pose_->theta_rad);
    const Eigen::Vector2d robot(pose_->x_m, pose_->y_m);
    const Eigen::Vector2d p =
        robot + Eigen::Vector2d(c * p_R.x() - s * p_R.y(), s * p_R.x() + c * p_R.y());
    const double d = p_R.norm();
    if (d > 0.1 && RayToWalls(robot, (p - robot) / d) < d - 0.1) return 0.5;
    for (const Box& b : kPocketWalls)
      if (b.Contains(p)) return 0.95;
    return 0.05;
  }

 private:
  const msgs::Pose2D* pose_;
};

struct PocketRun {
  std::string end_reason;
  bool entered_second_room = false;  // the robot's centre east of 1.2 m and south of 0 (unshifted)
  double closest_to_wall_m = 1e9;    // the robot's centre to the nearest wall
  std::vector<std::string> goals;
};

// Up to 150 s in the pocket, the pose moved by the commanded wheel speeds, a ring cast against the
// walls every 0.1 s, the perimeter cut short so that the planner's tiers run.
PocketRun RunInPocket(bool last_frontier_at_body_clearance) {
  SonarExplorerOptions options = ClassicalOptions();
  options.last_frontier_at_body_clearance = last_frontier_at_body_clearance;
  options.grid_half_extent_m = 2.5;  // cell edges on multiples of 0.05 m, the pose at (0, 0)
  options.perimeter_max_s = 1.0;
  msgs::Pose2D pose;
  SonarExplorer explorer(robot::MagellanProSpec(), options, std::make_shared<PocketModel>(&pose));
  PocketRun run;
  msgs::RangeRing ring;
  for (int k = 0; k < 15000 && !explorer.Finished(); ++k) {
    const double t = k * kDt;
    if (k % 10 == 0) {
      ring = RoomRing(t);
      for (msgs::RangeReading& r : ring.readings) {
        const double c = std::cos(pose.theta_rad), s = std::sin(pose.theta_rad);
        const Eigen::Vector2d at(pose.x_m + c * r.X_RS.x_m - s * r.X_RS.y_m,
                                 pose.y_m + s * r.X_RS.x_m + c * r.X_RS.y_m);
        const double a = pose.theta_rad + r.X_RS.theta_rad;
        r.range_m = RayToWalls(at, {std::cos(a), std::sin(a)});
        r.echo = r.range_m < ring.range_max_m;
        if (!r.echo) r.range_m = ring.range_max_m;
      }
    }
    robot::ControllerInput input;
    input.time_s = t;
    input.sonar = &ring;
    input.X_WR_estimate = pose;
    const robot::BodyTwist twist =
        robot::WheelSpeedsToTwist(robot::MagellanProSpec(), explorer.Update(input));
    pose.theta_rad += twist.angular_rad_s * kDt;
    pose.x_m += twist.linear_m_s * std::cos(pose.theta_rad) * kDt;
    pose.y_m += twist.linear_m_s * std::sin(pose.theta_rad) * kDt;
    run.entered_second_room =
        run.entered_second_room || (pose.x_m > 1.2 + kShiftX && pose.y_m < kShiftY);
    for (const Box& b : kPocketWalls) {
      const double dx = std::max({b.x0 - pose.x_m, 0.0, pose.x_m - b.x1});
      const double dy = std::max({b.y0 - pose.y_m, 0.0, pose.y_m - b.y1});
      run.closest_to_wall_m = std::min(run.closest_to_wall_m, std::hypot(dx, dy));
    }
  }
  run.end_reason = explorer.end_reason();
  for (const ExplorationEvent& e : explorer.events())
    if (e.kind == "goal") run.goals.push_back(e.detail);
  return run;
}

TEST(SonarExplorerTest, AGapTheBodyFitsButNoClearanceTierPassesIsDrivenAtTheBodysClearance) {
  // Off: no tier reaches past the gap, and the map is declared complete with the second room
  // never entered.
  const PocketRun off = RunInPocket(false);
  EXPECT_EQ(off.end_reason, "map_complete");
  EXPECT_FALSE(off.entered_second_room);
  EXPECT_EQ(std::count(off.goals.begin(), off.goals.end(), "frontier_at_body_clearance"), 0);
  // On: there, the last tier finds the frontier past the gap at the body's clearance, and the
  // robot drives through into the second room without touching a side (the body's radius is
  // 0.2 m).
  const PocketRun on = RunInPocket(true);
  EXPECT_GE(std::count(on.goals.begin(), on.goals.end(), "frontier_at_body_clearance"), 1);
  EXPECT_TRUE(on.entered_second_room);
  EXPECT_GT(on.closest_to_wall_m, 0.2);
}

void ExpectThrowsNaming(const SonarExplorerOptions& options, const std::string& field) {
  try {
    MakeExplorer(options);
    ADD_FAILURE() << "no exception for " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
  }
}

TEST(SonarExplorerTest, SqueezeClearanceOutsideFrontCorridorToNarrowClearanceThrowsNamingIt) {
  SonarExplorerOptions options = ClassicalOptions();
  options.squeeze_clearance_m = options.robot_radius_m + options.front_margin_m;
  ExpectThrowsNaming(options, "squeeze_clearance_m");
  options.squeeze_clearance_m = options.narrow_clearance_m + 0.01;
  ExpectThrowsNaming(options, "squeeze_clearance_m");
  options.squeeze_clearance_m = options.narrow_clearance_m;
  EXPECT_NO_THROW(MakeExplorer(options));
  options.squeeze_clearance_m = 0.0;
  EXPECT_NO_THROW(MakeExplorer(options));
}

TEST(SonarExplorerTest, ContactClearanceNotAboveTheRobotRadiusThrowsNamingIt) {
  SonarExplorerOptions options = ClassicalOptions();
  options.contact_clearance_m = options.robot_radius_m;
  ExpectThrowsNaming(options, "contact_clearance_m");
  options.contact_clearance_m = -0.25;
  ExpectThrowsNaming(options, "contact_clearance_m");
  options.contact_clearance_m = options.robot_radius_m + 0.01;
  EXPECT_NO_THROW(MakeExplorer(options));
  options.contact_clearance_m = 0.0;
  EXPECT_NO_THROW(MakeExplorer(options));
}

TEST(SonarExplorerTest, CompleteUnknownShareMaxOutsideZeroToOneThrowsNamingIt) {
  SonarExplorerOptions options = ClassicalOptions();
  for (const double bad : {0.0, -0.5, 1.01, std::numeric_limits<double>::quiet_NaN()}) {
    options.complete_unknown_share_max = bad;
    ExpectThrowsNaming(options, "complete_unknown_share_max");
  }
  options.complete_unknown_share_max = 1.0;  // off
  EXPECT_NO_THROW(MakeExplorer(options));
}

// The beam-free grid's fields are the experiment's beam_free_* keys: an error named max_range_m
// pointed the user at another key (the sonar's own range).
TEST(SonarExplorerTest, BadBeamFreeOptionsThrowNamingTheirExperimentKeys) {
  SonarExplorerOptions options = ClassicalOptions();
  options.beam_free.max_range_m = -1.0;
  ExpectThrowsNaming(options, "beam_free_max_range_m");
  options = ClassicalOptions();
  options.beam_free.oblique_face_max_rad = 2.0;
  ExpectThrowsNaming(options, "beam_free_oblique_face_max_rad");
  options = ClassicalOptions();
  options.beam_free.half_angle_rad = std::nan("");
  ExpectThrowsNaming(options, "beam_free_half_angle_rad");
}

TEST(SonarExplorerTest, DefaultClassicalOptionsAreValid) {
  EXPECT_NO_THROW(MakeExplorer(ClassicalOptions()));
}

TEST(SonarExplorerTest, FrontCorridorAsWideAsThePathClearanceThrowsNamingFrontMargin) {
  SonarExplorerOptions options = ClassicalOptions();
  options.front_margin_m = options.path_clearance_m - options.robot_radius_m;  // equal
  ExpectThrowsNaming(options, "front_margin_m");
  options.front_margin_m = 0.3;
  ExpectThrowsNaming(options, "front_margin_m");
}

TEST(SonarExplorerTest, PathClearanceNotBeyondTheRobotThrowsNamingPathClearance) {
  SonarExplorerOptions options = ClassicalOptions();
  options.front_margin_m = 0.0;
  options.path_clearance_m = options.robot_radius_m;
  ExpectThrowsNaming(options, "path_clearance_m");
  options.path_clearance_m = 0.1;
  ExpectThrowsNaming(options, "path_clearance_m");
}

TEST(SonarExplorerTest, NarrowClearanceOutsideFrontCorridorToPathClearanceThrowsNamingIt) {
  SonarExplorerOptions options = ClassicalOptions();
  // The front corridor's half-width (0.25 m): a narrow path would be blocked by what shaped it.
  options.narrow_clearance_m = options.robot_radius_m + options.front_margin_m;
  ExpectThrowsNaming(options, "narrow_clearance_m");
  options.narrow_clearance_m = options.path_clearance_m + 0.01;
  ExpectThrowsNaming(options, "narrow_clearance_m");
  options.narrow_clearance_m = options.path_clearance_m;
  EXPECT_NO_THROW(MakeExplorer(options));
}

TEST(SonarExplorerTest, NonPositiveWheelAccelerationThrowsNamingTheField) {
  SonarExplorerOptions options = ClassicalOptions();
  options.max_wheel_accel_rad_s2 = 0.0;
  ExpectThrowsNaming(options, "max_wheel_accel_rad_s2");
  options.max_wheel_accel_rad_s2 = -1.0;
  ExpectThrowsNaming(options, "max_wheel_accel_rad_s2");
}

TEST(SonarExplorerTest, CircuitOptionsOutOfRangeThrowNamingTheField) {
  SonarExplorerOptions options = ClassicalOptions();
  // A corner nearer than the waypoint tolerance could never count as reached.
  options.circuit_reach_m = options.waypoint_tolerance_m / 2.0;
  ExpectThrowsNaming(options, "circuit_reach_m");
  options = ClassicalOptions();
  options.circuit_max_s = 0.0;
  ExpectThrowsNaming(options, "circuit_max_s");
  options = ClassicalOptions();
  options.circuit_same_m = -0.1;
  ExpectThrowsNaming(options, "circuit_same_m");
}

// What a real robot's driver can hand the explorer (docs/errors.md, the s64 fifty-third pass).
void ExpectRefused(SonarExplorer& explorer, const robot::ControllerInput& input,
                   const std::string& message) {
  try {
    explorer.Update(input);
    ADD_FAILURE() << "no exception, expected " << message;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(SonarExplorerTest, APoseOrTimeThatIsNotFiniteIsRefusedAndTheRunGoesOn) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  auto explorer = MakeExplorer(ClassicalOptions());
  msgs::RangeRing ring = RoomRing(0.0);
  robot::ControllerInput input;
  input.sonar = &ring;
  // As the first tick: no start, no grid placed at NaN.
  input.X_WR_estimate = {kNan, 0.0, 0.0};
  ExpectRefused(*explorer, input, "X_WR_estimate: must be finite, got (nan, 0, 0)");
  EXPECT_FALSE(explorer->start().has_value());
  EXPECT_EQ(explorer->rings_integrated(), 0);
  Driver driver(*explorer);
  for (int k = 0; k < 100; ++k) driver.Tick();
  const int rings = explorer->rings_integrated();
  ring = RoomRing(driver.time_s());
  input.time_s = driver.time_s();
  input.X_WR_estimate = {0.0, 0.0, kNan};
  ExpectRefused(*explorer, input, "X_WR_estimate: must be finite, got (0, 0, nan)");
  input.X_WR_estimate = {0.0, std::numeric_limits<double>::infinity(), 0.0};
  ExpectRefused(*explorer, input, "X_WR_estimate: must be finite, got (0, inf, 0)");
  input.X_WR_estimate = {};
  input.time_s = kNan;
  ExpectRefused(*explorer, input, "time_s: must be finite, got nan");
  EXPECT_EQ(explorer->rings_integrated(), rings);
  // The next good tick integrates its ring as before.
  input.time_s = driver.time_s();
  explorer->Update(input);
  EXPECT_EQ(explorer->rings_integrated(), rings + 1);
}

TEST(SonarExplorerTest, ATickWhoseTimeRepeatsOrStepsBackChangesNoWheelSpeed) {
  auto explorer = MakeExplorer(ClassicalOptions());
  Driver driver(*explorer);
  msgs::WheelSpeedCommand last;
  for (int k = 0; k < 100; ++k) last = driver.Tick();
  ASSERT_GT(std::abs(last.left_rad_s) + std::abs(last.right_rad_s), 0.0);
  msgs::RangeRing ring = RoomRing(0.5);
  robot::ControllerInput input;
  input.sonar = &ring;
  for (const double back_s : {0.0, 0.5, 1e6}) {
    SCOPED_TRACE(back_s);
    input.time_s = 0.99 - back_s;  // the last tick's time, or earlier
    const msgs::WheelSpeedCommand c = explorer->Update(input);
    EXPECT_EQ(c.left_rad_s, last.left_rad_s);
    EXPECT_EQ(c.right_rad_s, last.right_rad_s);
  }
}

TEST(SonarExplorerTest, RingsWithUnusableRangesFewTransducersAndAFarPoseAreTakenInStride) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  SonarExplorerOptions options = ClassicalOptions();
  options.perimeter_max_s = 0.3;  // the far pose below meets the planner too
  auto explorer = MakeExplorer(options);
  Driver driver(*explorer);
  for (int k = 0; k < 50; ++k) driver.Tick();
  robot::ControllerInput input;
  double t = driver.time_s();
  msgs::RangeRing ring = RoomRing(t);
  const double bad[] = {kNan, kInf, -kInf, 0.0, -0.3};
  for (int i = 0; i < kSonars; ++i) ring.readings[i].range_m = bad[i % 5];
  input.sonar = &ring;
  for (int k = 0; k < 20; ++k, t += kDt) {
    ring.time_s = t;
    input.time_s = t;
    const msgs::WheelSpeedCommand c = explorer->Update(input);
    EXPECT_TRUE(std::isfinite(c.left_rad_s) && std::isfinite(c.right_rad_s));
  }
  ring.readings.resize(2);  // fewer transducers than the ring had
  for (int k = 0; k < 20; ++k, t += kDt) {
    ring.time_s = t;
    input.time_s = t;
    explorer->Update(input);
  }
  // An estimate that jumps 1e6 m (and 1e300 m) off the grid: nothing is written, no cell read.
  ring = RoomRing(t);
  for (const double x : {1e6, 1e300}) {
    for (int k = 0; k < 300; ++k, t += kDt) {
      ring.time_s = t;
      input.time_s = t;
      input.X_WR_estimate = {x, -x, 1e300};
      const msgs::WheelSpeedCommand c = explorer->Update(input);
      EXPECT_TRUE(std::isfinite(c.left_rad_s) && std::isfinite(c.right_rad_s));
    }
  }
  EXPECT_TRUE(explorer->perimeter_done());
  for (int ix = 0; ix < explorer->grid().width(); ++ix)
    for (int iy = 0; iy < explorer->grid().height(); ++iy)
      ASSERT_TRUE(std::isfinite(explorer->grid().LogOdds(ix, iy)));
}

}  // namespace
}  // namespace plywood::perception
