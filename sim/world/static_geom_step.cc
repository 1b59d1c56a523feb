#include "sim/world/static_geom_step.h"

namespace plywood::sim {
namespace {

// mj_kinematics with its geom loop over the geoms after the world body's only, `unplaced` aside.
void KinematicsOfMovingGeoms(mjModel* m, mjData* d, int first_moving_geom,
                             std::span<const int> unplaced, bool skip_sites) {
  const int ngeom = m->ngeom, nsite = m->nsite;
  struct RestoreCounts {
    mjModel* m;
    int ngeom, nsite;
    ~RestoreCounts() {
      m->ngeom = ngeom;
      m->nsite = nsite;
    }
  } restore{m, ngeom, nsite};
  m->ngeom = 0;  // bodies as usual, no geoms
  if (skip_sites) m->nsite = 0;
  mj_kinematics(m, d);
  m->ngeom = ngeom;
  m->nsite = nsite;
  auto skip = unplaced.begin();
  for (int g = first_moving_geom; g < ngeom; ++g) {
    if (skip != unplaced.end() && *skip == g) {
      ++skip;
      continue;
    }
    mj_local2Global(d, d->geom_xpos + 3 * g, d->geom_xmat + 9 * g, m->geom_pos + 3 * g,
                    m->geom_quat + 4 * g, m->geom_bodyid[g], m->geom_sameframe[g]);
  }
}

// mj_fwdPosition with the narrowed kinematics.
void PositionStage(mjModel* m, mjData* d, int first_moving_geom, std::span<const int> unplaced,
                   bool skip_sites) {
  KinematicsOfMovingGeoms(m, d, first_moving_geom, unplaced, skip_sites);
  mj_comPos(m, d);
  mj_camlight(m, d);
  mj_tendon(m, d);
  mj_transmission(m, d);
  mj_crb(m, d);
  mj_factorM(m, d);
  mj_collision(m, d);
  mj_makeConstraint(m, d);
  mj_projectConstraint(m, d);
}

int Resets(const mjData* d) {
  return d->warning[mjWARN_BADQPOS].number + d->warning[mjWARN_BADQVEL].number;
}

}  // namespace

void StepWithStaticWorldGeoms(mjModel* m, mjData* d) { StepWithStaticWorldGeoms(m, d, {}); }

bool StepWithStaticWorldGeoms(mjModel* m, mjData* d, std::span<const int> unplaced,
                              bool skip_sites) {
  // The world body's geoms come first in MuJoCo's geom order.
  const int static_geoms = m->body_geomadr[0] == 0 ? m->body_geomnum[0] : 0;
  if (static_geoms == 0 || m->opt.integrator != mjINT_EULER) {
    mj_step(m, d);
    return false;
  }
  // mj_step: check, forward, check, integrate; mj_forward: position stage, position sensors
  // and energy, then the rest (mj_forwardSkip from the velocity stage on).
  const int resets = Resets(d);
  mj_checkPos(m, d);
  mj_checkVel(m, d);
  const bool reset = Resets(d) != resets;
  if (reset) {
    mj_fwdPosition(m, d);  // a reset zeroed every pose, the static ones too
  } else {
    PositionStage(m, d, static_geoms, unplaced, skip_sites);
  }
  mj_sensorPos(m, d);
  if (mjENABLED(mjENBL_ENERGY)) mj_energyPos(m, d);
  mj_forwardSkip(m, d, mjSTAGE_POS, 0);
  const int bad_accelerations = d->warning[mjWARN_BADQACC].number;
  mj_checkAcc(m, d);
  mj_Euler(m, d);
  // After a reset the geoms hold what the reset left, as after mj_step.
  return !reset && d->warning[mjWARN_BADQACC].number == bad_accelerations &&
         (!unplaced.empty() || skip_sites);
}

}  // namespace plywood::sim
