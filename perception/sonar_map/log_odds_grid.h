#pragma once

#include <Eigen/Core>
#include <vector>

#include "msgs/pose2d.h"
#include "msgs/range_ring.h"
#include "perception/sonar_map/sonar_cell_model.h"

namespace plywood::perception {

// Seed 001's temporal integration of M readings with prior 0.5:
//   P = 1 - (1 + prod_m p_m / (1 - p_m))^-1,
// i.e. P = sigmoid(sum_m logit(p_m)). Each p_m is first clamped to [p_min, 1 - p_min] (a single
// reading must never make a cell certain), and the running sum is kept within +-log_odds_limit so a
// cell seen occupied a thousand times can still be cleared by later evidence.
struct LogOddsOptions {
  double p_min = 0.02;
  double log_odds_limit = 12.0;
  // @throws std::invalid_argument naming the field.
  void Validate() const;
};

// Closed form of the product formula (with the clamps above) for a list of readings of one cell.
double CombineReadings(const std::vector<double>& p, const LogOddsOptions& options = {});

// A global occupancy grid in the odometry frame. Each sonar ring is turned into a robot-centred
// local grid (local_cells x local_cells cells of local_cell_m, the seed's 14 x 14 x 10 cm) which is
// motion-compensated by placing it at the odometry pose of the reading: every global cell whose
// centre falls inside the local grid's footprint gets the model's P evaluated at its own centre,
// expressed in the robot frame (no resampling of the local grid, so no aliasing between the two
// resolutions).
struct LogOddsGridOptions {
  double resolution_m = 0.05;
  Eigen::Vector2d origin_xy{-4.0, -4.0};  // low corner of cell (0, 0) in the odometry frame
  int width = 160;
  int height = 160;
  int local_cells = 14;
  double local_cell_m = 0.10;
  LogOddsOptions log_odds;
  // @throws std::invalid_argument naming the field (resolution_m, local_cell_m and origin_xy must
  // be finite).
  void Validate() const;
  // Cell holding p, or (-1, -1) outside.
  Eigen::Vector2i CellAt(const Eigen::Vector2d& p) const;
};

class LogOddsGrid {
 public:
  explicit LogOddsGrid(const LogOddsGridOptions& options = {});

  // Adds one reading p of cell (ix, iy) (product formula, clamped). A cell outside the grid or a p
  // outside [0, 1] (NaN included) throws std::invalid_argument naming it; nothing is written.
  void Add(int ix, int iy, double p);
  // Integrates a whole ring seen from X_WR (odometry frame); an X_WR that is not finite throws
  // std::invalid_argument naming it, nothing written (one far off the grid writes nothing).
  void Integrate(const SonarCellModel& model, const msgs::RangeRing& ring,
                 const msgs::Pose2D& X_WR);

  // These three throw std::invalid_argument for a cell outside the grid, as Add does.
  double LogOdds(int ix, int iy) const { return log_odds_[CheckedIndex(ix, iy)]; }
  // How many readings called cell (ix, iy) occupied (p > 0.5). The log-odds saturate, so a cell
  // the network painted from a few far readings and a box face heard a hundred times both read
  // P ~ 1; the count tells them apart.
  int OccupiedVotes(int ix, int iy) const { return occupied_votes_[CheckedIndex(ix, iy)]; }
  double Probability(int ix, int iy) const;
  bool Contains(int ix, int iy) const {
    return ix >= 0 && iy >= 0 && ix < width() && iy < height();
  }
  Eigen::Vector2d CellCentre(int ix, int iy) const;
  // Cell holding p, or (-1, -1) outside.
  Eigen::Vector2i CellAt(const Eigen::Vector2d& p) const { return options_.CellAt(p); }

  int width() const { return options_.width; }
  int height() const { return options_.height; }
  double resolution_m() const { return options_.resolution_m; }
  const LogOddsGridOptions& options() const { return options_; }
  const std::vector<double>& log_odds() const { return log_odds_; }

 private:
  std::size_t Index(int ix, int iy) const { return static_cast<std::size_t>(iy) * width() + ix; }
  // Index(ix, iy); @throws std::invalid_argument "ix, iy: ..." outside the grid.
  std::size_t CheckedIndex(int ix, int iy) const {
    if (!Contains(ix, iy)) ThrowOutside(ix, iy);
    return Index(ix, iy);
  }
  [[noreturn]] void ThrowOutside(int ix, int iy) const;
  LogOddsGridOptions options_;
  std::vector<double> log_odds_;
  std::vector<int> occupied_votes_;
};

}  // namespace plywood::perception
