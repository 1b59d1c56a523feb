#include "eval/bench/tiled_world.h"

#include <regex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "perception/logs/regular_file.h"
#include "sim/runner/format_number.h"
#include "sim/runner/text_file.h"

namespace plywood::eval {

std::string TiledWorldMjcf(const std::filesystem::path& world_xml, int tiles_x, int tiles_y,
                           double pitch_x_m, double pitch_y_m) {
  if (!perception::IsRegularFile(world_xml)) {
    throw std::runtime_error(world_xml.string() + ": cannot read");
  }
  const std::string text = sim::ReadTextFile(world_xml);
  const std::size_t open = text.find("<worldbody>");
  const std::size_t close = text.find("</worldbody>");
  if (open == std::string::npos || close == std::string::npos || close < open) {
    throw std::runtime_error(world_xml.string() + ": no <worldbody>");
  }
  const std::size_t body_begin = open + std::string("<worldbody>").size();
  std::istringstream body(text.substr(body_begin, close - body_begin));
  std::vector<std::string> kept;  // light and floor, once
  std::vector<std::string> tiled;
  bool has_floor = false;
  for (std::string line; std::getline(body, line);) {
    if (line.find("<geom") == std::string::npos) {
      kept.push_back(line);
    } else if (line.find("name=\"floor\"") != std::string::npos) {
      // Scale the plane's half-extents to cover every tile.
      static const std::regex size(R"re(size="([-0-9.e]+) ([-0-9.e]+) )re");
      std::smatch m;
      if (!std::regex_search(line, m, size)) {
        throw std::runtime_error(world_xml.string() + ": floor: no size");
      }
      const double hx = std::stod(m[1]) + 0.5 * (tiles_x - 1) * pitch_x_m;
      const double hy = std::stod(m[2]) + 0.5 * (tiles_y - 1) * pitch_y_m;
      line = m.prefix().str() + "size=\"" + sim::FormatNumber(hx) + " " + sim::FormatNumber(hy) +
             " " + m.suffix().str();
      kept.push_back(line);
      has_floor = true;
    } else {
      tiled.push_back(line);
    }
  }
  if (!has_floor) throw std::runtime_error(world_xml.string() + ": no geom named \"floor\"");

  std::string out = text.substr(0, body_begin) + "\n";
  for (const std::string& line : kept) out += line + "\n";
  static const std::regex name(R"re(name="([^"]*)")re");
  static const std::regex pos(R"re(pos="([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+)")re");
  for (int i = 0; i < tiles_x; ++i) {
    for (int j = 0; j < tiles_y; ++j) {
      const std::string suffix = "_t" + std::to_string(i) + "_" + std::to_string(j);
      const double dx = (i - (tiles_x - 1) / 2) * pitch_x_m;
      const double dy = (j - (tiles_y - 1) / 2) * pitch_y_m;
      for (std::string line : tiled) {
        std::smatch m;
        if (!std::regex_search(line, m, pos)) {
          throw std::runtime_error(world_xml.string() + ": a geom without pos=\"x y z\"");
        }
        line = m.prefix().str() + "pos=\"" + sim::FormatNumber(std::stod(m[1]) + dx) + " " +
               sim::FormatNumber(std::stod(m[2]) + dy) + " " + m[3].str() + "\"" + m.suffix().str();
        out += std::regex_replace(line, name, "name=\"$1" + suffix + "\"") + "\n";
      }
    }
  }
  out += text.substr(close);
  return out;
}

}  // namespace plywood::eval
