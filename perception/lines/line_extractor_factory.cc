#include "perception/lines/line_extractor_factory.h"

#include <stdexcept>

namespace plywood::perception {

const std::vector<std::string>& LineExtractorNames() {
  static const std::vector<std::string> names{"polar_neighbour", "split_and_merge", "incremental",
                                              "ransac", "hough"};
  return names;
}

std::unique_ptr<LineExtractor> MakeLineExtractor(const std::string& name,
                                                 const LineExtractorOptions& options) {
  if (name == "polar_neighbour")
    return std::make_unique<PolarNeighbourExtractor>(options.polar_neighbour);
  if (name == "split_and_merge")
    return std::make_unique<SplitAndMergeExtractor>(options.split_and_merge);
  if (name == "incremental") return std::make_unique<IncrementalExtractor>(options.incremental);
  if (name == "ransac") return std::make_unique<RansacExtractor>(options.ransac);
  if (name == "hough") return std::make_unique<HoughExtractor>(options.hough);
  std::string known;
  for (const auto& n : LineExtractorNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("extractor: unknown line extractor '" + name + "' (known: " + known +
                              ")");
}

}  // namespace plywood::perception
