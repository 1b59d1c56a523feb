// The runner labels every laser beam with the ground-truth face it hit (laser_hits.csv, the line
// scores, wall_hit_fraction). Judged against geometry: with exact ranges, a labelled beam's end
// point lies on its face, at every heading of a robot turning on the spot.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <set>
#include <string>

#include "msgs/pose2d.h"
#include "plywood_paths.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/run_observer.h"

namespace plywood::sim {
namespace {

// Turns the robot on the spot, so the scans see the room at every heading.
class Spin : public RunObserver {
 public:
  bool AfterStep(const ExperimentRunner&) override { return true; }
  std::optional<msgs::WheelSpeedCommand> WheelOverride() override {
    return msgs::WheelSpeedCommand{.left_rad_s = -2.0, .right_rad_s = 2.0};
  }
};

// Distance from p to the segment ab.
double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double u = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + u * ab - p).norm();
}

TEST(BeamLabelsSimTest, EachLabelledBeamEndsOnItsFace) {
  const std::string yaml =
      "name: beam_labels\n"
      "seed: 5\n"
      "duration_s: 3\n"
      "world: worlds/office.xml\n"
      "robot: {model: p3dx, spawn: {x_m: -3.6, y_m: 0.5, theta_deg: 37}}\n"
      "controller: {type: idle}\n"
      "sensors:\n"
      "  laser: {resolution_deg: 0.5, range_max_m: 8, range_noise_sigma_m: 0, rate_hz: 10}\n"
      "output: {snapshot: false, sensor_logs: false}\n";
  const ExperimentConfig config =
      ParseExperimentConfig(yaml, "inline", std::filesystem::path(PLYWOOD_SOURCE_ROOT));
  ExperimentRunner runner(config);
  Spin spin;
  runner.SetObserver(&spin);
  runner.Run();

  const RunRecord& record = runner.record();
  const auto& segments = record.walls.segments;
  ASSERT_GE(record.laser.size(), 25u);
  long labelled = 0, returns = 0, off_face = 0;
  std::set<int> octants;  // the eighths of a turn the scans were taken facing
  for (const LaserRecord& laser : record.laser) {
    const msgs::Pose2D X_WS = laser.X_WR_truth * laser.scan.X_RS;
    octants.insert(
        static_cast<int>(std::floor(msgs::WrapAngle(X_WS.theta_rad) / (std::numbers::pi / 4.0))));
    for (std::size_t i = 0; i < laser.scan.ranges_m.size(); ++i) {
      if (!laser.scan.IsReturn(i)) continue;
      ++returns;
      const int label = laser.hit_segment_ids[i];
      if (label < 0) continue;
      ++labelled;
      ASSERT_LT(static_cast<std::size_t>(label), segments.size());
      const double angle = X_WS.theta_rad + laser.scan.BeamAngleRad(i);
      const Eigen::Vector2d end(X_WS.x_m + laser.scan.ranges_m[i] * std::cos(angle),
                                X_WS.y_m + laser.scan.ranges_m[i] * std::sin(angle));
      // Ranges are whole millimetres (the LMS 200's unit): 2 mm covers the rounding.
      if (DistanceToSegment(end, segments[label].a, segments[label].b) > 0.002) ++off_face;
    }
  }
  // The robot turned through more than half a turn, so the labels were taken at many headings.
  EXPECT_GE(octants.size(), 5u);
  EXPECT_GT(returns, 5000);
  // The office's walls and furniture are boxes: nearly every return lies on a labelled face (the
  // rest hit round legs and columns).
  EXPECT_GT(static_cast<double>(labelled) / returns, 0.9);
  EXPECT_EQ(off_face, 0) << "of " << labelled << " labelled beams";
}

}  // namespace
}  // namespace plywood::sim
