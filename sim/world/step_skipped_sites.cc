#include "sim/world/step_skipped_sites.h"

namespace plywood::sim {

bool StepCanSkipSites(const mjModel* m) {
  if (m->nsensor > 0 || m->ntendon > 0) return false;
  for (int a = 0; a < m->nu; ++a) {
    const int type = m->actuator_trntype[a];
    if (type != mjTRN_JOINT && type != mjTRN_JOINTINPARENT) return false;
  }
  return mjcb_control == nullptr && mjcb_passive == nullptr && mjcb_sensor == nullptr;
}

void PlaceSite(const mjModel* m, mjData* d, int site_id) {
  mj_local2Global(d, d->site_xpos + 3 * site_id, d->site_xmat + 9 * site_id,
                  m->site_pos + 3 * site_id, m->site_quat + 4 * site_id, m->site_bodyid[site_id],
                  m->site_sameframe[site_id]);
}

void PlaceSites(const mjModel* m, mjData* d) {
  for (int s = 0; s < m->nsite; ++s) PlaceSite(m, d, s);
}

}  // namespace plywood::sim
