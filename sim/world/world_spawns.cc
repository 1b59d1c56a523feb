#include "sim/world/world_spawns.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "msgs/shortest_number.h"

namespace plywood::sim {

std::optional<std::array<double, 3>> WorldSpawn(const mjModel* m, int k) {
  const int id = mj_name2id(m, mjOBJ_NUMERIC, ("spawn_" + std::to_string(k)).c_str());
  if (id < 0 || m->numeric_size[id] != 3) return std::nullopt;
  const mjtNum* v = m->numeric_data + m->numeric_adr[id];
  return std::array<double, 3>{v[0], v[1], v[2]};
}

std::optional<std::string> WorldSpawnProblem(const mjModel* m, int k) {
  const std::string name = "spawn_" + std::to_string(k);
  const int id = mj_name2id(m, mjOBJ_NUMERIC, name.c_str());
  if (id < 0) {
    // A spot marked the way MJCF marks spots (a site), or as custom text, is no spawn to the
    // readers: the robot started at the origin without a word.
    static constexpr std::pair<mjtObj, const char*> kLookAlikes[] = {
        {mjOBJ_SITE, "a <site>"}, {mjOBJ_BODY, "a <body>"},   {mjOBJ_GEOM, "a <geom>"},
        {mjOBJ_TEXT, "a <text>"}, {mjOBJ_TUPLE, "a <tuple>"},
    };
    for (const auto& [type, what] : kLookAlikes) {
      if (mj_name2id(m, type, name.c_str()) < 0) continue;
      return std::string("is ") + what +
             ", not a spawn: spawn poses are written <custom><numeric "
             "name=\"" +
             name + "\" data=\"x_m y_m yaw_deg\"/></custom> (worlds/README.md)";
    }
    return std::nullopt;
  }
  // A spawn of one or two numbers (data="-2") is malformed, not missing.
  if (m->numeric_size[id] != 3) {
    return "expected three numbers (x_m y_m theta_deg), got " + std::to_string(m->numeric_size[id]);
  }
  const mjtNum* v = m->numeric_data + m->numeric_adr[id];
  if (!std::all_of(v, v + 3, [](double x) { return std::isfinite(x); })) {
    return "expected three finite numbers (x_m y_m theta_deg), got " + msgs::ShortestNumber(v[0]) +
           " " + msgs::ShortestNumber(v[1]) + " " + msgs::ShortestNumber(v[2]);
  }
  if (!(std::abs(v[2]) <= kMaxSpawnTurnDeg)) {
    return "the heading must be in [-360, 360] deg (one turn either way holds every heading), "
           "got " +
           msgs::ShortestNumber(v[2]);
  }
  return std::nullopt;
}

}  // namespace plywood::sim
