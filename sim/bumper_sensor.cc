#include "sim/bumper_sensor.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/scene.h"

namespace plywood::sim {

void BumperSensorOptions::Validate() const {
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0) {
    throw std::invalid_argument("rate_hz: must be a finite number > 0, got " +
                                std::to_string(rate_hz));
  }
}

BumperSensor::BumperSensor(const Scene& scene, const BumperSensorOptions& options)
    : options_(options) {
  options_.Validate();
  const mjModel* m = scene.model();
  panel_of_geom_.assign(m->ngeom, -1);
  for (int i = 0;; ++i) {
    const int id = mj_name2id(m, mjOBJ_GEOM, ("bumper_" + std::to_string(i)).c_str());
    if (id < 0) break;
    panel_of_geom_[id] = i;
    panel_geoms_.push_back(id);
  }
}

msgs::Bumpers BumperSensor::Sample(const Scene& scene) const {
  msgs::Bumpers out;
  out.time_s = scene.time_s();
  out.pressed.assign(panel_geoms_.size(), false);
  const mjData* d = scene.data();
  for (int c = 0; c < d->ncon; ++c) {
    const mjContact& contact = d->contact[c];
    // Contacts inside a geom margin are not touching yet.
    if (contact.dist > 0.0) continue;
    const int panel1 = panel_of_geom_[contact.geom1], panel2 = panel_of_geom_[contact.geom2];
    if (panel1 >= 0 && !scene.IsRobotGeom(contact.geom2)) out.pressed[panel1] = true;
    if (panel2 >= 0 && !scene.IsRobotGeom(contact.geom1)) out.pressed[panel2] = true;
  }
  return out;
}

}  // namespace plywood::sim
