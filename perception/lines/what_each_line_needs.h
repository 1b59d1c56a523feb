#pragma once

#include <string>
#include <utility>
#include <vector>

#include "perception/lines/line_extractor_factory.h"

namespace plywood::perception {

// The options of the built-in extractor `extractor` that ask each line for at least that many
// points (or votes, or inliers) of one scan, by key; none for a registered extractor. A count
// above a scan's points finds no line in any scan.
std::vector<std::pair<std::string, int>> PointsEachLineNeeds(const LineExtractorOptions& options,
                                                             const std::string& extractor);

// The shortest segment the built-in extractor `extractor` keeps (its min_length_m), 0 when it
// keeps any. Two returns of one scan lie at most twice the maximum range apart, so a minimum
// above that finds no line either.
double ShortestLineKeptM(const LineExtractorOptions& options, const std::string& extractor);

}  // namespace plywood::perception
