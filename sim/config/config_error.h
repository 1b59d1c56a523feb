#pragma once

#include <stdexcept>
#include <string>

namespace plywood::sim {

// Bad user input: a config file, a world file, a log. what() is one line naming the file and the
// field, e.g. "experiments/x.yaml: sensors.laser.rate_hz: must be > 0, got -1". The apps print it
// and exit with code 2.
class ConfigError : public std::runtime_error {
 public:
  ConfigError(const std::string& file, const std::string& field, const std::string& message)
      : std::runtime_error(Compose(file, field, message)) {}

 private:
  static std::string Compose(const std::string& file, const std::string& field,
                             const std::string& message) {
    std::string line = file;
    if (!field.empty()) line += (line.empty() ? "" : ": ") + field;
    line += (line.empty() ? "" : ": ") + message;
    // One line, whatever the message carried (MuJoCo's compiler errors span several).
    for (char& c : line) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    return line;
  }
};

}  // namespace plywood::sim
