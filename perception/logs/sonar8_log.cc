#include "perception/logs/sonar8_log.h"

#include <array>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "msgs/angle_units.h"
#include "msgs/shortest_number.h"
#include "perception/logs/parse_number.h"
#include "perception/logs/regular_file.h"

namespace plywood::perception {
namespace {

// One line's numbers, with its 1-based line number in the file (blank lines are skipped).
struct Row {
  int line = 0;
  std::vector<double> values;
};

std::vector<Row> ReadColumns(const std::filesystem::path& path, int columns) {
  // A folder opens as a stream that reads nothing (a log of 0 rings, no error); a FIFO would be
  // waited on for ever.
  if (!IsRegularFile(path))
    throw std::runtime_error(path.string() + ": " + WhyNotARegularFile(path));
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  std::vector<Row> rows;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream s(line);
    std::vector<double> row;
    std::string token;
    while (s >> token) {
      const std::optional<double> v = ParseFiniteNumber(token);
      if (!v) {
        throw std::runtime_error(path.string() + ": line " + std::to_string(n) + ": '" + token +
                                 "' is not a number");
      }
      row.push_back(*v);
    }
    if (static_cast<int>(row.size()) != columns)
      throw std::runtime_error(path.string() + ": line " + std::to_string(n) + ": expected " +
                               std::to_string(columns) + " numbers, got " +
                               std::to_string(row.size()));
    rows.push_back({n, row});
  }
  return rows;
}

}  // namespace

std::vector<Sonar8Record> LoadSonar8Log(const std::filesystem::path& folder) {
  const auto m = ReadColumns(folder / "measurement.txt", 9);
  const auto p = ReadColumns(folder / "poses.txt", 4);
  // Two empty files made a log of no rings: a grid integrated from nothing, without a word.
  if (m.empty()) {
    throw std::runtime_error((folder / "measurement.txt").string() +
                             ": no measurement line: an empty log has nothing to map");
  }
  if (m.size() != p.size())
    throw std::runtime_error((folder / "poses.txt").string() + ": " + std::to_string(p.size()) +
                             " poses for " + std::to_string(m.size()) + " measurements");
  constexpr std::array<double, 8> kBearingDeg{-90, -37.5, -22.5, -7.5, 7.5, 22.5, 37.5, 90};
  std::vector<Sonar8Record> out;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m[i].values[0] != p[i].values[0])
      throw std::runtime_error((folder / "poses.txt").string() + ": line " +
                               std::to_string(p[i].line) + ": timestamp differs from line " +
                               std::to_string(m[i].line) + " of measurement.txt");
    const std::vector<double>& pose = p[i].values;
    Sonar8Record r;
    r.X_WR = {pose[1] / 1000.0, pose[2] / 1000.0, msgs::WrapAngle(pose[3] / 10.0 * kPi / 180.0)};
    r.ring.time_s = m[i].values[0] / 1000.0;
    r.ring.range_min_m = 0.17;
    r.ring.range_max_m = 5.0;
    for (int k = 0; k < 8; ++k) {
      msgs::RangeReading reading;
      reading.X_RS = {0.0, 0.0, kBearingDeg[k] * kPi / 180.0};
      const double range_mm = m[i].values[k + 1];
      // A negative range was taken for "no echo", and a miss clears its whole cone out to 5 m:
      // the grid was painted free where nothing was measured.
      if (range_mm < 0.0) {
        throw std::runtime_error((folder / "measurement.txt").string() + ": line " +
                                 std::to_string(m[i].line) + ": r" + std::to_string(k + 1) +
                                 ": negative range " + msgs::ShortestNumber(range_mm) +
                                 " mm (no echo is written 5110)");
      }
      const double range_m = range_mm / 1000.0;
      reading.echo = range_m >= 0.17 && range_m <= 5.0;
      reading.range_m = reading.echo ? range_m : 0.0;
      r.ring.readings.push_back(reading);
    }
    out.push_back(r);
  }
  return out;
}

}  // namespace plywood::perception
