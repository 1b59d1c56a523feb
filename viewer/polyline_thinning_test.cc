#include "viewer/polyline_thinning.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace plywood::viewer {
namespace {

// Distance from p to the segment [a, b].
double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t =
      ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

double DistanceToPolyline(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& line) {
  double best = (p - line.front()).norm();
  for (std::size_t i = 1; i < line.size(); ++i) {
    best = std::min(best, DistanceToSegment(p, line[i - 1], line[i]));
  }
  return best;
}

TEST(PolylineThinningTest, AStraightRunOfSamplesIsOneSegment) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i <= 1000; ++i) points.emplace_back(0.002 * i, 1.0);
  const auto thin = ThinPolyline(points, 0.005);
  ASSERT_EQ(thin.size(), 2u);
  EXPECT_EQ(thin.front(), points.front());
  EXPECT_EQ(thin.back(), points.back());
}

TEST(PolylineThinningTest, ASquareKeepsItsCornersAndNothingElse) {
  const Eigen::Vector2d corners[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  std::vector<Eigen::Vector2d> points;
  for (int side = 0; side < 4; ++side) {
    for (int i = 0; i < 100; ++i) {
      points.push_back(corners[side] + (corners[side + 1] - corners[side]) * (i / 100.0));
    }
  }
  points.push_back(corners[4]);
  const auto thin = ThinPolyline(points, 0.005);
  ASSERT_EQ(thin.size(), 5u);
  for (int k = 0; k < 5; ++k) EXPECT_LT((thin[k] - corners[k]).norm(), 1e-12) << k;
}

TEST(PolylineThinningTest, EveryPointStaysWithinTheToleranceOfWhatIsDrawn) {
  // A noisy wall-following path: a circle of radius 1 m sampled every 2 mm with 0.2 mm of jitter,
  // doubling back once.
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 5000; ++i) {
    const double a = 0.002 * i;
    const double wiggle = 0.0002 * std::sin(37.0 * i);
    points.emplace_back((1.0 + wiggle) * std::cos(a), (1.0 + wiggle) * std::sin(a));
  }
  for (int i = 0; i < 200; ++i) points.emplace_back(points.back() - Eigen::Vector2d(0.005, 0));
  const double tolerance = 0.005;
  const auto thin = ThinPolyline(points, tolerance);
  EXPECT_LT(thin.size(), points.size() / 10);  // the point of thinning
  for (const auto& p : points) ASSERT_LE(DistanceToPolyline(p, thin), tolerance + 1e-12);
}

TEST(PolylineThinningTest, ShortAndRepeatedInputsComeBackWhole) {
  EXPECT_TRUE(ThinPolyline({}, 0.005).empty());
  const std::vector<Eigen::Vector2d> one{{1, 2}};
  EXPECT_EQ(ThinPolyline(one, 0.005), one);
  const std::vector<Eigen::Vector2d> standing(50, Eigen::Vector2d(3, 4));
  const auto thin = ThinPolyline(standing, 0.005);
  EXPECT_EQ(thin.front(), standing.front());
  EXPECT_EQ(thin.back(), standing.back());
  EXPECT_LE(thin.size(), 2u);
}

}  // namespace
}  // namespace plywood::viewer
