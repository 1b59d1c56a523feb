#include "msgs/pose2d.h"

#include <gtest/gtest.h>

#include <numbers>

namespace plywood::msgs {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(WrapAngleTest, MapsIntoHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(WrapAngle(kPi), kPi);
  EXPECT_DOUBLE_EQ(WrapAngle(-kPi), kPi);
  EXPECT_NEAR(WrapAngle(3.0 * kPi / 2.0), -kPi / 2.0, 1e-12);
  EXPECT_NEAR(WrapAngle(-5.0 * kPi / 2.0), -kPi / 2.0, 1e-12);
}

TEST(Pose2DTest, ComposeMatchesHandComputedTransform) {
  const Pose2D X_WR{1.0, 2.0, kPi / 2.0};
  const Pose2D X_RS{0.5, 0.0, 0.0};
  const Pose2D X_WS = X_WR * X_RS;
  EXPECT_NEAR(X_WS.x_m, 1.0, 1e-12);
  EXPECT_NEAR(X_WS.y_m, 2.5, 1e-12);
  EXPECT_NEAR(X_WS.theta_rad, kPi / 2.0, 1e-12);
}

TEST(Pose2DTest, InverseUndoesCompose) {
  const Pose2D X_AB{-0.3, 4.0, 2.5};
  const Pose2D identity = X_AB * X_AB.Inverse();
  EXPECT_NEAR(identity.x_m, 0.0, 1e-12);
  EXPECT_NEAR(identity.y_m, 0.0, 1e-12);
  EXPECT_NEAR(identity.theta_rad, 0.0, 1e-12);
}

}  // namespace
}  // namespace plywood::msgs
