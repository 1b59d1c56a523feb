#include "perception/geometric_map/scan_segmentation.h"

#include <gtest/gtest.h>

#include <numbers>

#include "tests/support/synthetic_scan.h"

namespace plywood::perception {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// 50 points 2 cm apart on the line through (1, 2) at 25 deg; every fifth (20 %) pushed 0.3 m off
// the line, as the IR head's single outliers. The modal filter recovers the line to 1 mm and
// 0.1 deg; least squares is pulled 6 cm off.
TEST(ScanSegmentationTest, ModalFitIgnoresTwentyPercentOutliersLeastSquaresDoesNot) {
  const Eigen::Vector2d origin(1.0, 2.0), d(std::cos(25 * kDeg), std::sin(25 * kDeg));
  const Eigen::Vector2d n(-d.y(), d.x());
  std::vector<Eigen::Vector2d> points;
  std::vector<int> indices;
  for (int k = 0; k < 50; ++k) {
    points.push_back(origin + 0.02 * k * d +
                     (k % 5 == 2 ? Eigen::Vector2d(0.3 * n) : Eigen::Vector2d::Zero()));
    indices.push_back(k);
  }
  double true_alpha = 0, true_r = 0;
  CanonicalNormalForm(std::atan2(n.y(), n.x()), n.dot(origin), &true_alpha, &true_r);

  SegmentationOptions modal;
  const MapSegment m = FitMapSegment(points, indices, modal);
  EXPECT_LT(AngleDifferenceRad(m.line.alpha_rad, true_alpha), 0.1 * kDeg);
  EXPECT_LT(std::abs(m.line.r_m - true_r), 0.001);
  EXPECT_EQ(m.inliers, 40);

  SegmentationOptions tls;
  tls.fit = LineFitMethod::kTotalLeastSquares;
  const MapSegment t = FitMapSegment(points, indices, tls);
  EXPECT_GT(std::abs(t.line.r_m - true_r), 0.05);
}

// An inside corner at (1.5, 1) seen from the origin, and a 10 cm post at (0, -1): two lines meeting
// at the corner (the intersection of their fits: within 1 mm, as the split point next to the
// corner takes part in a fit), and the post as a cluster.
TEST(ScanSegmentationTest, CornerBecomesTwoLinesMeetingAtTheIntersectionPostACluster) {
  const std::vector<test::Wall> walls = {
      {{1.5, -3.0}, {1.5, 1.0}}, {{1.5, 1.0}, {-3.0, 1.0}}, {{-0.05, -0.95}, {0.05, -0.95}}};
  const msgs::Pose2D X_WR{0.5, -0.25, 0.3};  // the map frame differs from the robot's
  const msgs::Pose2D X_RW = X_WR.Inverse();
  // The same walls in the robot frame, scanned from its origin.
  std::vector<test::Wall> walls_R;
  const auto to_R = [&](const Eigen::Vector2d& p) {
    const msgs::Pose2D q = X_RW * msgs::Pose2D{p.x(), p.y(), 0.0};
    return Eigen::Vector2d(q.x_m, q.y_m);
  };
  for (const auto& [a, b] : walls) walls_R.push_back({to_R(a), to_R(b)});
  FusionOptions ir_only;
  ir_only.source = RangeSource::kIrOnly;
  const msgs::LaserScan scan = test::SyntheticScan(walls_R, {}, 200, 3.0);
  const std::vector<RangePoint> points = FuseRanges(scan, nullptr, ir_only);
  const ScanFeatures f = ExtractScanFeatures(points, 200, X_WR, {});
  ASSERT_EQ(f.segments.size(), 2u);
  EXPECT_NEAR((f.segments[0].line.end - Eigen::Vector2d(1.5, 1.0)).norm(), 0.0, 1e-3);
  EXPECT_EQ(f.segments[0].line.end, f.segments[1].line.start);
  for (const MapSegment& s : f.segments) EXPECT_EQ(s.inliers, s.line.num_points);
  ASSERT_EQ(f.clusters.size(), 1u);
  EXPECT_NEAR(f.clusters[0].box.min().y(), -0.95, 1e-9);
  EXPECT_NEAR(f.clusters[0].box.max().y(), -0.95, 1e-9);
  EXPECT_GE(f.clusters[0].box.min().x(), -0.05 - 1e-9);
  EXPECT_LE(f.clusters[0].box.max().x(), 0.05 + 1e-9);
}

TEST(ScanSegmentationTest, NegativeDistMaxNamesTheField) {
  SegmentationOptions o;
  o.dist_max_m = -0.1;
  try {
    o.Validate();
    FAIL() << "negative DIST_MAX accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("dist_max_m:", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace plywood::perception
