#include "robot/calibration/umbmark.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "msgs/shortest_number.h"
#include "robot/number_checks.h"

namespace plywood::robot {

UmbmarkRun UmbmarkReturnError(SquareDirection direction, const msgs::Pose2D& X_WR_start,
                              const msgs::Pose2D& X_WR_end_true,
                              const msgs::Pose2D& X_WR_end_odometry) {
  const double dx = X_WR_end_true.x_m - X_WR_end_odometry.x_m;
  const double dy = X_WR_end_true.y_m - X_WR_end_odometry.y_m;
  const double c = std::cos(X_WR_start.theta_rad), s = std::sin(X_WR_start.theta_rad);
  return {direction, c * dx + s * dy, -s * dx + c * dy};
}

UmbmarkResult AnalyseUmbmark(const std::vector<UmbmarkRun>& runs, double side_m, double track_m) {
  internal::RequirePositive("side_m", side_m);
  internal::RequirePositive("track_m", track_m);
  UmbmarkResult r;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const UmbmarkRun& run = runs[k];
    for (const auto& [field, value] :
         {std::pair{".error_x_m", run.error_x_m}, std::pair{".error_y_m", run.error_y_m}}) {
      if (!std::isfinite(value)) {
        throw std::invalid_argument("runs[" + std::to_string(k) + "]" + field +
                                    ": must be finite, got " + msgs::ShortestNumber(value));
      }
    }
    if (run.direction == SquareDirection::kClockwise) {
      ++r.runs_cw;
      r.x_cg_cw_m += run.error_x_m;
      r.y_cg_cw_m += run.error_y_m;
    } else {
      ++r.runs_ccw;
      r.x_cg_ccw_m += run.error_x_m;
      r.y_cg_ccw_m += run.error_y_m;
    }
  }
  if (r.runs_cw == 0 || r.runs_ccw == 0) {
    throw std::invalid_argument("UMBmark needs runs in both directions");
  }
  r.x_cg_cw_m /= r.runs_cw;
  r.y_cg_cw_m /= r.runs_cw;
  r.x_cg_ccw_m /= r.runs_ccw;
  r.y_cg_ccw_m /= r.runs_ccw;
  r.r_cg_cw_m = std::hypot(r.x_cg_cw_m, r.y_cg_cw_m);
  r.r_cg_ccw_m = std::hypot(r.x_cg_ccw_m, r.y_cg_ccw_m);
  r.e_max_syst_m = std::max(r.r_cg_cw_m, r.r_cg_ccw_m);

  const double four_l = -4.0 * side_m;
  r.alpha_from_x_rad = (r.x_cg_cw_m + r.x_cg_ccw_m) / four_l;
  r.alpha_from_y_rad = (r.y_cg_cw_m - r.y_cg_ccw_m) / four_l;
  r.beta_from_x_rad = (r.x_cg_cw_m - r.x_cg_ccw_m) / four_l;
  r.beta_from_y_rad = (r.y_cg_cw_m + r.y_cg_ccw_m) / four_l;
  r.alpha_rad = (r.alpha_from_x_rad + r.alpha_from_y_rad) / 2.0;
  r.beta_rad = (r.beta_from_x_rad + r.beta_from_y_rad) / 2.0;

  const double quarter = std::numbers::pi / 2.0;
  r.eb = quarter / (quarter - r.alpha_rad);
  const double b = r.eb * track_m;
  if (r.beta_rad == 0.0) {
    r.curvature_radius_m = std::numeric_limits<double>::infinity();
    r.ed = 1.0;
  } else {
    r.curvature_radius_m = (side_m / 2.0) / std::sin(r.beta_rad / 2.0);
    r.ed = (r.curvature_radius_m + b / 2.0) / (r.curvature_radius_m - b / 2.0);
  }
  return r;
}

OdometryCalibration CorrectedCalibration(const OdometryCalibration& used,
                                         const UmbmarkResult& result) {
  return {.wheel_diameter_ratio = used.wheel_diameter_ratio * result.ed,
          .track_ratio = used.track_ratio * result.eb};
}

}  // namespace plywood::robot
