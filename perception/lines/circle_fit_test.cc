#include "perception/lines/circle_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace plywood::perception {
namespace {

std::vector<Eigen::Vector2d> Arc(const Eigen::Vector2d& centre, double radius_m, double from_rad,
                                 double to_rad, int count, double noise_m = 0.0) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, noise_m);
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < count; ++k) {
    const double a = from_rad + (to_rad - from_rad) * k / (count - 1);
    const double r = radius_m + (noise_m > 0.0 ? noise(rng) : 0.0);
    points.push_back(centre + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return points;
}

std::vector<int> All(std::size_t n) {
  std::vector<int> indices(n);
  for (std::size_t i = 0; i < n; ++i) indices[i] = static_cast<int>(i);
  return indices;
}

TEST(CircleFitTest, PointsOnACircleGiveItExactly) {
  // A short arc (60 deg), where the algebraic fit alone is biased; far from the origin.
  const auto points = Arc({12.0, -7.0}, 0.15, 0.3, 0.3 + std::numbers::pi / 3.0, 9);
  const auto fit = FitCircle(points, All(points.size()));
  ASSERT_TRUE(fit.has_value());
  EXPECT_NEAR(fit->centre.x(), 12.0, 1e-9);
  EXPECT_NEAR(fit->centre.y(), -7.0, 1e-9);
  EXPECT_NEAR(fit->radius_m, 0.15, 1e-9);
  EXPECT_NEAR(fit->rss_m2, 0.0, 1e-18);
  EXPECT_NEAR(fit->max_residual_m, 0.0, 1e-9);
}

TEST(CircleFitTest, NoisyHalfCircleIsFoundWithinTheNoise) {
  const auto points = Arc({1.0, 2.0}, 0.2, 0.0, std::numbers::pi, 40, 0.005);
  const auto fit = FitCircle(points, All(points.size()));
  ASSERT_TRUE(fit.has_value());
  EXPECT_NEAR(fit->radius_m, 0.2, 0.005);
  EXPECT_NEAR((fit->centre - Eigen::Vector2d(1.0, 2.0)).norm(), 0.0, 0.005);
  EXPECT_NEAR(std::sqrt(fit->rss_m2 / 40.0), 0.005, 0.0025);
}

TEST(CircleFitTest, CollinearOrTooFewPointsHaveNoCircle) {
  const std::vector<Eigen::Vector2d> line{{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  EXPECT_FALSE(FitCircle(line, All(line.size())).has_value());
  const std::vector<Eigen::Vector2d> two{{0, 0}, {1, 0}};
  EXPECT_FALSE(FitCircle(two, All(two.size())).has_value());
  const std::vector<Eigen::Vector2d> same{{1, 1}, {1, 1}, {1, 1}};
  EXPECT_FALSE(FitCircle(same, All(same.size())).has_value());
}

TEST(CircleFitTest, UsesOnlyTheGivenIndices) {
  auto points = Arc({0.0, 3.0}, 0.3, -2.0, -1.0, 10);
  points.push_back({50.0, 50.0});  // not in the subset
  const auto fit = FitCircle(points, All(10));
  ASSERT_TRUE(fit.has_value());
  EXPECT_NEAR(fit->radius_m, 0.3, 1e-9);
}

}  // namespace
}  // namespace plywood::perception
