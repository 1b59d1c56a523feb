#include "sim/world/robot_changed_by_world.h"

#include <vector>

#include "sim/world/model_field_comparison.h"

namespace plywood::sim {

std::optional<std::string> RobotChangedByWorld(const mjModel* scene, const mjModel* alone) {
  const int base_s = mj_name2id(scene, mjOBJ_BODY, "base");
  const int base_a = mj_name2id(alone, mjOBJ_BODY, "base");
  if (base_s < 0 || base_a < 0) return std::nullopt;  // the scene's own checks name what is missing

  // MuJoCo numbers bodies depth first, so a subtree's bodies are consecutive.
  const auto subtree_end = [](const mjModel* m, int root) {
    int end = root + 1;
    while (end < m->nbody && m->body_rootid[end] == root) ++end;
    return end;
  };
  const int end_s = subtree_end(scene, base_s);
  const int end_a = subtree_end(alone, base_a);
  const std::string hint =
      " (a <compiler> or <default> setting of the world applies to the robot's file too: remove "
      "it; worlds/README.md)";
  const auto count_problem = [&](const std::string& what, std::size_t in_scene,
                                 std::size_t in_alone) -> std::optional<std::string> {
    if (in_scene == in_alone) return std::nullopt;
    return "it changes the robot: " + std::to_string(in_scene) + " " + what + " in this world, " +
           std::to_string(in_alone) + " in the robot's file alone" + hint;
  };
  if (auto p = count_problem("bodies", end_s - base_s, end_a - base_a)) return p;

  ModelFieldComparison c(alone, "in this world", "in the robot's file alone", " of the robot");
  for (int i = 0; i < end_a - base_a && !c.problem(); ++i) {
    const int s = base_s + i, a = base_a + i;
    c.Object(mjOBJ_BODY, "body", s, a);
    c.Field("pos", scene->body_pos, alone->body_pos, 3);
    c.Field("quat", scene->body_quat, alone->body_quat, 4);
    c.Field("ipos", scene->body_ipos, alone->body_ipos, 3);
    c.Field("iquat", scene->body_iquat, alone->body_iquat, 4);
    c.Field("mass", scene->body_mass, alone->body_mass, 1);
    c.Field("inertia", scene->body_inertia, alone->body_inertia, 3);
  }

  const std::vector<int> geoms_s = IdsOnBodies(scene->geom_bodyid, scene->ngeom, base_s, end_s);
  const std::vector<int> geoms_a = IdsOnBodies(alone->geom_bodyid, alone->ngeom, base_a, end_a);
  if (auto p = count_problem("geoms", geoms_s.size(), geoms_a.size())) return p;
  for (std::size_t i = 0; i < geoms_a.size() && !c.problem(); ++i) {
    c.Object(mjOBJ_GEOM, "geom", geoms_s[i], geoms_a[i]);
    c.Field("type", scene->geom_type, alone->geom_type, 1);
    c.Field("contype", scene->geom_contype, alone->geom_contype, 1);
    c.Field("conaffinity", scene->geom_conaffinity, alone->geom_conaffinity, 1);
    c.Field("condim", scene->geom_condim, alone->geom_condim, 1);
    c.Field("group", scene->geom_group, alone->geom_group, 1);
    c.Field("priority", scene->geom_priority, alone->geom_priority, 1);
    c.Field("size", scene->geom_size, alone->geom_size, 3);
    c.Field("pos", scene->geom_pos, alone->geom_pos, 3);
    c.Field("quat", scene->geom_quat, alone->geom_quat, 4);
    c.Field("friction", scene->geom_friction, alone->geom_friction, 3);
    c.Field("solmix", scene->geom_solmix, alone->geom_solmix, 1);
    c.Field("solref", scene->geom_solref, alone->geom_solref, mjNREF);
    c.Field("solimp", scene->geom_solimp, alone->geom_solimp, mjNIMP);
    c.Field("margin", scene->geom_margin, alone->geom_margin, 1);
    c.Field("gap", scene->geom_gap, alone->geom_gap, 1);
  }

  const std::vector<int> sites_s = IdsOnBodies(scene->site_bodyid, scene->nsite, base_s, end_s);
  const std::vector<int> sites_a = IdsOnBodies(alone->site_bodyid, alone->nsite, base_a, end_a);
  if (auto p = count_problem("sites", sites_s.size(), sites_a.size())) return p;
  for (std::size_t i = 0; i < sites_a.size() && !c.problem(); ++i) {
    c.Object(mjOBJ_SITE, "site", sites_s[i], sites_a[i]);
    c.Field("pos", scene->site_pos, alone->site_pos, 3);
    c.Field("quat", scene->site_quat, alone->site_quat, 4);
  }

  const std::vector<int> joints_s = IdsOnBodies(scene->jnt_bodyid, scene->njnt, base_s, end_s);
  const std::vector<int> joints_a = IdsOnBodies(alone->jnt_bodyid, alone->njnt, base_a, end_a);
  if (auto p = count_problem("joints", joints_s.size(), joints_a.size())) return p;
  for (std::size_t i = 0; i < joints_a.size() && !c.problem(); ++i) {
    c.Object(mjOBJ_JOINT, "joint", joints_s[i], joints_a[i]);
    c.Field("type", scene->jnt_type, alone->jnt_type, 1);
    c.Field("pos", scene->jnt_pos, alone->jnt_pos, 3);
    c.Field("axis", scene->jnt_axis, alone->jnt_axis, 3);
    c.Field("limited", scene->jnt_limited, alone->jnt_limited, 1);
    c.Field("range", scene->jnt_range, alone->jnt_range, 2);
    c.Field("stiffness", scene->jnt_stiffness, alone->jnt_stiffness, 1);
    c.Field("margin", scene->jnt_margin, alone->jnt_margin, 1);
  }
  const std::vector<int> dofs_s = IdsOnBodies(scene->dof_bodyid, scene->nv, base_s, end_s);
  const std::vector<int> dofs_a = IdsOnBodies(alone->dof_bodyid, alone->nv, base_a, end_a);
  if (auto p = count_problem("degrees of freedom", dofs_s.size(), dofs_a.size())) return p;
  for (std::size_t i = 0; i < dofs_a.size() && !c.problem(); ++i) {
    c.Object(mjOBJ_JOINT, "joint", dofs_s[i], dofs_a[i], alone->dof_jntid[dofs_a[i]]);
    c.Field("damping", scene->dof_damping, alone->dof_damping, 1);
    c.Field("armature", scene->dof_armature, alone->dof_armature, 1);
    c.Field("frictionloss", scene->dof_frictionloss, alone->dof_frictionloss, 1);
  }

  // Worlds hold no joints, so every actuator, equality and tendon acts on the robot.
  const auto added = [&](const std::string& what, int in_scene,
                         int in_alone) -> std::optional<std::string> {
    if (in_scene == in_alone) return std::nullopt;
    return "it gives the robot " + std::to_string(in_scene) + " " + what + ", its file " +
           std::to_string(in_alone) + ": a world is static geometry only (worlds/README.md)";
  };
  if (auto p = added("actuators", scene->nu, alone->nu)) return p;
  for (int i = 0; i < alone->nu && !c.problem(); ++i) {
    c.Object(mjOBJ_ACTUATOR, "actuator", i + scene->nu - alone->nu, i);
    c.Field("gear", scene->actuator_gear, alone->actuator_gear, 6);
    c.Field("gainprm", scene->actuator_gainprm, alone->actuator_gainprm, mjNGAIN);
    c.Field("biasprm", scene->actuator_biasprm, alone->actuator_biasprm, mjNBIAS);
    c.Field("ctrllimited", scene->actuator_ctrllimited, alone->actuator_ctrllimited, 1);
    c.Field("ctrlrange", scene->actuator_ctrlrange, alone->actuator_ctrlrange, 2);
    c.Field("forcelimited", scene->actuator_forcelimited, alone->actuator_forcelimited, 1);
    c.Field("forcerange", scene->actuator_forcerange, alone->actuator_forcerange, 2);
  }
  if (c.problem()) return "it changes the robot: " + *c.problem() + hint;
  // Contact pairs and exclusions between the robot and the world: a world's <exclude body1="world"
  // body2="left_wheel"/> dropped the wheel through the floor (drift 80 %, exit 0). Pairs between
  // two of the robot's geoms are left alone (the scene adds placeholders of its own).
  // Signatures are (body1 + 1) << 16 + body2 + 1.
  const auto touching_the_world = [](const int* signature, int n, int base, int end) {
    const auto on_robot = [&](int body) { return body >= base && body < end; };
    int count = 0;
    for (int i = 0; i < n; ++i) {
      if (on_robot((signature[i] >> 16) - 1) != on_robot((signature[i] & 0xFFFF) - 1)) ++count;
    }
    return count;
  };
  if (auto p =
          added("contact exclusions with the world",
                touching_the_world(scene->exclude_signature, scene->nexclude, base_s, end_s),
                touching_the_world(alone->exclude_signature, alone->nexclude, base_a, end_a))) {
    return p;
  }
  if (auto p = added("contact pairs with the world",
                     touching_the_world(scene->pair_signature, scene->npair, base_s, end_s),
                     touching_the_world(alone->pair_signature, alone->npair, base_a, end_a))) {
    return p;
  }
  if (auto p = added("equality constraints", scene->neq, alone->neq)) return p;
  if (auto p = added("tendons", scene->ntendon, alone->ntendon)) return p;
  return std::nullopt;
}

}  // namespace plywood::sim
