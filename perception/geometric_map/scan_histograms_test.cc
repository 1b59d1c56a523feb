#include "perception/geometric_map/scan_histograms.h"

#include <gtest/gtest.h>

#include <numbers>

#include "tests/support/synthetic_scan.h"

namespace plywood::perception {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

std::vector<RangePoint> Points(const msgs::LaserScan& scan) {
  FusionOptions ir_only;
  ir_only.source = RangeSource::kIrOnly;
  return FuseRanges(scan, nullptr, ir_only);
}

// A 4 x 2.5 m rectangle turned by 30.5 deg, seen from (0.3, -0.2) in its own frame: the long sides
// run at 30.5 deg and dominate the angle histogram; the distance histograms in the frame turned by
// alpha_max find the four sides at their exact distances.
TEST(ScanHistogramsTest, MainDirectionAndWallDistancesOfARotatedRectangle) {
  const double theta = 30.5 * kDeg;
  const std::vector<test::Wall> room = test::Rectangle(-2.3, -1.05, 1.7, 1.45, theta);
  const msgs::LaserScan scan = test::SyntheticScan(room, {}, 200, 10.0);
  const std::vector<RangePoint> points = Points(scan);
  ASSERT_EQ(points.size(), 200u);
  const HistogramOptions options;
  const AngleHistogram angles = MakeAngleHistogram(points, options);
  EXPECT_NEAR(angles.MainDirectionRad(), theta, 1e-9);
  // The histogram peak itself is the [30, 31) deg bin.
  const auto peak = std::max_element(angles.votes.begin(), angles.votes.end());
  EXPECT_EQ(peak - angles.votes.begin(), 30);

  const DistanceHistograms d = MakeDistanceHistograms(points, angles.MainDirectionRad(), options);
  ASSERT_FALSE(d.x_positive.empty());
  ASSERT_FALSE(d.x_negative.empty());
  ASSERT_FALSE(d.y_positive.empty());
  ASSERT_FALSE(d.y_negative.empty());
  EXPECT_NEAR(d.x_positive[0].position_m, 1.7, 1e-9);
  EXPECT_NEAR(d.x_negative[0].position_m, -2.3, 1e-9);
  EXPECT_NEAR(d.y_positive[0].position_m, 1.45, 1e-9);
  EXPECT_NEAR(d.y_negative[0].position_m, -1.05, 1e-9);
}

// The same room turned by -70 deg (110 deg mod 180): alpha_max follows it.
TEST(ScanHistogramsTest, MainDirectionWrapsModuloPi) {
  const std::vector<test::Wall> room = test::Rectangle(-2.3, -1.05, 1.7, 1.45, -70.0 * kDeg);
  const std::vector<RangePoint> points = Points(test::SyntheticScan(room, {}, 200, 10.0));
  EXPECT_NEAR(MakeAngleHistogram(points, {}).MainDirectionRad(), 110.0 * kDeg, 1e-9);
}

TEST(ScanHistogramsTest, StrongestMaximaPerSideStrongestFirst) {
  // Three piles on the positive side (5, 9 and 2 votes) and one on the negative side.
  std::vector<double> c;
  for (int i = 0; i < 5; ++i) c.push_back(0.52);
  for (int i = 0; i < 9; ++i) c.push_back(1.51);
  for (int i = 0; i < 2; ++i) c.push_back(2.53);
  for (int i = 0; i < 4; ++i) c.push_back(-1.02);
  const auto positive = StrongestMaxima(c, 0.05, true, 2);
  ASSERT_EQ(positive.size(), 2u);
  EXPECT_DOUBLE_EQ(positive[0].position_m, 1.51);
  EXPECT_DOUBLE_EQ(positive[0].votes, 9.0);
  EXPECT_DOUBLE_EQ(positive[1].position_m, 0.52);
  const auto negative = StrongestMaxima(c, 0.05, false, 3);
  ASSERT_EQ(negative.size(), 1u);
  EXPECT_DOUBLE_EQ(negative[0].position_m, -1.02);
}

TEST(ScanHistogramsTest, OptionsNameTheBadField) {
  HistogramOptions o;
  o.angle_bin_deg = 0.0;
  EXPECT_THROW(
      {
        try {
          o.Validate();
        } catch (const std::invalid_argument& e) {
          EXPECT_EQ(std::string(e.what()).rfind("angle_bin_deg:", 0), 0u) << e.what();
          throw;
        }
      },
      std::invalid_argument);
}

}  // namespace
}  // namespace plywood::perception
