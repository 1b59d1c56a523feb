#include "perception/lines/circle_feature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <string>
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
#ifdef PLYWOOD_SANITIZED_BUILD
// Under ASan + UBSan the extractors run ~15x slower (these draws took 40 s of CI's sanitized
// pass): there the Monte-Carlo tests draw their first 20 noise seeds, which cover the code paths;
// the plain build draws all 100 for the rates.
constexpr unsigned kNoiseSeeds = 20;
#else
constexpr unsigned kNoiseSeeds = 100;
#endif
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
}

// Every extractor with a round-object stage.
const std::vector<const LineExtractor*>& RoundAwareExtractors() {
  static const SplitAndMergeExtractor split_and_merge;
  static const IncrementalExtractor incremental;
  static const RansacExtractor ransac;
  static const HoughExtractor hough;
  static const std::vector<const LineExtractor*> all{&split_and_merge, &incremental, &ransac,
                                                     &hough};
  return all;
}

TEST(CircleFeatureTest, AStraightWallInARoomNeverGivesACircle) {
  // Rooms of straight walls only, the nearest wall 0.5-6 m from the sensor (where the beams are
  // 4 mm apart the noise is wider than the spacing: any few neighbours look like a small arc),
  // 1 cm noise, kNoiseSeeds noise seeds each: every extractor reports lines and no circle. Before
  // the partial-run rule (round_object_filter.cc: a run that is not its whole breakpoint group
  // must bend away from one line by >= 25 sigma^2) RANSAC and Hough gave circles in up to 10 % of
  // these scans and split_and_merge in 1 %; at a 45 deg arc without that rule, noise seed 1 of
  // the first room (a 9-point bump 2 m away) gave split_and_merge a circle.
  for (double d : {2.0, 0.5, 0.75, 1.0, 1.5, 3.0, 4.0, 5.0, 6.0}) {
    const std::vector<Eigen::Vector2d> room =
        d == 2.0 ? std::vector<Eigen::Vector2d>{{-2.5, -2.0}, {3.5, -2.0}, {3.5, 3.0}, {-2.5, 3.0}}
                 : std::vector<Eigen::Vector2d>{{-4.0, -d}, {5.0, -d}, {5.0, 4.0}, {-4.0, 4.0}};
    for (unsigned seed = 1; seed <= kNoiseSeeds; ++seed) {
      const ScanPoints scan = ScanScene({room}, {}, 0.01, 20.0, seed);
      for (const LineExtractor* e : RoundAwareExtractors()) {
        EXPECT_TRUE(e->ExtractFeatures(scan).circles.empty())
            << e->name() << " wall at " << d << " m, seed " << seed;
      }
    }
  }
}

TEST(CircleFeatureTest, AFreeStandingFlatPieceOfAtLeast30CmRarelyGivesACircle) {
  // A straight piece standing free (empty beams at both ends: its whole breakpoint group) across
  // 5-40 beams, 0.5-6 m away, facing the sensor or turned 30 / 60 deg, 1 cm noise, 100 seeds: once
  // it is >= 0.3 m long a circle in fewer than 1 of 1000 scans per extractor (sparse 6-12 point
  // pieces 3-6 m away; a few of them gave one at the 100 deg arc too). Shorter pieces give more:
  // a 0.1-0.25 m flat face with 1 cm noise and a thin column's chord look alike (docs/lines.md
  // has the rates).
  int tried = 0;
  std::map<std::string, int> circles;
  for (double d : {0.5, 1.0, 2.0, 3.0, 4.0, 6.0}) {
    for (int n : {5, 6, 8, 10, 12, 15, 20, 30, 40}) {
      for (double tilt_deg : {0.0, 30.0, 60.0}) {
        const double a = -1.0, half = d * std::tan(n * 0.25 * kPi / 180.0);
        const double t = tilt_deg * kPi / 180.0, h = half / std::cos(t);
        if (2.0 * h < 0.3) continue;
        const Eigen::Vector2d c = d * Eigen::Vector2d(std::cos(a), std::sin(a));
        const Eigen::Vector2d u(-std::sin(a + t), std::cos(a + t));
        ++tried;
        for (unsigned seed = 1; seed <= kNoiseSeeds; ++seed) {
          const ScanPoints scan =
              ScanScene({testing::Panel(c - h * u, c + h * u)}, {}, 0.01, 20.0, seed);
          for (const LineExtractor* e : RoundAwareExtractors()) {
            circles[e->name()] += !e->ExtractFeatures(scan).circles.empty();
          }
        }
      }
    }
  }
  EXPECT_GT(tried, 30);
  for (const LineExtractor* e : RoundAwareExtractors()) {
    EXPECT_LT(circles[e->name()] * 1000, tried * kNoiseSeeds)
        << e->name() << ": " << circles[e->name()] << " of " << tried * kNoiseSeeds;
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
