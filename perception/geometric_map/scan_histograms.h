#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "perception/geometric_map/range_fusion.h"

namespace plywood::perception {

// Seed 003's preprocessing of one scan. "Virtual lines" join points gamma_beams scanner steps
// apart; their directions (mod 180 deg) vote in an angle histogram whose highest peak is the scan's
// main direction alpha_max. In the frame turned by alpha_max, the points' X and Y coordinates vote
// in distance histograms whose strongest maxima are the walls around the robot; a point votes in
// the X histogram only when its virtual line is within max_wall_tilt_deg of square to X (and
// likewise for Y), so that the dense points of a wall running along X near the robot do not make a
// spurious X maximum at the robot's feet (the paper does not say how it avoids those). Defaults are
// assumptions: 3 steps of a 1.8 deg head (5.4 deg) keep virtual lines short enough to stay on one
// wall at 3 m (16 cm) yet long enough that 5 mm noise tilts them by less than 3 deg at 1 m; lines
// longer than max_virtual_line_m cross a gap or a depth jump and do not vote.
struct HistogramOptions {
  int gamma_beams = 3;
  double max_virtual_line_m = 0.4;
  double angle_bin_deg = 1.0;
  double distance_bin_m = 0.05;
  int maxima_per_side = 3;
  double max_wall_tilt_deg = 20.0;

  // @throws std::invalid_argument starting with the field's name.
  void Validate() const;
};

// A virtual line: from points[first] to the point gamma_beams beams later, direction in [0, pi).
struct VirtualLine {
  int first = 0;
  double direction_rad = 0.0;
};
// The virtual lines of `points` (beam order), skipping pairs farther apart than max_virtual_line_m.
std::vector<VirtualLine> MakeVirtualLines(std::span<const RangePoint> points,
                                          const HistogramOptions& options);

// Votes per direction bin; bin b covers [b, b + 1) * bin_deg of [0, 180).
struct AngleHistogram {
  double bin_deg = 1.0;
  std::vector<double> votes;
  // The directions (rad, in [0, pi)) of the virtual lines that voted, in scan order.
  std::vector<double> directions_rad;

  double TotalVotes() const { return static_cast<double>(directions_rad.size()); }
  // alpha_max in [0, pi): the doubled-angle mean of the virtual lines in the highest bin (summed
  // with its two neighbours) and those neighbours; exact for noise-free points. 0 without votes.
  double MainDirectionRad() const;
};

// `points` in beam order; `offset_rad` is added to every direction (e.g. the robot's heading, to
// vote in the world frame).
AngleHistogram MakeAngleHistogram(std::span<const RangePoint> points,
                                  const HistogramOptions& options, double offset_rad = 0.0);

// A maximum of a distance histogram: where (m, refined as the median coordinate of the points in
// the peak's bin and its two neighbours) and how many points voted in those three bins.
struct DistancePeak {
  double position_m = 0.0;
  double votes = 0.0;
};

// The X and Y histograms in the frame turned by alpha_rad, and their strongest maxima on each
// side of the robot (negative side, positive side), strongest first, at most maxima_per_side.
struct DistanceHistograms {
  double alpha_rad = 0.0;
  std::vector<DistancePeak> x_negative, x_positive, y_negative, y_positive;
};
DistanceHistograms MakeDistanceHistograms(std::span<const RangePoint> points, double alpha_rad,
                                          const HistogramOptions& options);

// The strongest local maxima of `coordinates` histogrammed in bins of bin_m (bin k covers
// [k, k + 1) * bin_m), among those on the side `positive` of zero, strongest first (ties: nearer
// first), at most `count`. Used for both axes.
std::vector<DistancePeak> StrongestMaxima(std::span<const double> coordinates, double bin_m,
                                          bool positive, int count);

}  // namespace plywood::perception
