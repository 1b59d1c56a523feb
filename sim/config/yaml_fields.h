#pragma once

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>
#include <vector>

namespace plywood::sim {

// Strict reader of one YAML mapping: every key read is remembered so that Finish() can reject keys
// nobody asked for (a typo must not silently fall back to a default). All errors are ConfigError
// naming the file and the dotted field path ("sensors.laser.rate_hz").
class YamlFields {
 public:
  // `node` may be undefined/null (treated as an empty mapping, all defaults); anything else that is
  // not a mapping is an error.
  YamlFields(const YAML::Node& node, std::string file, std::string path);

  bool Has(const std::string& key) const;

  // Reads `key` into `value` if present; leaves the default otherwise.
  void Get(const std::string& key, double* value);
  void Get(const std::string& key, int* value);
  void Get(const std::string& key, std::uint64_t* value);
  void Get(const std::string& key, bool* value);
  void Get(const std::string& key, std::string* value);
  void Get(const std::string& key, std::vector<double>* value);
  // Reads an angle given in degrees into radians.
  void GetDegrees(const std::string& key, double* radians);

  // A nested mapping; undefined when absent.
  YamlFields Child(const std::string& key);
  // A nested sequence of mappings.
  std::vector<YamlFields> ChildList(const std::string& key);
  // The raw node (marks the key as used).
  YAML::Node Raw(const std::string& key);
  // The mapping's keys in document order (none when it is absent or empty).
  std::vector<std::string> Keys() const;

  // @throws ConfigError for the first key that was never read.
  void Finish() const;

  // @throws ConfigError at `key` with `message`.
  [[noreturn]] void Fail(const std::string& key, const std::string& message) const;
  // Runs an options struct's Validate() and turns its std::invalid_argument ("field: reason") into
  // a ConfigError at this mapping's path.
  template <typename Options>
  void Validate(const Options& options) const {
    try {
      options.Validate();
    } catch (const std::invalid_argument& e) {
      FailValidation(e.what());
    }
  }

  // @throws ConfigError for a Validate()-style message "field: reason" at this mapping's path
  // (a message without a leading field is reported at the mapping itself).
  [[noreturn]] void FailValidation(const std::string& what) const;

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  std::string FieldPath(const std::string& key) const;

 private:
  YAML::Node Scalar(const std::string& key, const char* expected) const;

  YAML::Node node_;
  std::string file_;
  std::string path_;
  std::set<std::string> used_;
  mutable std::set<std::string> known_;  // every key asked for, to list in "unknown key" errors
};

// @throws ConfigError naming the first key that appears twice in one mapping of `node`.
void RejectDuplicateKeys(const YAML::Node& node, const std::string& file,
                         const std::string& path = "");

// Applies a command-line override "a.b.c=value" to a YAML tree, creating mappings on the way.
// The value is parsed as YAML, so numbers, booleans, lists and strings all work.
// @throws ConfigError naming `source` (e.g. "--set") when the override is malformed.
void ApplyOverride(YAML::Node root, const std::string& assignment, const std::string& source);

}  // namespace plywood::sim
