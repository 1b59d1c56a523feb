#include "perception/geometric_map/pose_correction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

#include "perception/geometric_map/scan_segmentation.h"
#include "tests/support/synthetic_scan.h"

namespace plywood::perception {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// An L-shaped room with a box in it, for scans that differ from pose to pose.
std::vector<test::Wall> Room() {
  std::vector<test::Wall> walls = {{{-3, -2}, {3, -2}}, {{3, -2}, {3, 0.5}}, {{3, 0.5}, {1, 0.5}},
                                   {{1, 0.5}, {1, 2}},  {{1, 2}, {-3, 2}},   {{-3, 2}, {-3, -2}}};
  for (const auto& w : test::Rectangle(-1.2, -0.6, -0.8, -0.2)) walls.push_back(w);
  return walls;
}

// An exact IR-only scan of `world` from `truth`, 3 m cut.
std::vector<RangePoint> IrScan(const std::vector<test::Wall>& world, const msgs::Pose2D& truth,
                               int beams = 200) {
  FusionOptions ir_only;
  ir_only.source = RangeSource::kIrOnly;
  return FuseRanges(test::SyntheticScan(world, truth, beams, 3.0), nullptr, ir_only);
}

// Exact odometry driven east down a corridor 2 m wide, from x -1.5 in steps of 0.15 m, for
// `scans` scans: its end wall at x 3.01 comes within the IR's 3 m from scan 11. `passing` adds
// walls to the world of the scans it names. The corrected pose must stay on the truth.
void ExpectExactOdometryStaysExactDownTheCorridor(
    const PoseCorrectionOptions& options, int scans,
    const std::map<int, std::vector<test::Wall>>& passing) {
  HistogramPoseCorrector corrector({}, options);
  const std::vector<test::Wall> corridor = {
      {{-20, -1}, {20, -1}}, {{20, 1}, {-20, 1}}, {{3.01, -1}, {3.01, 1}}};
  for (int k = 0; k < scans; ++k) {
    const msgs::Pose2D truth{-1.5 + 0.15 * k, 0.0, 0.0};
    std::vector<test::Wall> world = corridor;
    if (const auto extra = passing.find(k); extra != passing.end()) {
      world.insert(world.end(), extra->second.begin(), extra->second.end());
    }
    const std::vector<RangePoint> points = IrScan(world, truth, 720);
    const msgs::Pose2D corrected = corrector.Correct(truth, points);
    EXPECT_NEAR(corrected.x_m, truth.x_m, 0.002) << "scan " << k;
    EXPECT_NEAR(corrected.y_m, truth.y_m, 0.01) << "scan " << k;
  }
}

// The lines fitted to `points` (a 200-beam scan), which refine the heading.
std::vector<LineSegment> FittedLines(const std::vector<RangePoint>& points) {
  std::vector<LineSegment> lines_R;
  for (const MapSegment& s : ExtractScanFeatures(points, 200, {}, {}).segments) {
    lines_R.push_back(s.line);
  }
  return lines_R;
}

// The robot drives east along y = -0.9 and turns; its odometry gains 0.4 deg of heading and 1 cm
// of x per scan. Exact scans: the corrected heading stays within 0.05 deg of the truth and the
// position within 3 cm (2 cm histogram bins), while the odometry ends 11.6 deg and 0.29 m off.
TEST(PoseCorrectionTest, HistogramsRemoveOdometryDrift) {
  HistogramPoseCorrector corrector({}, {});  // heading and position
  const int scans = 30;
  for (int k = 0; k < scans; ++k) {
    const msgs::Pose2D truth{-2.0 + 0.15 * k, -0.9, 0.05 * k};
    const msgs::Pose2D odometry{truth.x_m + 0.01 * k, truth.y_m, truth.theta_rad + 0.4 * kDeg * k};
    const std::vector<RangePoint> points = IrScan(Room(), truth);
    const msgs::Pose2D corrected = corrector.Correct(odometry, points, FittedLines(points));
    EXPECT_LT(std::abs(msgs::WrapAngle(corrected.theta_rad - truth.theta_rad)), 0.05 * kDeg)
        << "scan " << k;
    EXPECT_LT(std::hypot(corrected.x_m - truth.x_m, corrected.y_m - truth.y_m), 0.03)
        << "scan " << k;
  }
}

// Along a corridor with no wall across it within the scanner's reach, exact odometry stays
// exact: the points of the side walls, denser behind the robot where earlier scans saw them, do
// not vote on the shift along the corridor (they pulled it back by up to max_shift_m a scan).
TEST(PoseCorrectionTest, CorridorSideWallsDoNotPullThePositionBack) {
  HistogramPoseCorrector corrector({}, {});
  const std::vector<test::Wall> corridor = {{{-20, -1}, {20, -1}}, {{20, 1}, {-20, 1}}};
  for (int k = 0; k < 30; ++k) {
    const msgs::Pose2D truth{0.15 * k, 0.5, 0.0};  // 0.5 m from a wall: dense points near it
    const std::vector<RangePoint> points = IrScan(corridor, truth, 720);
    const msgs::Pose2D corrected = corrector.Correct(truth, points);
    EXPECT_NEAR(corrected.x_m, truth.x_m, 1e-9) << "scan " << k;
    EXPECT_NEAR(corrected.y_m, truth.y_m, 0.01) << "scan " << k;
  }
}

// Odometry that creeps a quarter of a 2 cm bin a scan in x and y, exact scans (sharp walls: each
// fills one bin, so the correlation's parabola has nothing to fit): refined below the bin, the
// position stays within 6 mm (one scan with no wall across x keeps its 5 mm creep); whole bins
// alone let the creep grow past a bin before they take it back (2.7 cm).
TEST(PoseCorrectionTest, PositionCreepBelowABinIsCorrected) {
  PoseCorrectionOptions options;
  options.refine_position = true;
  HistogramPoseCorrector corrector({}, options);
  for (int k = 0; k < 30; ++k) {
    const msgs::Pose2D truth{-2.0 + 0.15 * k, -0.9, 0.05 * k};
    const msgs::Pose2D odometry{truth.x_m + 0.005 * k, truth.y_m - 0.005 * k, truth.theta_rad};
    const std::vector<RangePoint> points = IrScan(Room(), truth);
    const msgs::Pose2D corrected = corrector.Correct(odometry, points, FittedLines(points));
    EXPECT_LT(std::hypot(corrected.x_m - truth.x_m, corrected.y_m - truth.y_m), 0.006)
        << "scan " << k;
  }
}

// The end of a corridor comes into reach while the reference holds only a glimpse of something
// 2.5 cm before it (one scan saw a post's face there, a bin nearer): exact odometry must stay
// exact. Matched against those few points alone, the wall's 70 votes took the shift by a whole
// 2 cm bin (office seed 1, IR only, t = 122.5 s: the east end wall's 13 votes against one point).
TEST(PoseCorrectionTest, AWallSeenFirstDoesNotFollowAGlimpseInTheReference) {
  PoseCorrectionOptions options;
  options.require_reference_support = true;
  ExpectExactOdometryStaysExactDownTheCorridor(
      options, 15, {{10, {{{2.985, 0.0}, {2.985, 0.15}}}}});  // the glimpse, 2.99 m away
}

// The end of a corridor comes into reach with nothing of it in the reference, while a person
// walks by: seen 6 cm nearer in the scan before (a few points each time). The correlation's peak
// is those points against the person's earlier ones (the only pairs within max_shift_m), which
// moved x by 6 cm (generated columns_s1_00006 seed 1, t = 141 s: one pair moved y by 8 cm;
// room_s907_00002 seed 1 without refine_position). A shift needs min_peak_votes scan points with a
// reference point within a bin of them, so x is left alone and exact odometry stays exact.
const std::map<int, std::vector<test::Wall>> kPersonWalksByTheEndWall = {
    {10, {{{1.94, -0.35}, {1.94, -0.2}}}}, {11, {{{2.0, -0.35}, {2.0, -0.2}}}}};

TEST(PoseCorrectionTest, AShiftMatchedByTooFewPointsLeavesTheAxisAlone) {
  PoseCorrectionOptions options;
  options.refine_position = true;  // applies the rule
  ExpectExactOdometryStaysExactDownTheCorridor(options, 13, kPersonWalksByTheEndWall);
}

TEST(PoseCorrectionTest, APlainCorrelationPeakMatchedByTooFewPointsLeavesTheAxisAlone) {
  PoseCorrectionOptions options;
  options.require_peak_support = true;  // the plain correlation, not refined
  ExpectExactOdometryStaysExactDownTheCorridor(options, 13, kPersonWalksByTheEndWall);
}

// A wheel spinning against a wall: the odometry's heading jumps 20 deg in one scan while the robot
// stands still. The heading window grows with the turn the odometry reports, so the correction
// finds the truth again (a fixed 3 deg window stays 17 deg off).
TEST(PoseCorrectionTest, HeadingJumpOfAJammedWheelIsCorrected) {
  HistogramPoseCorrector corrector({}, {});
  for (int k = 0; k < 6; ++k) {
    const msgs::Pose2D truth{-2.0, -0.9, 0.1};
    const msgs::Pose2D odometry{truth.x_m, truth.y_m, truth.theta_rad + (k >= 3 ? 20 * kDeg : 0.0)};
    const std::vector<RangePoint> points = IrScan(Room(), truth);
    const msgs::Pose2D corrected = corrector.Correct(odometry, points, FittedLines(points));
    EXPECT_LT(std::abs(msgs::WrapAngle(corrected.theta_rad - truth.theta_rad)), 0.05 * kDeg)
        << "scan " << k;
  }
}

TEST(PoseCorrectionTest, OffLeavesOdometryAlone) {
  PoseCorrectionOptions off;
  off.heading = false;
  off.position = false;
  HistogramPoseCorrector corrector({}, off);
  for (int k = 0; k < 5; ++k) {
    const msgs::Pose2D truth{-2.0 + 0.15 * k, -0.9, 0.05 * k};
    const msgs::Pose2D odometry{truth.x_m, truth.y_m + 0.02 * k, truth.theta_rad + kDeg * k};
    const std::vector<RangePoint> points = IrScan(Room(), truth);
    const msgs::Pose2D corrected = corrector.Correct(odometry, points);
    EXPECT_NEAR(corrected.x_m, odometry.x_m, 1e-12);
    EXPECT_NEAR(corrected.y_m, odometry.y_m, 1e-12);
    EXPECT_NEAR(corrected.theta_rad, odometry.theta_rad, 1e-12);
  }
}

TEST(PoseCorrectionTest, AnOdometryPoseThatIsNotFiniteIsRefused) {
  // A NaN pose from the odometry went into the histograms (UBSan: a signed overflow binning it)
  // and the correction; refused, naming it, the correction goes on as before.
  HistogramPoseCorrector corrector({}, {});
  const msgs::Pose2D truth{0.3, -0.2, 0.1};
  corrector.Correct(truth, IrScan(Room(), truth));
  const msgs::Pose2D X_WO = corrector.X_WO();
  for (const msgs::Pose2D& bad :
       {msgs::Pose2D{std::nan(""), 0.0, 0.0}, msgs::Pose2D{0.0, HUGE_VAL, 0.0},
        msgs::Pose2D{0.0, 0.0, std::nan("")}}) {
    try {
      corrector.Correct(bad, IrScan(Room(), truth));
      ADD_FAILURE() << "no throw";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("X_OR: must be finite, got (", 0), 0u) << e.what();
    }
  }
  EXPECT_EQ(corrector.X_WO().x_m, X_WO.x_m);
  EXPECT_EQ(corrector.X_WO().y_m, X_WO.y_m);
  EXPECT_EQ(corrector.X_WO().theta_rad, X_WO.theta_rad);
  const msgs::Pose2D corrected = corrector.Correct(truth, IrScan(Room(), truth));
  EXPECT_NEAR(corrected.x_m, truth.x_m, 0.02);
  EXPECT_NEAR(corrected.y_m, truth.y_m, 0.02);
  EXPECT_NEAR(corrected.theta_rad, truth.theta_rad, 0.01);
}

}  // namespace
}  // namespace plywood::perception
