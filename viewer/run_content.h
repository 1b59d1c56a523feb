#pragma once

#include <memory>

#include "perception/geometric_map/geometric_mapper.h"
#include "sim/runner/experiment_runner.h"
#include "viewer/frame_content.h"

namespace plywood::viewer {

// Fills the overlays' FrameContent from a live run, keeping what is costly to recompute (the
// latest scan's extracted lines, each ring's classification) until a new reading arrives.
class RunContent {
 public:
  explicit RunContent(const sim::ExperimentRunner& runner);

  const FrameContent& Update(const sim::ExperimentRunner& runner);

 private:
  FrameContent content_;
  double laser_height_m_ = 0.0;
  double sonar_height_m_ = 0.0;
  double ir_height_m_ = 0.0;
  double next_map_s_ = 0.0;
  std::size_t laser_seen_ = 0, sonar_seen_ = 0, ir_seen_ = 0, trajectory_seen_ = 0;
  std::size_t ir_scans_seen_ = 0, next_sonar_ = 0;
  std::unique_ptr<perception::GeometricMapper> geometric_mapper_;  // seed 003 runs only
};

// What each reading of `ring` (read at robot pose X_WR) means, judged by a ray along its axis in
// the scene's current state (the robot's own geoms skipped).
std::vector<RingReadingKind> ClassifyRing(const sim::Scene& scene, const msgs::Pose2D& X_WR,
                                          double height_m, const msgs::RangeRing& ring);

}  // namespace plywood::viewer
