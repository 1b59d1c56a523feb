#include "eval/sonar_map/cognitive_map_json.h"

#include <vector>

#include "sim/runner/json_text.h"

namespace plywood::eval {
namespace {

using Json = nlohmann::ordered_json;

Json Point(const Eigen::Vector2d& p) { return Json::array({p.x(), p.y()}); }

Json RectJson(const perception::Rect& r) { return Json::array({r.x0, r.y0, r.x1, r.y1}); }

template <typename T, typename F>
Json List(const std::vector<T>& items, F&& to_json) {
  Json list = Json::array();
  for (const T& item : items) list.push_back(to_json(item));
  return list;
}

}  // namespace

Json CognitiveMapJson(const perception::CognitiveMap& map) {
  std::vector<std::pair<int, int>> forbidden;
  for (const auto& [a, b] : map.negative.pairs())
    if (a < b) forbidden.emplace_back(a, b);
  Json json = Json::object();
  json["room"] = RectJson(map.room);
  json["obstacles"] = List(map.obstacles, RectJson);
  json["bridges"] = List(map.bridges, RectJson);
  json["corners"] = List(map.corners, Point);
  json["partitions"] = List(map.partitions.partitions(), [](const perception::Partition& p) {
    return Json{{"rect", RectJson(p.rect)},
                {"label", p.label == perception::Label::kFree ? "free" : "obstacle"}};
  });
  json["negative_experience"] = List(forbidden, [](const std::pair<int, int>& d) {
    return Json::array({d.first, d.second});
  });
  json["graph"]["nodes"] = List(map.graph.nodes, [](int node) { return Json(node); });
  json["graph"]["arcs"] = List(map.graph.arcs, [](const perception::Adjacency& a) {
    return Json{{"a", a.a}, {"b", a.b}, {"door", Json::array({Point(a.door_a), Point(a.door_b)})}};
  });
  return json;
}

std::string CognitiveMapToJson(const perception::CognitiveMap& map) {
  return sim::WriteJson(CognitiveMapJson(map), {.fixed_decimals = 4});
}

}  // namespace plywood::eval
