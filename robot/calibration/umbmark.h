#pragma once

#include <vector>

#include "msgs/pose2d.h"
#include "robot/control/square_path_controller.h"
#include "robot/odometry/odometry_increments.h"

namespace plywood::robot {

// UMBmark (Borenstein & Feng, "Measurement and correction of systematic odometry errors in mobile
// robots", IEEE Trans. Robotics and Automation 12(6), 1996): the robot drives an L x L square
// n times clockwise and n times counter-clockwise, steering by its own odometry; the
// return-position errors expose the two dominant systematic errors, unequal wheel diameters (E_d)
// and an uncertain effective wheelbase (E_b).
//
// Conventions (the paper's): the error of one run is eps = p_true - p_odometry at the end, in the
// frame of the start pose (x along the first leg, y to its left), so a clockwise square goes +x
// then -y, a counter-clockwise one +x then +y. alpha > 0 means every 90 deg turn falls short
// (E_b > 1), beta > 0 means each straight leg curves to the left (the right wheel is larger,
// E_d = D_R / D_L > 1). To first order
//   eps_cw  = -2 L (beta + alpha) (1, 1),   eps_ccw = 2 L (beta - alpha) (1, -1),
// which the paper inverts to
//   alpha = (x_cw + x_ccw) / (-4 L),  beta = (x_cw - x_ccw) / (-4 L)   (and the same from y).
struct UmbmarkRun {
  SquareDirection direction = SquareDirection::kClockwise;
  double error_x_m = 0.0;
  double error_y_m = 0.0;
};

// eps of one run from the start pose and the true and estimated end poses.
UmbmarkRun UmbmarkReturnError(SquareDirection direction, const msgs::Pose2D& X_WR_start,
                              const msgs::Pose2D& X_WR_end_true,
                              const msgs::Pose2D& X_WR_end_odometry);

struct UmbmarkResult {
  int runs_cw = 0, runs_ccw = 0;
  // Centres of gravity of the two clusters, and their distances from the origin.
  double x_cg_cw_m = 0.0, y_cg_cw_m = 0.0, x_cg_ccw_m = 0.0, y_cg_ccw_m = 0.0;
  double r_cg_cw_m = 0.0, r_cg_ccw_m = 0.0;
  double e_max_syst_m = 0.0;  // max(r_cg_cw, r_cg_ccw): UMBmark's measure of systematic odometry
  // Type A (turn) and type B (curvature) errors, each the mean of the x- and y-based estimates.
  double alpha_rad = 0.0, beta_rad = 0.0;
  double alpha_from_x_rad = 0.0, alpha_from_y_rad = 0.0, beta_from_x_rad = 0.0,
         beta_from_y_rad = 0.0;
  double curvature_radius_m = 0.0;  // R = (L/2) / sin(beta/2); infinite for beta = 0
  // The errors relative to the geometry the odometry used: E_d = (R + b/2) / (R - b/2),
  // E_b = 90 deg / (90 deg - alpha).
  double ed = 1.0, eb = 1.0;
};

// Analyses the runs of one UMBmark (both directions needed). `track_m` is the wheelbase the
// odometry used; the curvature is converted with the corrected wheelbase E_b * track_m, since the
// legs curve with the real one (the paper uses the nominal b; the difference is (E_b - 1)(E_d -
// 1)).
// @throws std::invalid_argument without runs in both directions, naming the field and value for
// a side_m or track_m that is not a finite number > 0 or a run error that is not finite.
UmbmarkResult AnalyseUmbmark(const std::vector<UmbmarkRun>& runs, double side_m, double track_m);

// The calibration to use next: the measured ratios compose with the one the runs were driven with
// (b_new = E_b b_used; D_R/D_L believed = E_d times what was believed).
OdometryCalibration CorrectedCalibration(const OdometryCalibration& used,
                                         const UmbmarkResult& result);

}  // namespace plywood::robot
