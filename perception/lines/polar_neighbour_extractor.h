#pragma once

#include <string>
#include <vector>

#include "perception/lines/line_extractor.h"

namespace plywood::perception {

// Seed 000 (Souza, Becker, Rodrigues): polar-neighbourhood grouping. For each point P_i the line
// through P_{i-1}, P_i, P_{i+1} is fitted and put in normal form (alpha_i, r_i); consecutive points
// are chained while they are closer than max_point_distance_m and their local lines agree within
// max_alpha_diff_deg and max_r_diff_m; each chain of at least min_points points gives one line.
// Defaults are the paper's Table 2 (range cut 3-4 m: 4 m here; the scan filter applies it).
struct PolarNeighbourOptions {
  double max_point_distance_m = 0.30;
  double max_alpha_diff_deg = 30.0;
  double max_r_diff_m = 0.15;
  double max_range_m = 4.0;
  int min_points = 4;
  // The shared break rule (line_extractor.h OpeningBetween): points with more beams than this
  // between them without a usable return are never chained.
  int max_missing_beams = 1;

  void Validate() const;
};

class PolarNeighbourExtractor final : public LineExtractor {
 public:
  explicit PolarNeighbourExtractor(const PolarNeighbourOptions& options = {});
  std::string name() const override { return "polar_neighbour"; }
  std::vector<LineSegment> Extract(const ScanPoints& scan) const override;

 private:
  const PolarNeighbourOptions options_;
};

}  // namespace plywood::perception
