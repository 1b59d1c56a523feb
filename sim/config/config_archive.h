#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <string>
#include <vector>

#include "sim/config/yaml_fields.h"
#include "sim/runner/metrics.h"

namespace plywood::sim {

// Each options struct's fields are listed once, in a VisitFields(Archive&, Options&) overload
// (sim/config/config_fields.h); the same list reads YAML (strictly, rejecting unknown keys) and
// writes the fully resolved config.yaml, so the two can never disagree. This is Drake's
// Serialize(Archive*) idea without touching the hardware-side structs, which must not see YAML.

class YamlReadArchive {
 public:
  explicit YamlReadArchive(YamlFields fields) : fields_(std::move(fields)) {}

  template <typename T>
  void operator()(const char* key, T& value) {
    fields_.Get(key, &value);
  }
  // An enum stored as text: parse(text) throws std::invalid_argument for unknown spellings.
  template <typename E, typename ToText, typename Parse>
  void Enum(const char* key, E& value, ToText, Parse parse) {
    if (!fields_.Has(key)) return;
    std::string text;
    fields_.Get(key, &text);
    try {
      value = parse(text);
    } catch (const std::invalid_argument& e) {
      fields_.Fail(key, e.what());
    }
  }
  // A list of fixed-width number rows ("waypoints: [[1, 2], [3, 4]]") mapped to structs.
  template <typename T, typename ToRow, typename FromRow>
  void Rows(const char* key, std::vector<T>& items, const std::vector<std::string>& columns, ToRow,
            FromRow from_row) {
    if (!fields_.Has(key)) return;
    const YAML::Node list = fields_.Raw(key);
    if (!list.IsSequence()) fields_.Fail(key, "expected a list of rows " + Describe(columns));
    items.clear();
    // One wrapper for every row: yaml-cpp merges the memory of the whole document into a node
    // assigned from it, so a wrapper per row made a list of n rows cost n^2 (20,000 waypoints
    // read for minutes); after the first assignment the memory is shared and a merge is free.
    YAML::Node wrapper(YAML::NodeType::Map);
    for (std::size_t i = 0; i < list.size(); ++i) {
      wrapper["row"] = list[i];
      YamlFields row(wrapper, fields_.file(), fields_.path());
      std::vector<double> values;
      const std::string element = std::string(key) + "[" + std::to_string(i) + "]";
      if (!list[i].IsSequence() || list[i].size() != columns.size()) {
        fields_.Fail(element, "expected a row " + Describe(columns));
      }
      // A `!!str` number was refused as "expected a row of finite numbers", the tag unnamed (s59's
      // left item); each scalar read alone says what is wrong with it.
      for (std::size_t j = 0; j < columns.size(); ++j) {
        if (list[i][j].Tag() == "tag:yaml.org,2002:str") {
          fields_.Fail(element + "[" + std::to_string(j) + "]",
                       "the YAML tag '!!str' says a string, but the row takes numbers " +
                           Describe(columns) + " (written '" + list[i][j].Scalar() +
                           "'): drop the tag");
        }
      }
      try {
        row.Get("row", &values);
      } catch (const std::exception&) {
        fields_.Fail(element, "expected a row of finite numbers " + Describe(columns));
      }
      items.push_back(from_row(values));
    }
  }
  // A nested options struct with its own VisitFields and Validate.
  template <typename T>
  void Nested(const char* key, T& value);

  YamlFields& fields() { return fields_; }

 private:
  static std::string Describe(const std::vector<std::string>& columns) {
    std::string text = "[";
    for (std::size_t i = 0; i < columns.size(); ++i) text += (i ? ", " : "") + columns[i];
    return text + "]";
  }

  YamlFields fields_;
};

class YamlWriteArchive {
 public:
  YamlWriteArchive() : node_(YAML::NodeType::Map) {}

  void operator()(const char* key, const double& value) { node_[key] = FormatNumber(value); }
  void operator()(const char* key, const int& value) { node_[key] = value; }
  void operator()(const char* key, const std::uint64_t& value) { node_[key] = value; }
  void operator()(const char* key, const bool& value) { node_[key] = value; }
  void operator()(const char* key, const std::string& value) { node_[key] = value; }
  void operator()(const char* key, const std::vector<double>& values) {
    YAML::Node list(YAML::NodeType::Sequence);
    for (double v : values) list.push_back(FormatNumber(v));
    list.SetStyle(YAML::EmitterStyle::Flow);
    node_[key] = list;
  }
  template <typename E, typename ToText, typename Parse>
  void Enum(const char* key, E& value, ToText to_text, Parse) {
    node_[key] = std::string(to_text(value));
  }
  template <typename T, typename ToRow, typename FromRow>
  void Rows(const char* key, std::vector<T>& items, const std::vector<std::string>&, ToRow to_row,
            FromRow) {
    YAML::Node list(YAML::NodeType::Sequence);
    for (const T& item : items) {
      YAML::Node row(YAML::NodeType::Sequence);
      for (double v : to_row(item)) row.push_back(FormatNumber(v));
      row.SetStyle(YAML::EmitterStyle::Flow);
      list.push_back(row);
    }
    node_[key] = list;
  }
  template <typename T>
  void Nested(const char* key, T& value);

  YAML::Node node() const { return node_; }

 private:
  YAML::Node node_;
};

// Reads `options` from `fields`: every listed field, then no unknown keys, then Validate().
template <typename T>
void ReadOptions(YamlFields fields, T& options) {
  YamlReadArchive archive(fields);
  VisitFields(archive, options);
  archive.fields().Finish();
  archive.fields().Validate(options);
}

template <typename T>
YAML::Node WriteOptions(T& options) {
  YamlWriteArchive archive;
  VisitFields(archive, options);
  return archive.node();
}

template <typename T>
void YamlReadArchive::Nested(const char* key, T& value) {
  ReadOptions(fields_.Child(key), value);
}

template <typename T>
void YamlWriteArchive::Nested(const char* key, T& value) {
  node_[key] = WriteOptions(value);
}

}  // namespace plywood::sim
