#include "perception/lines/what_each_line_needs.h"

namespace plywood::perception {

std::vector<std::pair<std::string, int>> PointsEachLineNeeds(const LineExtractorOptions& o,
                                                             const std::string& extractor) {
  if (extractor == "polar_neighbour") return {{"min_points", o.polar_neighbour.min_points}};
  if (extractor == "split_and_merge") return {{"min_points", o.split_and_merge.filter.min_points}};
  if (extractor == "incremental") return {{"min_points", o.incremental.filter.min_points}};
  if (extractor == "ransac") {
    return {{"min_inliers", o.ransac.min_inliers}, {"min_points", o.ransac.min_points}};
  }
  if (extractor == "hough") {
    return {{"min_votes", o.hough.min_votes}, {"min_points", o.hough.min_points}};
  }
  return {};
}

double ShortestLineKeptM(const LineExtractorOptions& o, const std::string& extractor) {
  if (extractor == "split_and_merge") return o.split_and_merge.filter.min_length_m;
  if (extractor == "incremental") return o.incremental.filter.min_length_m;
  if (extractor == "ransac") return o.ransac.min_length_m;
  if (extractor == "hough") return o.hough.min_length_m;
  return 0.0;
}

}  // namespace plywood::perception
