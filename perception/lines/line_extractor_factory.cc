#include "perception/lines/line_extractor_factory.h"

#include <algorithm>
#include <stdexcept>

namespace plywood::perception {
namespace {

[[noreturn]] void FailUnknown(const std::string& name, const std::vector<std::string>& known) {
  std::string list;
  for (const auto& n : known) list += (list.empty() ? "" : ", ") + n;
  throw std::invalid_argument("extractor: unknown line extractor '" + name + "' (known: " + list +
                              ")");
}

}  // namespace

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
  FailUnknown(name, LineExtractorNames());
}

std::vector<std::string> LineExtractorNames(const LineExtractorRegistry& registry) {
  std::vector<std::string> names = LineExtractorNames();
  for (const std::string& name : registry.Names()) names.push_back(name);
  return names;
}

std::unique_ptr<LineExtractor> MakeLineExtractor(const std::string& name,
                                                 const LineExtractorOptions& options,
                                                 const LineExtractorRegistry& registry) {
  const auto& built_in = LineExtractorNames();
  if (std::find(built_in.begin(), built_in.end(), name) != built_in.end()) {
    return MakeLineExtractor(name, options);
  }
  const RegisteredLineExtractor* entry = registry.Find(name);
  if (!entry) FailUnknown(name, LineExtractorNames(registry));
  const auto it = options.registered.find(name);
  return robot::MakeRegistered(*entry,
                               it == options.registered.end() ? robot::ParameterMap() : it->second);
}

}  // namespace plywood::perception
