#pragma once

#include <memory>
#include <string>
#include <vector>

#include "perception/lines/hough_extractor.h"
#include "perception/lines/incremental_extractor.h"
#include "perception/lines/line_extractor.h"
#include "perception/lines/polar_neighbour_extractor.h"
#include "perception/lines/ransac_extractor.h"
#include "perception/lines/split_and_merge_extractor.h"

namespace plywood::perception {

// The options of every extractor, each holding its defaults; an extractor is picked by name.
struct LineExtractorOptions {
  PolarNeighbourOptions polar_neighbour;
  SplitAndMergeOptions split_and_merge;
  IncrementalOptions incremental;
  RansacOptions ransac;
  HoughOptions hough;
};

// "polar_neighbour", "split_and_merge", "incremental", "ransac", "hough".
const std::vector<std::string>& LineExtractorNames();

// @throws std::invalid_argument for an unknown name (listing the known ones) or invalid options.
std::unique_ptr<LineExtractor> MakeLineExtractor(const std::string& name,
                                                 const LineExtractorOptions& options = {});

}  // namespace plywood::perception
