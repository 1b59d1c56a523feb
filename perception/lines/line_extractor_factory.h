#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "perception/lines/hough_extractor.h"
#include "perception/lines/incremental_extractor.h"
#include "perception/lines/line_extractor.h"
#include "perception/lines/line_extractor_registry.h"
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
  // The options of registered extractors (line_extractor_registry.h), by name; none when absent.
  std::map<std::string, robot::ParameterMap> registered;
};

// "polar_neighbour", "split_and_merge", "incremental", "ransac", "hough".
const std::vector<std::string>& LineExtractorNames();

// The built-in names followed by the registered ones.
std::vector<std::string> LineExtractorNames(const LineExtractorRegistry& registry);

// @throws std::invalid_argument for an unknown name (listing the known ones) or invalid options.
std::unique_ptr<LineExtractor> MakeLineExtractor(const std::string& name,
                                                 const LineExtractorOptions& options = {});

// A built-in extractor, else the one `registry` has under `name`, built from
// options.registered[name].
// @throws std::invalid_argument for an unknown name (listing the built-in and registered ones),
// invalid options, or an option the registered factory did not read ("<key>: unknown key").
std::unique_ptr<LineExtractor> MakeLineExtractor(const std::string& name,
                                                 const LineExtractorOptions& options,
                                                 const LineExtractorRegistry& registry);

}  // namespace plywood::perception
