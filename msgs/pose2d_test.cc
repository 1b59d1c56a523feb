#include "msgs/pose2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
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

TEST(WrapAngleTest, HugeAnglesWrapAndNonFiniteOnesGiveNan) {
  for (const double angle : {1e300, -1e300, 1e17, -7e15, 12345.678}) {
    SCOPED_TRACE(angle);
    const double wrapped = WrapAngle(angle);
    EXPECT_GT(wrapped, -kPi);
    EXPECT_LE(wrapped, kPi);
  }
  EXPECT_NEAR(WrapAngle(1000.0 * kPi + 0.25), 0.25, 1e-9);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (const double angle : {kInf, -kInf, std::numeric_limits<double>::quiet_NaN()})
    EXPECT_TRUE(std::isnan(WrapAngle(angle))) << angle;
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
