#include "sim/world/world_changed_by_robot.h"

#include <vector>

#include "sim/world/model_field_comparison.h"

namespace plywood::sim {

std::optional<std::string> WorldChangedByRobot(const mjModel* scene, const mjModel* alone) {
  const std::string hint =
      " (a <compiler> or <default> setting of the robot's file applies to the world too: remove "
      "it; models/README.md)";
  if (scene->nbody < alone->nbody) return std::nullopt;  // not the world this scene was made of
  ModelFieldComparison c(alone, "with this robot", "in the world's file alone", "");
  for (int b = 1; b < alone->nbody && !c.problem(); ++b) {
    c.Object(mjOBJ_BODY, "body", b, b);
    c.Field("pos", scene->body_pos, alone->body_pos, 3);
    c.Field("quat", scene->body_quat, alone->body_quat, 4);
  }
  const std::vector<int> geoms_s = IdsOnBodies(scene->geom_bodyid, scene->ngeom, 0, alone->nbody);
  const std::vector<int> geoms_a = IdsOnBodies(alone->geom_bodyid, alone->ngeom, 0, alone->nbody);
  if (!c.problem() && geoms_s.size() != geoms_a.size()) {
    return std::to_string(geoms_s.size()) + " geoms with this robot, " +
           std::to_string(geoms_a.size()) + " in the world's file alone" + hint;
  }
  for (std::size_t i = 0; i < geoms_a.size() && !c.problem(); ++i) {
    c.Object(mjOBJ_GEOM, "geom", geoms_s[i], geoms_a[i]);
    c.Field("type", scene->geom_type, alone->geom_type, 1);
    c.Field("size", scene->geom_size, alone->geom_size, 3);
    c.Field("pos", scene->geom_pos, alone->geom_pos, 3);
    c.Field("quat", scene->geom_quat, alone->geom_quat, 4);
    c.Field("contype", scene->geom_contype, alone->geom_contype, 1);
    c.Field("conaffinity", scene->geom_conaffinity, alone->geom_conaffinity, 1);
    c.Field("group", scene->geom_group, alone->geom_group, 1);
    c.Field("priority", scene->geom_priority, alone->geom_priority, 1);
    c.Field("margin", scene->geom_margin, alone->geom_margin, 1);
    c.Field("gap", scene->geom_gap, alone->geom_gap, 1);
    c.Field("friction", scene->geom_friction, alone->geom_friction, 3);
    c.Field("rgba", scene->geom_rgba, alone->geom_rgba, 4);
  }
  if (c.problem()) return *c.problem() + hint;
  return std::nullopt;
}

}  // namespace plywood::sim
