#include "perception/lines/circle_feature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "perception/lines/hough_extractor.h"
#include "perception/lines/incremental_extractor.h"
#include "perception/lines/ransac_extractor.h"
#include "perception/lines/ray_explanation.h"
#include "perception/lines/scan_scene_test_support.h"
#include "perception/lines/split_and_merge_extractor.h"

namespace plywood::perception {
namespace {

constexpr double kPi = std::numbers::pi;
using testing::Disc;
using testing::ScanScene;

// n points on the arc of (centre, radius) from a0 to a1 (radians), optionally with noise along
// the radius.
std::vector<Eigen::Vector2d> Arc(const Eigen::Vector2d& centre, double radius_m, double a0,
                                 double a1, int n, double noise_m = 0.0, unsigned seed = 3) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_m > 0 ? noise_m : 1.0);
  std::vector<Eigen::Vector2d> out;
  for (int k = 0; k < n; ++k) {
    const double a = a0 + (a1 - a0) * k / (n - 1);
    const double r = radius_m + (noise_m > 0 ? noise(rng) : 0.0);
    out.push_back(centre + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return out;
}

std::vector<int> All(int n) {
  std::vector<int> out(n);
  for (int i = 0; i < n; ++i) out[i] = i;
  return out;
}

TEST(CircleFeatureTest, AnExactArcGivesItsCentreAndRadius) {
  // 12 points over 120 deg of a 0.08 m leg 2 m away: the closed form back to 1e-9.
  const Eigen::Vector2d centre(2.0, -0.5);
  const std::vector<Eigen::Vector2d> points = Arc(centre, 0.08, 2.0, 2.0 + 2.0 * kPi / 3.0, 12);
  const std::optional<CircleFeature> c = FitCircleFeature(points, All(12), {});
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->centre.x(), 2.0, 1e-9);
  EXPECT_NEAR(c->centre.y(), -0.5, 1e-9);
  EXPECT_NEAR(c->radius_m, 0.08, 1e-9);
  EXPECT_NEAR(c->rms_m, 0.0, 1e-9);
  EXPECT_EQ(c->num_points(), 12);
  for (const Eigen::Vector2d& p : points) EXPECT_NEAR(c->RimDistance(p), 0.0, 1e-9);
  EXPECT_NEAR(c->RimDistance(centre), 0.08, 1e-12);
}

TEST(CircleFeatureTest, ANoisyArcIsFoundWithinItsNoise) {
  // 1 cm noise on a 0.3 m column, 40 points over 150 deg: centre and radius to a few mm.
  const Eigen::Vector2d centre(-1.5, 2.0);
  const std::vector<Eigen::Vector2d> points =
      Arc(centre, 0.3, -0.9, -0.9 + 150.0 * kPi / 180.0, 40, 0.01);
  const std::optional<CircleFeature> c = FitCircleFeature(points, All(40), {});
  ASSERT_TRUE(c.has_value());
  EXPECT_LT((c->centre - centre).norm(), 0.01);
  EXPECT_NEAR(c->radius_m, 0.3, 0.01);
  EXPECT_LT(c->rms_m, 0.012);
}

TEST(CircleFeatureTest, TheGatesHold) {
  const std::vector<Eigen::Vector2d> big = Arc({0.0, 3.0}, 0.8, -2.5, -0.6, 30);
  EXPECT_FALSE(FitCircleFeature(big, All(30), {}).has_value()) << "radius over 0.5 m";
  CircleFeatureGates wide;
  wide.max_radius_m = 1.0;
  EXPECT_TRUE(FitCircleFeature(big, All(30), wide).has_value());
  // 5 cm noise on a 1 cm-noise sensor: not a real fit.
  const std::vector<Eigen::Vector2d> rough = Arc({2.0, 0.0}, 0.2, 2.0, 4.3, 30, 0.05);
  EXPECT_FALSE(FitCircleFeature(rough, All(30), {}).has_value()) << "residual gate";
  const std::vector<Eigen::Vector2d> few = Arc({2.0, 0.0}, 0.2, 2.0, 4.3, 4);
  EXPECT_FALSE(FitCircleFeature(few, All(4), {}).has_value()) << "fewer than 5 points";
}

TEST(CircleFeatureTest, AStraightWallNeverGivesACircle) {
  // Collinear points, exact and with 1 cm noise over many seeds: no fit passes the gates.
  for (unsigned seed = 0; seed < 50; ++seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.01);
    std::vector<Eigen::Vector2d> wall;
    for (int k = 0; k < 20; ++k) wall.push_back({1.5 + noise(rng), -0.5 + 0.05 * k});
    EXPECT_FALSE(FitCircleFeature(wall, All(20), {}).has_value()) << "seed " << seed;
  }
  // A room of straight walls only, 1 cm noise: every extractor reports lines and no circle.
  const std::vector<Eigen::Vector2d> room{{-2.5, -2.0}, {3.5, -2.0}, {3.5, 3.0}, {-2.5, 3.0}};
  for (unsigned seed = 1; seed <= 10; ++seed) {
    const ScanPoints scan = ScanScene({room}, {}, 0.01, 20.0, seed);
    EXPECT_TRUE(SplitAndMergeExtractor().ExtractFeatures(scan).circles.empty()) << seed;
    EXPECT_TRUE(IncrementalExtractor().ExtractFeatures(scan).circles.empty()) << seed;
    EXPECT_TRUE(RansacExtractor().ExtractFeatures(scan).circles.empty()) << seed;
    EXPECT_TRUE(HoughExtractor().ExtractFeatures(scan).circles.empty()) << seed;
  }
}

TEST(CircleFeatureTest, ExtractorsReportTheColumnsTheyTakeOutOfTheLines) {
  // Two columns in a room, 1 cm noise: no line on either, one circle on each with its true
  // centre and radius (within the noise), and the lines are those Extract gives.
  const std::vector<Eigen::Vector2d> room{{-2.5, -2.0}, {3.5, -2.0}, {3.5, 3.0}, {-2.5, 3.0}};
  const Disc near_column{{1.3, 0.2}, 0.2}, far_column{{-1.0, 2.2}, 0.15};
  const ScanPoints scan = ScanScene({room}, {near_column, far_column}, 0.01);
  const SplitAndMergeExtractor split_and_merge;
  const IncrementalExtractor incremental;
  const RansacExtractor ransac;
  const HoughExtractor hough;
  for (const LineExtractor* e :
       std::vector<const LineExtractor*>{&split_and_merge, &incremental, &ransac, &hough}) {
    const ExtractedFeatures f = e->ExtractFeatures(scan);
    EXPECT_EQ(f.lines.size(), e->Extract(scan).size()) << e->name();
    for (const Disc& disc : {near_column, far_column}) {
      int found = 0;
      for (const CircleFeature& c : f.circles) {
        if ((c.centre - disc.centre).norm() > 0.05) continue;
        ++found;
        EXPECT_NEAR(c.radius_m, disc.radius_m, 0.03) << e->name();
        EXPECT_GE(c.num_points(), 8) << e->name();
        for (int i : c.point_indices) EXPECT_LT(c.RimDistance(scan.points[i]), 0.04) << e->name();
      }
      EXPECT_EQ(found, 1) << e->name() << " column at " << disc.centre.transpose();
    }
    EXPECT_EQ(f.circles.size(), 2u) << e->name();
    // The circles explain the columns' rays, which no line does.
    const RayExplanation lines_only = ExplainRays(scan.points, f.lines);
    const RayExplanation with_circles = ExplainRays(scan.points, f.lines, f.circles);
    EXPECT_GT(with_circles.explained, lines_only.explained + 16) << e->name();
    EXPECT_EQ(with_circles.rays, lines_only.rays);
  }
}

}  // namespace
}  // namespace plywood::perception
