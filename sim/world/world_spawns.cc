#include "sim/world/world_spawns.h"

#include <string>

namespace plywood::sim {

std::optional<std::array<double, 3>> WorldSpawn(const mjModel* m, int k) {
  const int id = mj_name2id(m, mjOBJ_NUMERIC, ("spawn_" + std::to_string(k)).c_str());
  if (id < 0 || m->numeric_size[id] != 3) return std::nullopt;
  const mjtNum* v = m->numeric_data + m->numeric_adr[id];
  return std::array<double, 3>{v[0], v[1], v[2]};
}

int WorldSpawnValueCount(const mjModel* m, int k) {
  const int id = mj_name2id(m, mjOBJ_NUMERIC, ("spawn_" + std::to_string(k)).c_str());
  return id < 0 ? -1 : m->numeric_size[id];
}

}  // namespace plywood::sim
