#include "sim/world/generator/generated_world.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "msgs/angle_units.h"

namespace plywood::sim::worldgen {
namespace {

using Eigen::Vector2d;

// Into (-180, 180].
double WrapDegrees(double deg) {
  double wrapped = std::fmod(deg, 360.0);
  if (wrapped <= -180.0) wrapped += 360.0;
  if (wrapped > 180.0) wrapped -= 360.0;
  return wrapped;
}

}  // namespace

Footprint WorldGeom::footprint() const {
  if (shape == Shape::kCylinder) return Footprint::Disc(centre, radius_m);
  return Footprint::Box(centre, half_size, yaw_deg * kDegToRad);
}

std::string JsonNumber(double value) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.6f", value);
  std::string s = text;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

std::string JsonString(const std::string& value) {
  std::string s = "\"";
  for (const char c : value) {
    if (c == '"' || c == '\\') s += '\\';
    s += c;
  }
  return s + "\"";
}

std::string JsonArray(const std::vector<std::string>& items) {
  std::string s = "[";
  for (size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + items[i];
  return s + "]";
}

std::string JsonNumbers(const std::vector<double>& values) {
  std::vector<std::string> items;
  for (const double v : values) items.push_back(JsonNumber(v));
  return JsonArray(items);
}

std::string JsonObject(const std::vector<WorldParameter>& members) {
  std::string s = "{";
  for (size_t i = 0; i < members.size(); ++i) {
    s += (i ? ", " : "") + JsonString(members[i].key) + ": " + members[i].json;
  }
  return s + "}";
}

std::string GeneratedWorld::Name() const {
  char index_text[16];
  std::snprintf(index_text, sizeof(index_text), "%05d", index);
  return family + "_s" + std::to_string(seed) + "_" + index_text;
}

void GeneratedWorld::AddParameter(const std::string& key, double value) {
  parameters.push_back({key, JsonNumber(value)});
}

void GeneratedWorld::AddParameter(const std::string& key, const std::string& json_text) {
  parameters.push_back({key, json_text});
}

int GeneratedWorld::NextNumber(const std::string& kind) {
  for (auto& [name, count] : counters_) {
    if (name == kind) return count++;
  }
  counters_.emplace_back(kind, 1);
  return 0;
}

WorldGeom& GeneratedWorld::AddWallBox(const Vector2d& centre, double half_length_m,
                                      double yaw_deg) {
  return AddBox("wall", "wall", centre, {half_length_m, kWallThicknessM / 2}, yaw_deg,
                kWallHeightM);
}

WorldGeom& GeneratedWorld::AddBox(const std::string& kind, const std::string& geom_class,
                                  const Vector2d& centre, const Vector2d& half_size, double yaw_deg,
                                  double height_m) {
  WorldGeom g;
  g.shape = WorldGeom::Shape::kBox;
  g.name = kind + "_" + std::to_string(NextNumber(kind));
  g.geom_class = geom_class;
  g.centre = centre;
  g.half_size = half_size;
  g.yaw_deg = WrapDegrees(yaw_deg);
  g.z_min_m = 0.0;
  g.z_max_m = height_m;
  geoms.push_back(g);
  return geoms.back();
}

WorldGeom& GeneratedWorld::AddCylinder(const std::string& kind, const std::string& geom_class,
                                       const Vector2d& centre, double radius_m, double height_m) {
  WorldGeom g;
  g.shape = WorldGeom::Shape::kCylinder;
  g.name = kind + "_" + std::to_string(NextNumber(kind));
  g.geom_class = geom_class;
  g.centre = centre;
  g.radius_m = radius_m;
  g.z_min_m = 0.0;
  g.z_max_m = height_m;
  geoms.push_back(g);
  return geoms.back();
}

Footprint GeneratedWorld::AddTable(const Vector2d& centre, const Vector2d& half_size,
                                   double yaw_deg, double height_m, double leg_radius_m,
                                   double leg_inset_m) {
  constexpr double kTopThicknessM = 0.03;
  const std::string name = "table_" + std::to_string(NextNumber("table"));
  WorldGeom top;
  top.shape = WorldGeom::Shape::kBox;
  top.name = name + "_top";
  top.geom_class = "table_top";
  top.centre = centre;
  top.half_size = half_size;
  top.yaw_deg = WrapDegrees(yaw_deg);
  top.z_min_m = height_m - kTopThicknessM;
  top.z_max_m = height_m;
  geoms.push_back(top);
  const double c = std::cos(yaw_deg * kDegToRad), s = std::sin(yaw_deg * kDegToRad);
  const Vector2d leg_half = half_size - Vector2d::Constant(leg_inset_m + leg_radius_m);
  int k = 0;
  for (const double sx : {1.0, -1.0}) {
    for (const double sy : {1.0, -1.0}) {
      const Vector2d local(sx * leg_half.x(), sy * leg_half.y());
      WorldGeom leg;
      leg.shape = WorldGeom::Shape::kCylinder;
      leg.name = name + "_leg_" + std::to_string(k++);
      leg.geom_class = "table_leg";
      leg.centre = centre + Vector2d(c * local.x() - s * local.y(), s * local.x() + c * local.y());
      leg.radius_m = leg_radius_m;
      leg.z_min_m = 0.0;
      leg.z_max_m = height_m - kTopThicknessM;
      geoms.push_back(leg);
    }
  }
  return top.footprint();
}

std::vector<Footprint> GeneratedWorld::Footprints() const {
  std::vector<Footprint> out;
  for (const WorldGeom& g : geoms) out.push_back(g.footprint());
  return out;
}

std::vector<Footprint> GeneratedWorld::FootprintsAtHeight(double height_m) const {
  std::vector<Footprint> out;
  for (const WorldGeom& g : geoms) {
    if (g.z_min_m <= height_m && height_m <= g.z_max_m) out.push_back(g.footprint());
  }
  return out;
}

void GeneratedWorld::Transform(double rotation, const Vector2d& shift) {
  const double c = std::cos(rotation * kDegToRad), s = std::sin(rotation * kDegToRad);
  auto move = [&](const Vector2d& p) {
    return Vector2d(c * p.x() - s * p.y() + shift.x(), s * p.x() + c * p.y() + shift.y());
  };
  for (WorldGeom& g : geoms) {
    g.centre = move(g.centre);
    g.yaw_deg = WrapDegrees(g.yaw_deg + rotation);
  }
  for (auto& outline : interiors) {
    for (Vector2d& p : outline) p = move(p);
  }
  for (SpawnPose& spawn : spawns) {
    const Vector2d p = move({spawn.x_m, spawn.y_m});
    spawn = {p.x(), p.y(), WrapDegrees(spawn.yaw_deg + rotation)};
  }
  // Compose with what was applied before: world = R2 (R1 local + t1) + t2.
  translation = move(translation);
  rotation_deg = WrapDegrees(rotation_deg + rotation);
}

}  // namespace plywood::sim::worldgen
