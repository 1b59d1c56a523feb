#include "perception/sonar_map/cognitive_map_json.h"

#include <charconv>
#include <cmath>
#include <string>
#include <vector>

namespace plywood::perception {
namespace {

std::string Number(double v) {
  if (!std::isfinite(v)) return "null";  // JSON has no NaN or infinity
  // std::to_chars does not depend on the locale, so the bytes are the same on every machine.
  char buffer[64];
  const auto result =
      std::to_chars(buffer, buffer + sizeof(buffer), v, std::chars_format::fixed, 4);
  const std::string text(buffer, result.ptr);
  // "-0.0000" and "0.0000" are the same place.
  return text == "-0.0000" ? std::string("0.0000") : text;
}

std::string Point(const Eigen::Vector2d& p) {
  return "[" + Number(p.x()) + ", " + Number(p.y()) + "]";
}

std::string Box(const Rect& r) {
  return "[" + Number(r.x0) + ", " + Number(r.y0) + ", " + Number(r.x1) + ", " + Number(r.y1) + "]";
}

template <typename T, typename F>
std::string List(const std::vector<T>& items, F&& format, const std::string& indent) {
  if (items.empty()) return "[]";
  std::string out = "[\n";
  for (std::size_t i = 0; i < items.size(); ++i)
    out += indent + "  " + format(items[i]) + (i + 1 < items.size() ? ",\n" : "\n");
  return out + indent + "]";
}

}  // namespace

std::string CognitiveMapToJson(const CognitiveMap& map) {
  std::vector<std::pair<int, int>> forbidden;
  for (const auto& [a, b] : map.negative.pairs())
    if (a < b) forbidden.emplace_back(a, b);
  std::string out = "{\n";
  out += "  \"room\": " + Box(map.room) + ",\n";
  out += "  \"obstacles\": " + List(map.obstacles, Box, "  ") + ",\n";
  out += "  \"corners\": " + List(map.corners, Point, "  ") + ",\n";
  out += "  \"partitions\": " +
         List(
             map.partitions.partitions(),
             [](const Partition& p) {
               return std::string("{\"rect\": ") + Box(p.rect) + ", \"label\": \"" +
                      (p.label == Label::kFree ? "free" : "obstacle") + "\"}";
             },
             "  ") +
         ",\n";
  out += "  \"negative_experience\": " +
         List(
             forbidden,
             [](const std::pair<int, int>& d) {
               return "[" + std::to_string(d.first) + ", " + std::to_string(d.second) + "]";
             },
             "  ") +
         ",\n";
  out += "  \"graph\": {\n    \"nodes\": [";
  for (std::size_t i = 0; i < map.graph.nodes.size(); ++i)
    out += (i ? ", " : "") + std::to_string(map.graph.nodes[i]);
  out += "],\n    \"arcs\": " +
         List(
             map.graph.arcs,
             [](const Adjacency& a) {
               return "{\"a\": " + std::to_string(a.a) + ", \"b\": " + std::to_string(a.b) +
                      ", \"door\": [" + Point(a.door_a) + ", " + Point(a.door_b) + "]}";
             },
             "    ") +
         "\n  }\n}\n";
  return out;
}

}  // namespace plywood::perception
