#include "sim/world/world_changed_by_robot.h"

#include <algorithm>
#include <vector>

#include "msgs/shortest_number.h"

namespace plywood::sim {
namespace {

template <typename T>
std::string WorldFieldValues(const T* v, int n) {
  std::string text;
  for (int i = 0; i < n; ++i) text += (i ? " " : "") + msgs::ShortestNumber(double(v[i]));
  return text;
}

// The ids of the geoms on the bodies [0, end_body), in order.
std::vector<int> GeomsOnBodies(const mjModel* m, int end_body) {
  std::vector<int> ids;
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_bodyid[g] < end_body) ids.push_back(g);
  }
  return ids;
}

}  // namespace

std::optional<std::string> WorldChangedByRobot(const mjModel* scene, const mjModel* alone) {
  const std::string hint =
      " (a <compiler> or <default> setting of the robot's file applies to the world too: remove "
      "it; models/README.md)";
  if (scene->nbody < alone->nbody) return std::nullopt;  // not the world this scene was made of
  std::optional<std::string> problem;
  const auto field = [&](mjtObj type, const char* kind, int s, int a, const char* name,
                         const auto* in_scene, const auto* in_alone, int n) {
    if (problem) return;
    const auto* x = in_scene + static_cast<long>(n) * s;
    const auto* y = in_alone + static_cast<long>(n) * a;
    if (std::equal(x, x + n, y)) return;
    const char* object_name = mj_id2name(alone, type, a);
    const std::string object = object_name
                                   ? std::string(kind) + " '" + object_name + "'"
                                   : "unnamed " + std::string(kind) + " #" + std::to_string(a);
    problem = object + ": " + name + " is " + WorldFieldValues(x, n) + " with this robot, " +
              WorldFieldValues(y, n) + " in the world's file alone" + hint;
  };
  for (int b = 1; b < alone->nbody && !problem; ++b) {
    field(mjOBJ_BODY, "body", b, b, "pos", scene->body_pos, alone->body_pos, 3);
    field(mjOBJ_BODY, "body", b, b, "quat", scene->body_quat, alone->body_quat, 4);
  }
  const std::vector<int> geoms_s = GeomsOnBodies(scene, alone->nbody);
  const std::vector<int> geoms_a = GeomsOnBodies(alone, alone->nbody);
  if (!problem && geoms_s.size() != geoms_a.size()) {
    return std::to_string(geoms_s.size()) + " geoms with this robot, " +
           std::to_string(geoms_a.size()) + " in the world's file alone" + hint;
  }
  for (std::size_t i = 0; i < geoms_a.size() && !problem; ++i) {
    const int s = geoms_s[i], a = geoms_a[i];
    field(mjOBJ_GEOM, "geom", s, a, "type", scene->geom_type, alone->geom_type, 1);
    field(mjOBJ_GEOM, "geom", s, a, "size", scene->geom_size, alone->geom_size, 3);
    field(mjOBJ_GEOM, "geom", s, a, "pos", scene->geom_pos, alone->geom_pos, 3);
    field(mjOBJ_GEOM, "geom", s, a, "quat", scene->geom_quat, alone->geom_quat, 4);
    field(mjOBJ_GEOM, "geom", s, a, "contype", scene->geom_contype, alone->geom_contype, 1);
    field(mjOBJ_GEOM, "geom", s, a, "conaffinity", scene->geom_conaffinity, alone->geom_conaffinity,
          1);
    field(mjOBJ_GEOM, "geom", s, a, "group", scene->geom_group, alone->geom_group, 1);
    field(mjOBJ_GEOM, "geom", s, a, "priority", scene->geom_priority, alone->geom_priority, 1);
    field(mjOBJ_GEOM, "geom", s, a, "margin", scene->geom_margin, alone->geom_margin, 1);
    field(mjOBJ_GEOM, "geom", s, a, "gap", scene->geom_gap, alone->geom_gap, 1);
    field(mjOBJ_GEOM, "geom", s, a, "friction", scene->geom_friction, alone->geom_friction, 3);
    field(mjOBJ_GEOM, "geom", s, a, "rgba", scene->geom_rgba, alone->geom_rgba, 4);
  }
  return problem;
}

}  // namespace plywood::sim
