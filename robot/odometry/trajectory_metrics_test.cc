#include "robot/odometry/trajectory_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace plywood::robot {
namespace {

TEST(TrajectoryMetricsTest, ConstantOffsetGivesClosedFormErrors) {
  // Truth drives 10 m along x in 1 m steps; the estimate is 0.3 m to the side, heading 2 deg off.
  std::vector<msgs::Pose2D> truth, estimate;
  for (int i = 0; i <= 10; ++i) {
    truth.push_back({static_cast<double>(i), 0.0, 0.0});
    estimate.push_back({static_cast<double>(i), 0.3, 2.0 * M_PI / 180.0});
  }
  const TrajectoryErrors errors = ScoreTrajectory(truth, estimate);
  EXPECT_NEAR(errors.distance_travelled_m, 10.0, 1e-12);
  EXPECT_NEAR(errors.final_error_m, 0.3, 1e-12);
  EXPECT_NEAR(errors.drift_percent, 3.0, 1e-10);
  EXPECT_NEAR(errors.heading_error_deg, 2.0, 1e-10);
  EXPECT_NEAR(errors.ate_rms_m, 0.3, 1e-12);
}

TEST(TrajectoryMetricsTest, AteIsRootMeanSquare) {
  const std::vector<msgs::Pose2D> truth{{0, 0, 0}, {1, 0, 0}};
  const std::vector<msgs::Pose2D> estimate{{0, 0, 0}, {1, 2, 0}};
  EXPECT_NEAR(ScoreTrajectory(truth, estimate).ate_rms_m, std::sqrt(2.0), 1e-12);
}

TEST(TrajectoryMetricsTest, MismatchedLengthsThrow) {
  EXPECT_THROW(ScoreTrajectory({{0, 0, 0}}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace plywood::robot
