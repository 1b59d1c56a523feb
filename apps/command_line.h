#pragma once

#include <optional>
#include <string>
#include <vector>

namespace plywood::apps {

// Bad command-line usage: printed as one line, exit code 2.
struct UsageError {
  std::string message;
};

// A small strict parser for "subcommand POSITIONAL... [--flag value]... [--switch]": flags may
// repeat (--set), unknown flags are errors.
class CommandLine {
 public:
  // `value_flags` take a value ("--out DIR" or "--out=DIR"); `switches` take none.
  CommandLine(const std::vector<std::string>& args, const std::vector<std::string>& value_flags,
              const std::vector<std::string>& switches);

  const std::vector<std::string>& positional() const { return positional_; }
  std::optional<std::string> Value(const std::string& flag) const;
  std::vector<std::string> Values(const std::string& flag) const;
  bool Switch(const std::string& flag) const;

  // Parses a flag's value as a number. @throws UsageError.
  std::optional<double> Number(const std::string& flag) const;

 private:
  std::vector<std::string> positional_;
  std::vector<std::pair<std::string, std::string>> values_;
  std::vector<std::string> switches_;
};

}  // namespace plywood::apps
