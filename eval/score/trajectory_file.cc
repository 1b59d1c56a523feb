#include "eval/score/trajectory_file.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <utility>

#include "eval/score/csv_table.h"
#include "eval/score/score_report.h"
#include "perception/logs/byte_order_mark.h"
#include "perception/logs/regular_file.h"
#include "sim/config/config_error.h"
#include "sim/runner/metrics.h"

namespace plywood::eval {
namespace {

bool EndsWith(const std::string& text, const std::string& suffix) {
  return text.size() > suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::vector<NamedTrajectory> ReadPlywoodCsv(const std::filesystem::path& path,
                                            const std::string& name_flag) {
  const CsvTable table = ReadCsv(path, {.comments = true});
  const auto header_error = [&](const std::string& field, const std::string& what) {
    throw sim::ConfigError(table.file + ":" + std::to_string(table.header_line), field, what);
  };
  const std::vector<std::string>& h = table.header;
  if (h.size() < 4 || (h.size() - 1) % 3 != 0) {
    header_error("header", "expected time_s then groups NAME_x_m,NAME_y_m,NAME_theta_rad, got " +
                               std::to_string(h.size()) + " columns");
  }
  // The header names every estimate: `--name other` was dropped without a word and the figures
  // came out under the header's name.
  if (!name_flag.empty()) {
    header_error("header", "names the file's estimates (NAME_x_m, ...), so --name " + name_flag +
                               " would be ignored: leave --name out");
  }
  std::vector<NamedTrajectory> trajectories;
  for (std::size_t c = 1; c < h.size(); c += 3) {
    if (!EndsWith(h[c], "_x_m")) header_error(h[c], "expected a column NAME_x_m");
    const std::string name = h[c].substr(0, h[c].size() - 4);
    // The name becomes the metric keys odometry.NAME.*: "my.est" would read as estimator "my".
    if (!IsMetricName(name)) {
      header_error(h[c], NotAMetricName(name));
    }
    if (h[c + 1] != name + "_y_m") header_error(h[c + 1], "expected " + name + "_y_m");
    if (h[c + 2] != name + "_theta_rad") header_error(h[c + 2], "expected " + name + "_theta_rad");
    trajectories.push_back({name, {}});
  }
  for (const CsvRow& row : table.rows) {
    const double t = table.Number(row, 0, "time_s");
    if (!trajectories.front().poses.empty() && !(t > trajectories.front().poses.back().time_s)) {
      table.Fail(row, "time_s",
                 sim::FormatNumber(t) + " s does not come after the previous row's " +
                     sim::FormatNumber(trajectories.front().poses.back().time_s) + " s");
    }
    for (std::size_t k = 0; k < trajectories.size(); ++k) {
      const std::size_t c = 1 + 3 * k;
      perception::TimedPose pose;
      pose.time_s = t;
      pose.line_number = row.line_number;
      pose.pose = {table.Number(row, c, h[c]), table.Number(row, c + 1, h[c + 1]),
                   table.Number(row, c + 2, h[c + 2])};
      for (const auto& [i, v] : {std::pair{c, pose.pose.x_m}, std::pair{c + 1, pose.pose.y_m}}) {
        if (std::abs(v) > perception::kMaxTrajectoryCoordinateM) {
          table.Fail(row, h[i],
                     "must be within 1e+09 m of the origin, got " + sim::FormatNumber(v));
        }
      }
      if (std::abs(pose.pose.theta_rad) > perception::kMaxTrajectoryHeadingRad) {
        table.Fail(row, h[c + 2],
                   "must be within 1e+09 rad of 0 (beyond it a double cannot hold a heading to "
                   "1e-6 rad), got " +
                       sim::FormatNumber(pose.pose.theta_rad));
      }
      trajectories[k].poses.push_back(pose);
    }
  }
  return trajectories;
}

}  // namespace

bool IsPlywoodCsvLayout(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  bool first_line = true;  // a UTF-8 byte-order mark there hid "time_s" (read as a TUM file)
  for (std::string line; std::getline(in, line);) {
    if (std::exchange(first_line, false)) perception::DropUtf8ByteOrderMark(line);
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    // Quoted, as R's write.csv and Python's csv.QUOTE_ALL write header names, it was read as TUM
    // and refused as "tx: expected 8 fields ..., got 1"; the CSV reader takes RFC 4180 quotes.
    return line.compare(first, 6, "time_s") == 0 || line.compare(first, 8, "\"time_s\"") == 0;
  }
  return false;
}

std::vector<NamedTrajectory> ReadTrajectoryFile(const std::filesystem::path& path,
                                                const std::string& tum_name,
                                                const std::string& name_flag) {
  if (!perception::IsRegularFile(path)) {
    throw sim::ConfigError(path.string(), "", perception::WhyNotARegularFile(path));
  }
  if (IsPlywoodCsvLayout(path)) return ReadPlywoodCsv(path, name_flag);
  try {
    return {{tum_name, perception::ReadTumTrajectory(path)}};
  } catch (const std::invalid_argument& e) {
    throw sim::ConfigError("", "", e.what());  // already "FILE:LINE: FIELD: what"
  }
}

std::string TrajectoryNameOf(const std::filesystem::path& path) {
  std::string name = path.stem().string();
  if (name.rfind("trajectory.", 0) == 0 && name.size() > 11) name = name.substr(11);
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
  }
  return name.empty() ? "estimate" : name;
}

}  // namespace plywood::eval
