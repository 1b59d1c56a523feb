#pragma once

#include <vector>

#include "perception/lines/circle_feature.h"
#include "perception/lines/line_segment.h"

namespace plywood::perception {

// Everything an extractor recognised in one scan: the lines, and the round objects it took out of
// them as circles (columns and legs have no line to give; their chords are not walls, yet their
// points are explained). Both in the points' frame.
struct ExtractedFeatures {
  std::vector<LineSegment> lines;
  std::vector<CircleFeature> circles;
};

}  // namespace plywood::perception
