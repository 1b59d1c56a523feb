#pragma once

#include <Eigen/Core>
#include <filesystem>

#include "eval/score/grid_image.h"
#include "eval/score/score_report.h"
#include "eval/sonar_map/sonar_ground_truth.h"

namespace plywood::eval {

// Where an occupancy grid image lies in the world (= the odometry frame, which starts at the
// spawn's world pose) and how its pixels read.
struct GridPlacement {
  double resolution_m = 0.0;                           // pixel edge
  Eigen::Vector2d origin_W = Eigen::Vector2d::Zero();  // lower-left corner of the image
  double occupied_threshold = 0.5;  // a pixel is occupied when 1 - brightness > this, else free

  // @throws std::invalid_argument naming the field.
  void Validate() const;
};

// The fewest pixels a map may put across the scored area's shorter side (docs/errors.md, s38).
inline constexpr double kMinPixelsAcross = 10.0;

// Seed 001's occupancy error of `image` (eval/sonar_map/sonar_ground_truth.h): every truth cell of
// the scored area is compared with the pixel holding its centre; unknown (grey) pixels below the
// threshold count as free, like seed 001's unseen cells.
// @throws sim::ConfigError "FILE: size: ..." when the image does not cover the scored area;
// std::invalid_argument "--resolution: ..." when it puts fewer than kMinPixelsAcross pixels across
// the scored area's shorter side.
OccupancyError ScoreGridImage(const OccupancyTruth& truth, const GridImage& image,
                              const GridPlacement& placement, const std::string& file);

// The truth of a run directory: its config.yaml's world, rasterised, reachable from the spawn.
// @throws sim::ConfigError naming config.yaml.
std::unique_ptr<OccupancyTruth> LoadRunOccupancyTruth(const std::filesystem::path& run_dir);

// `plywood score grid RUN_DIR GRID.png|GRID.pgm`: occupancy.grid_error (e = A_e / A_tot) and
// occupancy.area_total_m2.
ScoreReport ScoreGridFile(const std::filesystem::path& run_dir, const std::filesystem::path& file,
                          const GridPlacement& placement);

}  // namespace plywood::eval
