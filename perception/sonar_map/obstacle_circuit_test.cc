#include "perception/sonar_map/obstacle_circuit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

namespace plywood::perception {
namespace {

// Where a ray from `origin` along `direction` first meets the sides of `box` (nullopt: never).
std::optional<Eigen::Vector2d> RayHit(const Rect& box, const Eigen::Vector2d& origin,
                                      const Eigen::Vector2d& direction, double max_range) {
  double t_near = 0.0, t_far = max_range;
  for (int axis = 0; axis < 2; ++axis) {
    const double lo = axis == 0 ? box.x0 : box.y0, hi = axis == 0 ? box.x1 : box.y1;
    if (std::abs(direction[axis]) < 1e-12) {
      if (origin[axis] < lo || origin[axis] > hi) return std::nullopt;
      continue;
    }
    double t0 = (lo - origin[axis]) / direction[axis], t1 = (hi - origin[axis]) / direction[axis];
    if (t0 > t1) std::swap(t0, t1);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
  }
  if (t_near > t_far) return std::nullopt;
  return origin + t_near * direction;
}

// A robot drives the circuit round `box` at `distance`, and three sonars on its left (45, 90 and
// 135 deg) hear the box every 2 cm; the echoes are snapped to the centres of 5 cm cells, as the
// grid holds them.
std::vector<Eigen::Vector2d> HeardOnCircuit(const Rect& box, double distance) {
  const double cell = 0.05;
  const std::vector<Eigen::Vector2d> corners =
      CircuitAround(box, distance, Eigen::Vector2d(box.x0 - 1.0, box.y0 - 1.0));
  std::vector<Eigen::Vector2d> heard;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Eigen::Vector2d a = corners[k], b = corners[(k + 1) % corners.size()];
    const Eigen::Vector2d heading = (b - a).normalized();
    const double theta = std::atan2(heading.y(), heading.x());
    const int steps = static_cast<int>((b - a).norm() / 0.02);
    for (int i = 0; i <= steps; ++i) {
      const Eigen::Vector2d at = a + (b - a) * (static_cast<double>(i) / steps);
      for (double bearing : {M_PI / 4, M_PI / 2, 3 * M_PI / 4}) {
        const Eigen::Vector2d dir(std::cos(theta + bearing), std::sin(theta + bearing));
        if (const auto hit = RayHit(box, at, dir, 1.0)) {
          // The cell the echo falls in, nudged inside the box (the grid marks the cell behind
          // the face occupied).
          const Eigen::Vector2d inside = *hit + 1e-6 * dir;
          heard.emplace_back((std::floor(inside.x() / cell) + 0.5) * cell,
                             (std::floor(inside.y() / cell) + 0.5) * cell);
        }
      }
    }
  }
  return heard;
}

TEST(ObstacleCircuitTest, CircuitCornersCounterClockwiseFromTheNearest) {
  const Rect box{1.0, 2.0, 1.6, 2.4};
  const std::vector<Eigen::Vector2d> c = CircuitAround(box, 0.5, {3.0, 3.0});
  ASSERT_EQ(c.size(), 4u);
  EXPECT_TRUE(c[0].isApprox(Eigen::Vector2d(2.1, 2.9)));  // NE is nearest to (3, 3)
  EXPECT_TRUE(c[1].isApprox(Eigen::Vector2d(0.5, 2.9)));  // then NW, SW, SE
  EXPECT_TRUE(c[2].isApprox(Eigen::Vector2d(0.5, 1.5)));
  EXPECT_TRUE(c[3].isApprox(Eigen::Vector2d(2.1, 1.5)));
  // Counter-clockwise: positive signed area; the box is on the left of every leg.
  double area = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d a = c[k], b = c[(k + 1) % 4];
    area += a.x() * b.y() - b.x() * a.y();
    const Eigen::Vector2d to_box = box.Centre() - a, leg = b - a;
    EXPECT_GT(leg.x() * to_box.y() - leg.y() * to_box.x(), 0.0) << "leg " << k;
  }
  EXPECT_NEAR(0.5 * area, 1.6 * 1.4, 1e-9);
}

TEST(ObstacleCircuitTest, FollowRoundAKnownBoxGivesItsCorners) {
  for (const Rect& box : {Rect{0.32, -0.21, 0.93, 0.19}, Rect{-1.07, 0.4, -0.52, 1.31}}) {
    const std::vector<Eigen::Vector2d> heard = HeardOnCircuit(box, 0.5);
    const std::optional<ObstacleOutline> outline = OutlineFromBoundary(heard, 0.05, 0.05, 3);
    ASSERT_TRUE(outline.has_value());
    // Cell centres lie within half a cell inside the face: the corners come out within 2.5 cm
    // plus the snap of the face into its cell row.
    const std::array<Eigen::Vector2d, 4> truth = {
        Eigen::Vector2d(box.x0, box.y0), Eigen::Vector2d(box.x1, box.y0),
        Eigen::Vector2d(box.x1, box.y1), Eigen::Vector2d(box.x0, box.y1)};
    for (int k = 0; k < 4; ++k)
      EXPECT_LT((outline->corners[k] - truth[k]).norm(), 0.05)
          << "corner " << k << ": " << outline->corners[k].transpose();
    const Rect r = outline->Box();
    EXPECT_NEAR(r.Area(), box.Area(), 0.06 * box.Area());
  }
}

TEST(ObstacleCircuitTest, RotatedFacesMeetAtTheirIntersections) {
  // Points on the faces of a square of side 0.6 m turned by 5 deg about (2, 1): each corner is
  // where consecutive fitted lines meet, exactly.
  const double a = 5.0 * M_PI / 180.0;
  const Eigen::Vector2d centre(2.0, 1.0), u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
  std::array<Eigen::Vector2d, 4> truth;
  const double h = 0.3;
  truth[0] = centre - h * u - h * v;
  truth[1] = centre + h * u - h * v;
  truth[2] = centre + h * u + h * v;
  truth[3] = centre - h * u + h * v;
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < 4; ++k)
    for (int i = 1; i < 30; ++i)  // corners themselves left out: they belong to two faces
      points.push_back(truth[k] + (truth[(k + 1) % 4] - truth[k]) * (i / 30.0));
  // Group at 1 cm so that every point is its own row and column.
  const std::optional<ObstacleOutline> outline = OutlineFromBoundary(points, 0.001, 0.01, 3);
  ASSERT_TRUE(outline.has_value());
  for (int k = 0; k < 4; ++k) EXPECT_LT((outline->corners[k] - truth[k]).norm(), 0.01) << k;
}

TEST(ObstacleCircuitTest, AnUnheardFaceGivesNoOutline) {
  const Rect box{0.0, 0.0, 0.6, 0.4};
  std::vector<Eigen::Vector2d> heard;
  for (const Eigen::Vector2d& p : HeardOnCircuit(box, 0.5))
    if (p.y() > 0.05) heard.push_back(p);  // nothing of the south face
  // The columns then give north points for the south side too: no outline, not a flat one.
  EXPECT_FALSE(OutlineFromBoundary(heard, 0.05, 0.05, 3).has_value());
  EXPECT_TRUE(OutlineFromBoundary(HeardOnCircuit(box, 0.5), 0.05, 0.05, 3).has_value());
  EXPECT_FALSE(OutlineFromBoundary({}, 0.05, 0.05, 3).has_value());
  EXPECT_FALSE(OutlineFromBoundary({{0.0, 0.0}}, 0.05, 0.05, 3).has_value());
}

TEST(ObstacleCircuitTest, ParallelLinesDoNotIntersect) {
  EXPECT_FALSE(Intersect({{0, 0}, {1, 0}}, {{0, 1}, {1, 0}}).has_value());
  const auto p = Intersect({{0, 0}, {1, 0}}, {{2, 5}, {0, 1}});
  ASSERT_TRUE(p.has_value());
  EXPECT_TRUE(p->isApprox(Eigen::Vector2d(2, 0)));
}

}  // namespace
}  // namespace plywood::perception
