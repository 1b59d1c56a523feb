#pragma once

#include <string>
#include <vector>

#include "perception/lines/line_extractor.h"
#include "perception/lines/round_object_filter.h"

namespace plywood::perception {

// Sequential Hough transform (Duda & Hart 1972): every point votes for the (theta, rho) cells of
// the lines through it; the strongest cell's points (within distance_threshold_m of its line)
// are refitted by total least squares, cut into runs at gaps wider than max_gap_m, kept when a
// run has min_points, and their votes withdrawn before the next peak is taken.
// Points farther than this from the sensor cannot be voted (no laser in the project reaches it).
inline constexpr double kMaxHoughRangeM = 100.0;

struct HoughOptions {
  double theta_bin_deg = 1.0;
  double rho_bin_m = 0.02;
  int min_votes = 8;
  double distance_threshold_m = 0.03;
  double max_gap_m = 0.3;
  int min_points = 5;
  double min_length_m = 0.06;  // as split_and_merge: chords across a table leg are not walls
  int max_lines = 100;
  // On an ordered scan (Extract): runs are also cut where neighbours along the line are not
  // neighbours in the scan or have an opening between them (SplitRunsInScan, with
  // breakpoints.max_missing_beams), and points on round objects are left out before the search
  // (RoundObjectPoints: breakpoint groups cut by the end-point fit at distance_threshold_m).
  BreakpointOptions breakpoints;
  RoundObjectOptions round_objects;

  void Validate() const;
};

class HoughExtractor final : public RoundObjectAwareExtractor {
 public:
  explicit HoughExtractor(const HoughOptions& options = {});
  std::string name() const override { return "hough"; }

 private:
  std::vector<LineSegment> Run(const ScanPoints& scan,
                               std::vector<CircleFeature>* circles) const override;
  const HoughOptions options_;
};

}  // namespace plywood::perception
