#include "sim/config/lines_config.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "sim/config/config_archive.h"
#include "sim/config/guarded_algorithms.h"
#include "sim/config/lines_fields.h"
#include "sim/config/plugin_loader.h"
#include "sim/config/plugin_options.h"
#include "sim/config/yaml_fields.h"
#include "sim/runner/metrics.h"

namespace plywood::sim {

using perception::VisitFields;

void LinesConfig::Validate() const {
  if (!(range_cut_m > 0.0)) {
    throw std::invalid_argument("range_cut_m: must be > 0, got " + FormatNumber(range_cut_m));
  }
  const std::vector<std::string> known =
      perception::LineExtractorNames(RegisteredAlgorithms().line_extractors);
  for (std::size_t i = 0; i < extractors.size(); ++i) {
    if (std::find(known.begin(), known.end(), extractors[i]) == known.end()) {
      std::string list;
      for (const auto& name : known) list += (list.empty() ? "" : ", ") + name;
      throw std::invalid_argument("extractors: unknown extractor '" + extractors[i] +
                                  "' (known: " + list + ")");
    }
    if (std::find(extractors.begin(), extractors.begin() + i, extractors[i]) !=
        extractors.begin() + i) {
      throw std::invalid_argument("extractors: '" + extractors[i] + "' is listed twice");
    }
  }
}

void ReadLinesConfig(YamlFields fields, LinesConfig& config) {
  config.given = true;
  const perception::LineExtractorRegistry& registered = RegisteredAlgorithms().line_extractors;
  config.extractors = perception::LineExtractorNames(registered);
  if (fields.Has("extractors")) {
    const YAML::Node list = fields.Raw("extractors");
    if (!list.IsSequence()) fields.Fail("extractors", "expected a list of extractor names");
    config.extractors.clear();
    for (const auto& item : list) {
      if (!item.IsScalar()) fields.Fail("extractors", "expected a list of extractor names");
      config.extractors.push_back(item.Scalar());
    }
  }
  fields.Get("range_cut_m", &config.range_cut_m);
  ReadOptions(fields.Child("scoring"), config.scoring);
  ReadOptions(fields.Child("polar_neighbour"), config.options.polar_neighbour);
  ReadOptions(fields.Child("split_and_merge"), config.options.split_and_merge);
  ReadOptions(fields.Child("incremental"), config.options.incremental);
  ReadOptions(fields.Child("ransac"), config.options.ransac);
  ReadOptions(fields.Child("hough"), config.options.hough);
  config.options.registered.clear();
  for (const std::string& name : registered.Names()) {
    if (!fields.Has(name)) continue;
    YamlFields options = fields.Child(name);
    config.options.registered[name] = ReadPluginOptions(options);
  }
  fields.Finish();
  fields.Validate(config);
  // Build each registered extractor that will run, or was given options, once now, so a bad or
  // unknown option is reported before the run.
  for (const std::string& name : registered.Names()) {
    const bool runs = std::find(config.extractors.begin(), config.extractors.end(), name) !=
                      config.extractors.end();
    if (!runs && !config.options.registered.count(name)) continue;
    CheckPluginBuild(fields.Child(name), [&] { MakeLineExtractor(name, config); });
  }
}

YAML::Node WriteLinesConfig(LinesConfig& config) {
  YAML::Node node(YAML::NodeType::Map);
  YAML::Node list(YAML::NodeType::Sequence);
  for (const auto& name : config.extractors) list.push_back(name);
  list.SetStyle(YAML::EmitterStyle::Flow);
  node["extractors"] = list;
  node["range_cut_m"] = FormatNumber(config.range_cut_m);
  node["scoring"] = WriteOptions(config.scoring);
  node["polar_neighbour"] = WriteOptions(config.options.polar_neighbour);
  node["split_and_merge"] = WriteOptions(config.options.split_and_merge);
  node["incremental"] = WriteOptions(config.options.incremental);
  node["ransac"] = WriteOptions(config.options.ransac);
  node["hough"] = WriteOptions(config.options.hough);
  for (const auto& [name, options] : config.options.registered) {
    YAML::Node plugin(YAML::NodeType::Map);
    WritePluginOptions(options, plugin);
    if (options.empty()) plugin.SetStyle(YAML::EmitterStyle::Flow);  // "name: {}"
    node[name] = plugin;
  }
  return node;
}

std::unique_ptr<perception::LineExtractor> MakeLineExtractor(const std::string& name,
                                                             const LinesConfig& config) {
  auto extractor =
      perception::MakeLineExtractor(name, config.options, RegisteredAlgorithms().line_extractors);
  if (!RegisteredAlgorithms().line_extractors.Find(name)) return extractor;
  return GuardRegistered(std::move(extractor), "line extractor '" + name + "' (" +
                                                   RegisteredBy("line extractor", name) + ")");
}

std::vector<std::string> TakenLinesKeys() {
  std::vector<std::string> keys = perception::LineExtractorNames();
  // Section keys, and "scans": metrics.json's lines.scans would also be lines.<name>.*.
  for (const char* key : {"extractors", "range_cut_m", "scoring", "scans"}) keys.push_back(key);
  return keys;
}

}  // namespace plywood::sim
