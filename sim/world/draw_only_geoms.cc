#include "sim/world/draw_only_geoms.h"

namespace plywood::sim {

std::vector<int> DrawOnlyGeoms(const mjModel* m, int ray_skipped_group) {
  for (int s = 0; s < m->nsensor; ++s) {
    if (m->sensor_type[s] == mjSENS_RANGEFINDER) return {};
  }
  std::vector<bool> referenced(m->ngeom, false);
  for (int p = 0; p < m->npair; ++p) {
    referenced[m->pair_geom1[p]] = true;
    referenced[m->pair_geom2[p]] = true;
  }
  for (int s = 0; s < m->nsensor; ++s) {
    if (m->sensor_objtype[s] == mjOBJ_GEOM && m->sensor_objid[s] >= 0) {
      referenced[m->sensor_objid[s]] = true;
    }
    if (m->sensor_reftype[s] == mjOBJ_GEOM && m->sensor_refid[s] >= 0) {
      referenced[m->sensor_refid[s]] = true;
    }
  }
  for (int w = 0; w < m->nwrap; ++w) {
    if ((m->wrap_type[w] == mjWRAP_SPHERE || m->wrap_type[w] == mjWRAP_CYLINDER) &&
        m->wrap_objid[w] >= 0) {
      referenced[m->wrap_objid[w]] = true;
    }
  }
  std::vector<int> geoms;
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_bodyid[g] != 0 && m->geom_group[g] == ray_skipped_group &&
        m->geom_contype[g] == 0 && m->geom_conaffinity[g] == 0 && !referenced[g]) {
      geoms.push_back(g);
    }
  }
  return geoms;
}

void PlaceGeoms(const mjModel* m, mjData* d, std::span<const int> geoms) {
  for (const int g : geoms) {
    mj_local2Global(d, d->geom_xpos + 3 * g, d->geom_xmat + 9 * g, m->geom_pos + 3 * g,
                    m->geom_quat + 4 * g, m->geom_bodyid[g], m->geom_sameframe[g]);
  }
}

}  // namespace plywood::sim
