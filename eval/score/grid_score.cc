#include "eval/score/grid_score.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "eval/score/run_directory.h"
#include "eval/score/run_world_check.h"
#include "sim/config/config_error.h"
#include "sim/runner/experiment_runner.h"
#include "sim/world/occupancy_raster.h"
#include "sim/world/setup_checks.h"

namespace plywood::eval {
namespace {

// The pixel (column, row from the top) holding p_W, or false outside the image.
bool PixelOf(const GridImage& image, const GridPlacement& placement, const Eigen::Vector2d& p_W,
             int* x, int* y) {
  const Eigen::Vector2d cells = (p_W - placement.origin_W) / placement.resolution_m;
  const double column = std::floor(cells.x()), from_bottom = std::floor(cells.y());
  if (!(column >= 0 && column < image.width && from_bottom >= 0 && from_bottom < image.height)) {
    return false;
  }
  *x = static_cast<int>(column);
  *y = image.height - 1 - static_cast<int>(from_bottom);
  return true;
}

}  // namespace

void GridPlacement::Validate() const {
  if (!(std::isfinite(resolution_m) && resolution_m > 0.0)) {
    throw std::invalid_argument("--resolution: must be > 0 m per pixel");
  }
  if (!origin_W.allFinite()) throw std::invalid_argument("--origin: must be finite");
  if (!(occupied_threshold >= 0.0 && occupied_threshold < 1.0)) {
    throw std::invalid_argument("--threshold: must be in [0, 1)");
  }
}

OccupancyError ScoreGridImage(const OccupancyTruth& truth, const GridImage& image,
                              const GridPlacement& placement, const std::string& file) {
  placement.Validate();
  const Eigen::Vector2d low = truth.raster.CellCentre(truth.x0, truth.y0);
  const Eigen::Vector2d high = truth.raster.CellCentre(truth.x1, truth.y1);
  // The scored area's sides in pixels. A pixel edge r mislabels up to r / 2 on each side of every
  // boundary, about 1 / n_x + 1 / n_y of a box n_x x n_y px wide: below kMinPixelsAcross the
  // pixels alone would decide e (at 1e300 m/px one pixel held the world and e read 0).
  const Eigen::Vector2d extent_m =
      (high - low).array() + truth.raster.resolution_m;  // cell centres to cell edges
  const double pixels_across = extent_m.minCoeff() / placement.resolution_m;
  if (!(pixels_across >= kMinPixelsAcross)) {
    char what[512];
    std::snprintf(what, sizeof(what),
                  "--resolution: %g m per pixel leaves the scored area (%g x %g m) %.3g px across "
                  "its shorter side; at least %g are needed, or the pixels alone decide e: use at "
                  "most %g m",
                  placement.resolution_m, extent_m.x(), extent_m.y(), pixels_across,
                  kMinPixelsAcross, extent_m.minCoeff() / kMinPixelsAcross);
    throw std::invalid_argument(what);
  }
  int x = 0, y = 0;
  if (!PixelOf(image, placement, low, &x, &y) || !PixelOf(image, placement, high, &x, &y)) {
    char what[512];
    const Eigen::Vector2d far =
        placement.origin_W + placement.resolution_m * Eigen::Vector2d(image.width, image.height);
    std::snprintf(what, sizeof(what),
                  "%d x %d px at %g m/px from (%g, %g) covers x %g..%g, y %g..%g m, but the "
                  "scored area spans x %g..%g, y %g..%g m: check --resolution and --origin",
                  image.width, image.height, placement.resolution_m, placement.origin_W.x(),
                  placement.origin_W.y(), placement.origin_W.x(), far.x(), placement.origin_W.y(),
                  far.y(), low.x(), high.x(), low.y(), high.y());
    throw sim::ConfigError(file, "size", what);
  }
  return ScoreOccupancy(truth, [&](const Eigen::Vector2d& p_W) {
    int px = 0, py = 0;
    if (!PixelOf(image, placement, p_W, &px, &py)) return true;
    return 1.0 - image.At(px, py) <= placement.occupied_threshold;
  });
}

std::unique_ptr<OccupancyTruth> LoadRunOccupancyTruth(const std::filesystem::path& run_dir) {
  const sim::ExperimentConfig config = LoadRunConfig(run_dir, "plywood score grid");
  const sim::ExperimentRunner runner(config);  // the scene as the run built it; nothing runs
  // The truth is the world file as it is now: an edited one was scored without a word.
  RequireWorldAsTheRunSawIt(
      runner.scene(), config,
      ReadWallsCsv(
          RunFile(run_dir, "walls.csv", "the run's walls, to check its world is unchanged")),
      run_dir / "config.yaml", "the grid would be scored against another world");
  // The occupancy truth leaves out what it cannot describe (a tilted box, a sphere): a grid that
  // maps it would be scored wrong for it.
  if (const auto problem = sim::GeomTheGroundTruthCannotHold(
          runner.scene(), sim::OccupancyRasterOptions{}.height_m)) {
    throw sim::ConfigError((run_dir / "config.yaml").string(), "world",
                           config.world_path.string() + ": " + *problem);
  }
  if (const auto problem =
          sim::WorldTooWideToRasterise(runner.scene(), sim::kOccupancyTruthResolutionM)) {
    throw sim::ConfigError((run_dir / "config.yaml").string(), "world",
                           config.world_path.string() + ": " + *problem);
  }
  return MakeOccupancyTruth(runner.scene().model(), {config.spawn.x_m, config.spawn.y_m},
                            (run_dir / "config.yaml").string());
}

ScoreReport ScoreGridFile(const std::filesystem::path& run_dir, const std::filesystem::path& file,
                          const GridPlacement& placement) {
  placement.Validate();
  const auto truth = LoadRunOccupancyTruth(run_dir);
  const GridImage image = ReadGridImage(file);
  const OccupancyError error = ScoreGridImage(*truth, image, placement, file.string());
  ScoreReport report;
  report.metrics.Set("occupancy.grid_error", error.Error());
  report.metrics.Set("occupancy.area_total_m2", error.AreaTotalM2());
  char line[512];
  const Eigen::Vector2d low = truth->raster.CellCentre(truth->x0, truth->y0);
  const Eigen::Vector2d high = truth->raster.CellCentre(truth->x1, truth->y1);
  std::snprintf(line, sizeof(line), "%-18s %s: scored area x %.2f..%.2f, y %.2f..%.2f m\n", "run",
                run_dir.c_str(), low.x(), high.x(), low.y(), high.y());
  report.table += line;
  std::snprintf(line, sizeof(line), "%-18s %s: %d x %d px at %g m/px from (%g, %g), threshold %g\n",
                "file", file.c_str(), image.width, image.height, placement.resolution_m,
                placement.origin_W.x(), placement.origin_W.y(), placement.occupied_threshold);
  report.table += line;
  std::snprintf(line, sizeof(line), "%-18s e %.4f (%.3f m2 misclassified of %.3f m2 free)\n",
                "occupancy", error.Error(), error.AreaErrorM2(), error.AreaTotalM2());
  report.table += line;
  return report;
}

}  // namespace plywood::eval
