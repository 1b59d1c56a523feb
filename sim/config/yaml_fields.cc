#include "sim/config/yaml_fields.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <sstream>

#include "perception/logs/parse_number.h"
#include "sim/config/config_error.h"
#include "sim/config/decimal_whole_number.h"
#include "sim/config/yaml_alias_expansion.h"

namespace plywood::sim {
namespace {

std::string Describe(const YAML::Node& node) {
  if (node.IsNull()) return "nothing";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "'" + node.Scalar() + "'";
}

// Parses the whole of `text` as a finite number (perception::ParseFiniteNumber).
bool ParseFinite(const std::string& text, double* value) {
  const std::optional<double> parsed = perception::ParseFiniteNumber(text);
  if (parsed) *value = *parsed;
  return parsed.has_value();
}

// A scalar tagged `!!str` where a number or a boolean is read: the tag says the value is text,
// which the reader would have turned into a number regardless (yaml-cpp keeps the tag, not the
// type), so `duration_s: !!str 0.4` ran 0.4 s. A quoted '0.4' carries no tag and is still read.
bool TaggedAsString(const YAML::Node& node) { return node.Tag() == "tag:yaml.org,2002:str"; }

std::string StringTagMessage(const YAML::Node& node, const char* wanted) {
  return std::string("the YAML tag '!!str' says a string, but the key takes ") + wanted +
         " (written '" + node.Scalar() + "'): drop the tag";
}

}  // namespace

YamlFields::YamlFields(const YAML::Node& node, std::string file, std::string path)
    : node_(node), file_(std::move(file)), path_(std::move(path)) {
  if (node_.IsDefined() && !node_.IsNull() && !node_.IsMap()) {
    throw ConfigError(file_, path_.empty() ? "(top level)" : path_,
                      "expected a mapping of keys, got " + Describe(node_));
  }
}

std::string YamlFields::FieldPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

bool YamlFields::Has(const std::string& key) const {
  known_.insert(key);
  return node_.IsMap() && node_[key].IsDefined();
}

void YamlFields::Fail(const std::string& key, const std::string& message) const {
  throw ConfigError(file_, FieldPath(key), message);
}

void YamlFields::FailValidation(const std::string& what) const {
  // Validate() messages read "field: reason"; join the field onto this mapping's path.
  const auto colon = what.find(": ");
  if (colon != std::string::npos && what.find(' ') > colon) {
    throw ConfigError(file_, FieldPath(what.substr(0, colon)), what.substr(colon + 2));
  }
  throw ConfigError(file_, path_, what);
}

YAML::Node YamlFields::Scalar(const std::string& key, const char* expected) const {
  const YAML::Node value = node_[key];
  if (!value.IsScalar())
    Fail(key, std::string("expected ") + expected + ", got " + Describe(value));
  return value;
}

void YamlFields::Get(const std::string& key, double* value) {
  if (!Has(key)) return;
  used_.insert(key);
  const YAML::Node node = Scalar(key, "a number");
  if (TaggedAsString(node)) Fail(key, StringTagMessage(node, "a number"));
  const std::string text = node.Scalar();
  if (!ParseFinite(text, value)) Fail(key, "expected a finite number, got '" + text + "'");
}

void YamlFields::Get(const std::string& key, int* value) {
  if (!Has(key)) return;
  double parsed = 0.0;
  Get(key, &parsed);
  if (parsed != std::floor(parsed) || std::abs(parsed) > std::numeric_limits<int>::max()) {
    Fail(key, "expected a whole number, got " + node_[key].Scalar());
  }
  *value = static_cast<int>(parsed);
}

void YamlFields::Get(const std::string& key, std::uint64_t* value) {
  if (!Has(key)) return;
  used_.insert(key);
  const YAML::Node node = Scalar(key, "a whole number");
  if (TaggedAsString(node)) Fail(key, StringTagMessage(node, "a whole number"));
  const std::string text = node.Scalar();
  const std::optional<std::uint64_t> parsed = ParseDecimalWholeNumber(text);
  if (!parsed) Fail(key, "expected a non-negative whole number, got '" + text + "'");
  *value = *parsed;
}

void YamlFields::Get(const std::string& key, bool* value) {
  if (!Has(key)) return;
  used_.insert(key);
  const YAML::Node node = Scalar(key, "true or false");
  if (TaggedAsString(node)) Fail(key, StringTagMessage(node, "true or false"));
  const std::string text = node.Scalar();
  if (text == "true") {
    *value = true;
  } else if (text == "false") {
    *value = false;
  } else {
    Fail(key, "expected true or false, got '" + text + "'");
  }
}

void YamlFields::Get(const std::string& key, std::string* value) {
  if (!Has(key)) return;
  used_.insert(key);
  *value = Scalar(key, "a string").Scalar();
}

void YamlFields::Get(const std::string& key, std::vector<double>* value) {
  if (!Has(key)) return;
  used_.insert(key);
  const YAML::Node list = node_[key];
  if (!list.IsSequence()) Fail(key, "expected a list of numbers, got " + Describe(list));
  value->clear();
  for (std::size_t i = 0; i < list.size(); ++i) {
    double v = 0.0;
    const std::string element = key + "[" + std::to_string(i) + "]";
    if (!list[i].IsScalar()) Fail(element, "expected a number, got " + Describe(list[i]));
    if (TaggedAsString(list[i])) Fail(element, StringTagMessage(list[i], "a number"));
    if (!ParseFinite(list[i].Scalar(), &v)) {
      Fail(element, "expected a finite number, got '" + list[i].Scalar() + "'");
    }
    value->push_back(v);
  }
}

void YamlFields::GetDegrees(const std::string& key, double* radians) {
  if (!Has(key)) return;
  double degrees = 0.0;
  Get(key, &degrees);
  *radians = degrees * std::numbers::pi / 180.0;
}

YamlFields YamlFields::Child(const std::string& key) {
  known_.insert(key);
  used_.insert(key);
  return YamlFields(node_.IsMap() ? node_[key] : YAML::Node(), file_, FieldPath(key));
}

std::vector<YamlFields> YamlFields::ChildList(const std::string& key) {
  std::vector<YamlFields> children;
  if (!Has(key)) return children;
  used_.insert(key);
  const YAML::Node list = node_[key];
  if (!list.IsSequence()) Fail(key, "expected a list, got " + Describe(list));
  for (std::size_t i = 0; i < list.size(); ++i) {
    children.emplace_back(list[i], file_, FieldPath(key) + "[" + std::to_string(i) + "]");
  }
  return children;
}

YAML::Node YamlFields::Raw(const std::string& key) {
  known_.insert(key);
  used_.insert(key);
  return node_.IsMap() ? node_[key] : YAML::Node();
}

std::vector<std::string> YamlFields::Keys() const {
  std::vector<std::string> keys;
  if (!node_.IsMap()) return keys;
  for (const auto& entry : node_) keys.push_back(entry.first.Scalar());
  return keys;
}

void YamlFields::Finish() const {
  if (!node_.IsMap()) return;
  for (const auto& entry : node_) {
    const std::string key = entry.first.Scalar();
    if (used_.count(key)) continue;
    std::string known;
    for (const std::string& k : known_) known += (known.empty() ? "" : ", ") + k;
    known = known.empty() ? std::string() : " (known here: " + known + ")";
    // `? [a, b]: 1` (a list or a map as the key) was "a key that is null or empty" (s56).
    if (entry.first.IsSequence() || entry.first.IsMap()) {
      Fail("?", std::string("unknown key: a key that is ") +
                    (entry.first.IsSequence() ? "a list" : "a map") +
                    " (YAML's '? ' complex key) names no setting" + known);
    }
    // `~: 5` (or `null:`, `"":`) was "plywood: e.yaml: unknown key", naming no field.
    if (key.empty() || entry.first.IsNull()) {
      Fail(entry.first.IsNull() ? "~" : "\"\"",
           "unknown key: a key that is null or empty names no setting" + known);
    }
    Fail(key, "unknown key" + known);
  }
}

void RejectDuplicateKeys(const YAML::Node& node, const std::string& file, const std::string& path) {
  const auto child_path = [&](const std::string& key) {
    return path.empty() ? key : path + "." + key;
  };
  if (node.IsMap()) {
    std::set<std::string> seen;
    for (const auto& entry : node) {
      // A list or a map as the key names no setting: YamlFields::Finish refuses it as such.
      if (entry.first.IsSequence() || entry.first.IsMap()) continue;
      const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "";
      if (!seen.insert(key).second) {
        throw ConfigError(file, child_path(key),
                          "duplicate key (YAML would silently keep only the first)");
      }
      RejectDuplicateKeys(entry.second, file, child_path(key));
    }
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      RejectDuplicateKeys(node[i], file, path + "[" + std::to_string(i) + "]");
    }
  }
}

void ApplyOverride(YAML::Node root, const std::string& assignment, const std::string& source) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw ConfigError(source, "", "expected key.path=value");
  }
  const std::string path = assignment.substr(0, equals);
  YAML::Node value;
  std::size_t documents = 0;
  try {
    const std::string text = assignment.substr(equals + 1);
    value = YAML::Load(text);
    documents = YAML::LoadAll(text).size();
  } catch (const YAML::Exception& e) {
    throw ConfigError(source, path, std::string("value is not valid YAML: ") + e.what());
  }
  // yaml-cpp reads text after a value's closing quote or bracket as a second document and Load
  // keeps the first: `name="x" extra` set x, `controller.waypoints=[[1, 2]] [[3, 4]]` the first
  // list, the rest dropped without a word (s62).
  if (documents > 1) {
    throw ConfigError(source, path,
                      "value is not valid YAML: text follows the end of its value (a closing "
                      "quote or bracket), which would be dropped: quote the whole value, or "
                      "remove the rest");
  }
  RejectAliasExpansion(value, source);
  // getline yields no last empty key: `duration_s.=1` set duration_s without a word (s56).
  if (path.ends_with('.')) throw ConfigError(source, path, "empty key in path");
  std::vector<std::string> keys;
  std::stringstream stream(path);
  for (std::string key; std::getline(stream, key, '.');) {
    if (key.empty()) throw ConfigError(source, path, "empty key in path");
    keys.push_back(key);
  }
  // yaml-cpp nodes are handles: walk down with fresh handles, never re-seat (assigning to a handle
  // would overwrite the node it refers to).
  std::vector<YAML::Node> chain{root};
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    YAML::Node next = chain.back()[keys[i]];
    if (next.IsDefined() && !next.IsNull() && !next.IsMap()) {
      throw ConfigError(source, path, "'" + keys[i] + "' is not a mapping");
    }
    chain.push_back(next);
  }
  chain.back()[keys.back()] = value;
}

}  // namespace plywood::sim
