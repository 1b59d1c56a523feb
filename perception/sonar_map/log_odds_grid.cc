#include "perception/sonar_map/log_odds_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/pose2d.h"
#include "msgs/shortest_number.h"

namespace plywood::perception {
namespace {

double ClampedLogit(double p, const LogOddsOptions& o) {
  const double q = std::clamp(p, o.p_min, 1.0 - o.p_min);
  return std::log(q / (1.0 - q));
}

}  // namespace

void LogOddsOptions::Validate() const {
  if (!(p_min > 0.0 && p_min < 0.5))
    throw std::invalid_argument("p_min: must be in (0, 0.5), got " + msgs::ShortestNumber(p_min));
  if (!(log_odds_limit > 0.0))
    throw std::invalid_argument("log_odds_limit: must be > 0, got " +
                                msgs::ShortestNumber(log_odds_limit));
}

double CombineReadings(const std::vector<double>& p, const LogOddsOptions& options) {
  options.Validate();
  double l = 0.0;
  for (double q : p) {
    l = std::clamp(l + ClampedLogit(q, options), -options.log_odds_limit, options.log_odds_limit);
  }
  return 1.0 / (1.0 + std::exp(-l));
}

void LogOddsGridOptions::Validate() const {
  // An infinite cell put every point in cell (0, 0); a NaN origin put none in the grid.
  if (!(std::isfinite(resolution_m) && resolution_m > 0.0))
    throw std::invalid_argument("resolution_m: must be a finite number > 0, got " +
                                msgs::ShortestNumber(resolution_m));
  if (!origin_xy.allFinite())
    throw std::invalid_argument("origin_xy: must be finite, got (" +
                                msgs::ShortestNumber(origin_xy.x()) + ", " +
                                msgs::ShortestNumber(origin_xy.y()) + ")");
  if (width < 1 || width > 20000) throw std::invalid_argument("width: must be in [1, 20000]");
  if (height < 1 || height > 20000) throw std::invalid_argument("height: must be in [1, 20000]");
  if (local_cells < 1) throw std::invalid_argument("local_cells: must be >= 1");
  // An infinite one let every ring write every cell of the grid.
  if (!(std::isfinite(local_cell_m) && local_cell_m > 0.0))
    throw std::invalid_argument("local_cell_m: must be a finite number > 0, got " +
                                msgs::ShortestNumber(local_cell_m));
  log_odds.Validate();
}

LogOddsGrid::LogOddsGrid(const LogOddsGridOptions& options) : options_(options) {
  options_.Validate();
  log_odds_.assign(static_cast<std::size_t>(width()) * height(), 0.0);
  occupied_votes_.assign(log_odds_.size(), 0);
}

void LogOddsGrid::ThrowOutside(int ix, int iy) const {
  throw std::invalid_argument("ix, iy: cell (" + std::to_string(ix) + ", " + std::to_string(iy) +
                              ") is outside the " + std::to_string(width()) + " x " +
                              std::to_string(height()) + " grid");
}

void LogOddsGrid::Add(int ix, int iy, double p) {
  const std::size_t i = CheckedIndex(ix, iy);
  // A NaN would pass the clamp and make the cell NaN for good.
  if (!(p >= 0.0 && p <= 1.0)) {
    throw std::invalid_argument("p: must be a probability in [0, 1], got " +
                                msgs::ShortestNumber(p));
  }
  log_odds_[i] = std::clamp(log_odds_[i] + ClampedLogit(p, options_.log_odds),
                            -options_.log_odds.log_odds_limit, options_.log_odds.log_odds_limit);
  if (p > 0.5) ++occupied_votes_[i];
}

double LogOddsGrid::Probability(int ix, int iy) const {
  return 1.0 / (1.0 + std::exp(-LogOdds(ix, iy)));
}

Eigen::Vector2d LogOddsGrid::CellCentre(int ix, int iy) const {
  return options_.origin_xy +
         (Eigen::Vector2d(ix, iy) + Eigen::Vector2d(0.5, 0.5)) * resolution_m();
}

Eigen::Vector2i LogOddsGridOptions::CellAt(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d q = (p - origin_xy) / resolution_m;
  // Compared as doubles first: a point far outside (a diverged pose) must not overflow the int.
  if (!(q.x() >= 0.0 && q.y() >= 0.0 && q.x() < width && q.y() < height)) return {-1, -1};
  return {static_cast<int>(std::floor(q.x())), static_cast<int>(std::floor(q.y()))};
}

void LogOddsGrid::Integrate(const SonarCellModel& model, const msgs::RangeRing& ring,
                            const msgs::Pose2D& X_WR) {
  RequireFinitePose("X_WR", X_WR);
  const double half = 0.5 * options_.local_cells * options_.local_cell_m;
  const double c = std::cos(X_WR.theta_rad), s = std::sin(X_WR.theta_rad);
  // Bounding box of the rotated local square in the global grid.
  const double reach = half * std::sqrt(2.0);
  // Clamped as doubles first: a pose far off the grid (a diverged estimate) must not overflow the
  // int; within the grid the cells are the same.
  const auto cell = [&](const Eigen::Vector2d& p) -> Eigen::Vector2i {
    const Eigen::Array2d q = ((p - options_.origin_xy) / resolution_m()).array().floor();
    return q.max(-1.0).min(Eigen::Array2d(width(), height())).cast<int>();
  };
  const Eigen::Vector2i lo = cell({X_WR.x_m - reach, X_WR.y_m - reach});
  const Eigen::Vector2i hi = cell({X_WR.x_m + reach, X_WR.y_m + reach});
  for (int iy = std::max(0, lo.y()); iy <= std::min(height() - 1, hi.y()); ++iy) {
    for (int ix = std::max(0, lo.x()); ix <= std::min(width() - 1, hi.x()); ++ix) {
      const Eigen::Vector2d p = CellCentre(ix, iy) - Eigen::Vector2d(X_WR.x_m, X_WR.y_m);
      const Eigen::Vector2d p_R(c * p.x() + s * p.y(), -s * p.x() + c * p.y());
      if (std::abs(p_R.x()) >= half || std::abs(p_R.y()) >= half) continue;
      Add(ix, iy, model.Probability(ring, p_R));
    }
  }
}

}  // namespace plywood::perception
