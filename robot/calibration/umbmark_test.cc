// UMBmark's sign conventions checked against a kinematic robot with known injected errors: the
// robot drives each square exactly as its (nominal) odometry tells it, its true wheels differ, and
// the analysis must recover the injected E_d and E_b and a correction that removes the error.

#include "robot/calibration/umbmark.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "robot/calibration/turn_calibration.h"
#include "robot/drive/diff_drive_kinematics.h"

namespace plywood::robot {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSide = 4.0, kTrack = 0.33, kRadius = 0.0975;

// A real drive: true wheel radii from E_d (mean nominal) and track E_b * nominal. The odometry
// believes `believed`. Driving "by odometry" means: a leg turns both wheels so that the believed
// wheel travels are equal and sum to the side, a turn so that the believed heading change is
// exactly 90 deg; the true pose integrates the true travels in small exact arc steps.
struct KinematicRobot {
  OdometryGeometry truth;
  OdometryGeometry believed;

  msgs::Pose2D Move(msgs::Pose2D X, double left_rad, double right_rad) const {
    const int steps = 200;
    for (int i = 0; i < steps; ++i) {
      const double l = truth.left_wheel_radius_m * left_rad / steps;
      const double r = truth.right_wheel_radius_m * right_rad / steps;
      X = IntegrateArc(X, (l + r) / 2.0, (r - l) / truth.track_m);
    }
    return X;
  }

  // Final true pose after one square from X_start (odometry returns exactly to X_start).
  msgs::Pose2D Square(SquareDirection direction, msgs::Pose2D X) const {
    const double sign = direction == SquareDirection::kCounterClockwise ? 1.0 : -1.0;
    for (int leg = 0; leg < 4; ++leg) {
      X = Move(X, kSide / believed.left_wheel_radius_m, kSide / believed.right_wheel_radius_m);
      // Believed turn: (r_R phi_R + r_L phi_L) / b = pi / 2 with phi_R = -phi_L = phi.
      const double phi = sign * (kPi / 2.0) * believed.track_m /
                         (believed.left_wheel_radius_m + believed.right_wheel_radius_m);
      X = Move(X, -phi, phi);
    }
    return X;
  }
};

KinematicRobot Robot(double ed, double eb, OdometryCalibration calibration = {}) {
  DiffDriveSpec nominal;
  nominal.wheel_radius_m = kRadius;
  nominal.track_m = kTrack;
  return {CalibratedGeometry(nominal, {.wheel_diameter_ratio = ed, .track_ratio = eb}),
          CalibratedGeometry(nominal, calibration)};
}

std::vector<UmbmarkRun> Benchmark(const KinematicRobot& robot, msgs::Pose2D start = {}) {
  std::vector<UmbmarkRun> runs;
  for (SquareDirection d : {SquareDirection::kClockwise, SquareDirection::kCounterClockwise}) {
    const msgs::Pose2D end = robot.Square(d, start);
    runs.push_back(UmbmarkReturnError(d, start, end, start));
  }
  return runs;
}

TEST(UmbmarkTest, WheelbaseErrorAloneIsTypeA) {
  // E_b > 1: every turn falls short, alpha > 0; both clusters lie at -2 L alpha in x and mirror
  // each other in y.
  const UmbmarkResult r = AnalyseUmbmark(Benchmark(Robot(1.0, 1.02)), kSide, kTrack);
  EXPECT_GT(r.alpha_rad, 0.0);
  EXPECT_NEAR(r.beta_rad, 0.0, 2e-4);
  EXPECT_LT(r.x_cg_cw_m, 0.0);
  EXPECT_NEAR(r.x_cg_cw_m, r.x_cg_ccw_m, 0.05 * std::abs(r.x_cg_cw_m));
  EXPECT_NEAR(r.y_cg_cw_m, -r.y_cg_ccw_m, 0.05 * std::abs(r.y_cg_cw_m));
  EXPECT_NEAR(r.eb, 1.02, 0.002);
  EXPECT_NEAR(r.ed, 1.0, 1e-4);
}

TEST(UmbmarkTest, UnequalWheelsAloneAreTypeB) {
  // E_d > 1 (right wheel larger): legs curve left, beta > 0; the turns are still exact.
  const UmbmarkResult r = AnalyseUmbmark(Benchmark(Robot(1.005, 1.0)), kSide, kTrack);
  EXPECT_GT(r.beta_rad, 0.0);
  // Only to first order: the legs' curvature leaks L beta^2 ~ 1.4 cm into the clusters, about
  // 0.1 deg of apparent alpha.
  EXPECT_NEAR(r.alpha_rad, 0.0, 2.5e-3);
  EXPECT_NEAR(r.ed, 1.005, 3e-4);
  EXPECT_NEAR(r.eb, 1.0, 0.002);
}

TEST(UmbmarkTest, RecoversTheAcceptanceErrorsAndTheCorrectionRemovesThem) {
  // Issue 3's acceptance case, here without physics; the start pose is arbitrary.
  const msgs::Pose2D start{-2.0, -2.0, 0.7};
  const UmbmarkResult before = AnalyseUmbmark(Benchmark(Robot(1.005, 1.03), start), kSide, kTrack);
  EXPECT_NEAR(before.ed, 1.005, 0.001);
  EXPECT_NEAR(before.eb, 1.03, 0.005);
  const OdometryCalibration corrected = CorrectedCalibration({}, before);
  const UmbmarkResult after =
      AnalyseUmbmark(Benchmark(Robot(1.005, 1.03, corrected), start), kSide, kTrack);
  EXPECT_LT(after.e_max_syst_m, before.e_max_syst_m / 20.0)
      << before.e_max_syst_m << " -> " << after.e_max_syst_m;
  // A second round converges further: the correction composes with the one used.
  const UmbmarkResult again = AnalyseUmbmark(
      Benchmark(Robot(1.005, 1.03, CorrectedCalibration(corrected, after)), start), kSide, kTrack);
  EXPECT_LT(again.e_max_syst_m, after.e_max_syst_m);
}

TEST(UmbmarkTest, ReturnErrorIsInTheStartFrame) {
  // Facing +y, a true end 1 cm further along +y and 2 cm towards -x is (+0.01, +0.02) in the
  // start frame (x along the heading, y to its left).
  const UmbmarkRun run = UmbmarkReturnError(SquareDirection::kClockwise, {1, 1, kPi / 2},
                                            {0.98, 1.01, kPi / 2}, {1, 1, kPi / 2});
  EXPECT_NEAR(run.error_x_m, 0.01, 1e-12);
  EXPECT_NEAR(run.error_y_m, 0.02, 1e-12);
}

TEST(UmbmarkTest, NeedsBothDirections) {
  EXPECT_THROW(AnalyseUmbmark({{SquareDirection::kClockwise, 0.1, 0.1}}, kSide, kTrack),
               std::invalid_argument);
}

TEST(UmbmarkTest, ARunOrLengthThatIsNotAFiniteNumberIsRefusedByField) {
  // A NaN return error (an end pose the tracker lost) made every result NaN, and an infinite side
  // made alpha and beta 0: E_d = E_b = 1, a perfect robot. Each is refused, naming the field.
  const auto message = [](const std::vector<UmbmarkRun>& runs, double side_m, double track_m) {
    try {
      AnalyseUmbmark(runs, side_m, track_m);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no throw");
  };
  const std::vector<UmbmarkRun> good{{SquareDirection::kClockwise, -0.1, -0.1},
                                     {SquareDirection::kCounterClockwise, 0.05, -0.05}};
  EXPECT_EQ(message(good, HUGE_VAL, kTrack), "side_m: must be a finite number > 0, got inf");
  EXPECT_EQ(message(good, 0.0, kTrack), "side_m: must be a finite number > 0, got 0");
  EXPECT_EQ(message(good, kSide, std::nan("")), "track_m: must be a finite number > 0, got nan");
  std::vector<UmbmarkRun> runs = good;
  runs.push_back({SquareDirection::kCounterClockwise, std::nan(""), 0.0});
  EXPECT_EQ(message(runs, kSide, kTrack), "runs[2].error_x_m: must be finite, got nan");
  runs.back() = {SquareDirection::kClockwise, 0.0, -HUGE_VAL};
  EXPECT_EQ(message(runs, kSide, kTrack), "runs[2].error_y_m: must be finite, got -inf");
  EXPECT_EQ(message(good, kSide, kTrack), "no throw");
}

TEST(TurnCalibrationTest, MeanErrorOfNinetyDegreeTurns) {
  // Seed 001: n turns of 90 deg by odometry, the robot really turns 87.4 deg (E_b = 1.03).
  std::vector<TurnObservation> turns;
  for (int i = 0; i < 8; ++i) {
    const double sign = i % 2 ? -1.0 : 1.0;
    turns.push_back({sign * kPi / 2.0, sign * (kPi / 2.0) / 1.03});
  }
  const TurnCalibration c = CalibrateTurns(turns);
  EXPECT_EQ(c.turns, 8);
  EXPECT_NEAR(c.mean_error_deg, 90.0 / 1.03 - 90.0, 1e-9);
  EXPECT_NEAR(c.error_sigma_deg, 0.0, 1e-9);
  EXPECT_NEAR(c.track_ratio, 1.03, 1e-12);
  EXPECT_THROW(CalibrateTurns({}), std::invalid_argument);
}

}  // namespace
}  // namespace plywood::robot
