#include "sim/world/finite_geometry.h"

#include <algorithm>
#include <cmath>

#include "msgs/shortest_number.h"

namespace plywood::sim {
namespace {

std::optional<std::string> Check(const mjModel* m, mjtObj type, int id, const char* field,
                                 const mjtNum* values, int n) {
  if (std::all_of(values, values + n, [](mjtNum v) { return std::isfinite(v); })) {
    return std::nullopt;
  }
  const char* name = mj_id2name(m, type, id);
  const std::string kind = type == mjOBJ_BODY ? "body" : "geom";
  std::string text = name ? kind + " '" + name + "'" : kind + " #" + std::to_string(id);
  text += std::string(": ") + field + " is not a finite number (";
  for (int i = 0; i < n; ++i) text += (i ? " " : "") + msgs::ShortestNumber(values[i]);
  return text + ")";
}

}  // namespace

std::optional<std::string> NonFiniteGeometry(const mjModel* m) {
  for (int b = 1; b < m->nbody; ++b) {  // body 0 is the world frame itself
    for (const auto& problem : {Check(m, mjOBJ_BODY, b, "pos", m->body_pos + 3 * b, 3),
                                Check(m, mjOBJ_BODY, b, "quat", m->body_quat + 4 * b, 4)}) {
      if (problem) return problem;
    }
  }
  for (int g = 0; g < m->ngeom; ++g) {
    for (const auto& problem : {Check(m, mjOBJ_GEOM, g, "pos", m->geom_pos + 3 * g, 3),
                                Check(m, mjOBJ_GEOM, g, "quat", m->geom_quat + 4 * g, 4),
                                Check(m, mjOBJ_GEOM, g, "size", m->geom_size + 3 * g, 3)}) {
      if (problem) return problem;
    }
  }
  return std::nullopt;
}

}  // namespace plywood::sim
