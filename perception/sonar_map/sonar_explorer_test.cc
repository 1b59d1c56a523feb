#include "perception/sonar_map/sonar_explorer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
  const SonarExplorerOptions options = ClassicalOptions();
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

void ExpectThrowsNaming(const SonarExplorerOptions& options, const std::string& field) {
  try {
    MakeExplorer(options);
    ADD_FAILURE() << "no exception for " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
  }
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

}  // namespace
}  // namespace plywood::perception
