#include "viewer/run_maps_file.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "sim/config/config_error.h"
#include "sim/runner/format_number.h"

namespace plywood::viewer {
namespace {

using Json = nlohmann::json;

Json ReadJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw sim::ConfigError(path.string(), "", "cannot be read");
  try {
    return Json::parse(in);
  } catch (const Json::parse_error& e) {
    throw sim::ConfigError(path.string(), "", std::string("not JSON: ") + e.what());
  }
}

// Beyond it no map is of a room (trajectory files take the same bound); a pseudo segment 1e300 m
// long hung the replay (s63).
constexpr double kMaxCoordinateM = 1e9;

// A coordinate at `value`: a finite number within kMaxCoordinateM of the origin, else an error
// naming `field`.
double Number(const Json& value, const std::filesystem::path& path, const std::string& field) {
  if (!value.is_number() || !std::isfinite(value.get<double>())) {
    throw sim::ConfigError(path.string(), field, "must be a finite number");
  }
  const double v = value.get<double>();
  if (!(std::abs(v) <= kMaxCoordinateM)) {
    throw sim::ConfigError(path.string(), field,
                           "must be within " + sim::FormatNumber(kMaxCoordinateM) +
                               " m of the origin, got " + sim::FormatNumber(v));
  }
  return v;
}

// [x, y] at `value`.
Eigen::Vector2d Point(const Json& value, const std::filesystem::path& path,
                      const std::string& field) {
  if (!value.is_array() || value.size() != 2) {
    throw sim::ConfigError(path.string(), field, "must be a point [x, y]");
  }
  return {Number(value[0], path, field), Number(value[1], path, field)};
}

const Json& Member(const Json& object, const char* key, const std::filesystem::path& path,
                   const std::string& field) {
  if (!object.is_object() || !object.contains(key)) {
    throw sim::ConfigError(path.string(), field.empty() ? key : field + "." + key, "is missing");
  }
  return object.at(key);
}

const Json& Array(const Json& object, const char* key, const std::filesystem::path& path) {
  const Json& value = Member(object, key, path, "");
  if (!value.is_array()) throw sim::ConfigError(path.string(), key, "must be a list");
  return value;
}

}  // namespace

MapView ReadCognitiveMapFile(const std::filesystem::path& path) {
  const Json root = ReadJson(path);
  MapView view;
  const Json& partitions = Array(root, "partitions", path);
  for (std::size_t i = 0; i < partitions.size(); ++i) {
    const std::string field = "partitions[" + std::to_string(i) + "]";
    const Json& rect = Member(partitions[i], "rect", path, field);
    if (!rect.is_array() || rect.size() != 4) {
      throw sim::ConfigError(path.string(), field + ".rect", "must be [x0, y0, x1, y1]");
    }
    const Json& label = Member(partitions[i], "label", path, field);
    if (!label.is_string()) throw sim::ConfigError(path.string(), field + ".label", "not a string");
    view.partitions.push_back({{Number(rect[0], path, field), Number(rect[1], path, field)},
                               {Number(rect[2], path, field), Number(rect[3], path, field)},
                               label.get<std::string>() == "free"});
  }
  const Json& arcs = Array(Member(root, "graph", path, ""), "arcs", path);
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    const std::string field = "graph.arcs[" + std::to_string(i) + "]";
    const Json& door = Member(arcs[i], "door", path, field);
    if (!door.is_array() || door.size() != 2) {
      throw sim::ConfigError(path.string(), field + ".door", "must be two points");
    }
    const Eigen::Vector2d door_centre =
        0.5 * (Point(door[0], path, field + ".door") + Point(door[1], path, field + ".door"));
    for (const char* end : {"a", "b"}) {
      const Json& index = Member(arcs[i], end, path, field);
      if (!index.is_number_integer() || index.get<long>() < 0 ||
          index.get<std::size_t>() >= view.partitions.size()) {
        throw sim::ConfigError(path.string(), field + "." + end, "is not a partition's index");
      }
    }
    const auto centre = [&](const char* end) {
      const MapView::Box& box = view.partitions[arcs[i][end].get<std::size_t>()];
      return Eigen::Vector2d(0.5 * (box.min_W + box.max_W));
    };
    view.graph_arcs.emplace_back(centre("a"), door_centre);
    view.graph_arcs.emplace_back(door_centre, centre("b"));
  }
  return view;
}

GeometricMapView ReadGeometricMapFile(const std::filesystem::path& path) {
  const Json root = ReadJson(path);
  GeometricMapView view;
  const Json& segments = Array(root, "segments", path);
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::string field = "segments[" + std::to_string(i) + "]";
    const Json& tag = Member(segments[i], "tag", path, field);
    if (!tag.is_string()) throw sim::ConfigError(path.string(), field + ".tag", "not a string");
    const std::string kind = tag.get<std::string>();
    if (kind != "real" && kind != "pseudo" && kind != "unconfirmed") {
      throw sim::ConfigError(path.string(), field + ".tag",
                             "must be real, pseudo or unconfirmed, not '" + kind + "'");
    }
    if (kind == "unconfirmed") continue;
    view.segments.push_back(
        {Point(Member(segments[i], "start", path, field), path, field + ".start"),
         Point(Member(segments[i], "end", path, field), path, field + ".end"), kind == "pseudo"});
  }
  const Json& clusters = Array(root, "clusters", path);
  for (std::size_t i = 0; i < clusters.size(); ++i) {
    const std::string field = "clusters[" + std::to_string(i) + "]";
    view.clusters.emplace_back(
        Point(Member(clusters[i], "min", path, field), path, field + ".min"),
        Point(Member(clusters[i], "max", path, field), path, field + ".max"));
  }
  return view;
}

}  // namespace plywood::viewer
