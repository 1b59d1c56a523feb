#include "apps/command_line.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "perception/logs/parse_number.h"

namespace plywood::apps {
namespace {

bool Contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

}  // namespace

CommandLine::CommandLine(const std::vector<std::string>& args,
                         const std::vector<std::string>& value_flags,
                         const std::vector<std::string>& switches) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.rfind("--", 0) != 0) {
      positional_.push_back(arg);
      continue;
    }
    const auto equals = arg.find('=');
    const std::string flag = arg.substr(0, equals);
    if (Contains(switches, flag) && equals == std::string::npos) {
      switches_.push_back(flag);
    } else if (Contains(value_flags, flag)) {
      if (equals != std::string::npos) {
        values_.emplace_back(flag, arg.substr(equals + 1));
      } else if (i + 1 < args.size()) {
        values_.emplace_back(flag, args[++i]);
      } else {
        throw UsageError{flag + " needs a value"};
      }
    } else {
      throw UsageError{"unknown option " + flag};
    }
  }
}

std::optional<std::string> CommandLine::Value(const std::string& flag) const {
  std::optional<std::string> last;
  for (const auto& [name, value] : values_) {
    if (name == flag) last = value;
  }
  return last;
}

std::vector<std::string> CommandLine::Values(const std::string& flag) const {
  std::vector<std::string> all;
  for (const auto& [name, value] : values_) {
    if (name == flag) all.push_back(value);
  }
  return all;
}

bool CommandLine::Switch(const std::string& flag) const { return Contains(switches_, flag); }

std::optional<double> CommandLine::Number(const std::string& flag) const {
  const auto text = Value(flag);
  if (!text) return std::nullopt;
  const std::optional<double> value = perception::ParseFiniteNumber(*text);
  if (!value) throw UsageError{flag + ": expected a number, got '" + *text + "'"};
  return value;
}

}  // namespace plywood::apps
