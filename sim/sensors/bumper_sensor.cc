#include "sim/sensors/bumper_sensor.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "msgs/shortest_number.h"
#include "sim/config/config_error.h"
#include "sim/world/scene.h"

namespace plywood::sim {
namespace {

// Bearing of world point `p_W` in the frame of body `body` (planar part: atan2(y, x)).
double BearingInBody(const mjData* d, int body, const mjtNum* p_W) {
  const mjtNum* o = d->xpos + 3 * body;
  const mjtNum* r = d->xmat + 9 * body;  // row-major: columns are the body's axes
  const mjtNum delta[3] = {p_W[0] - o[0], p_W[1] - o[1], p_W[2] - o[2]};
  const double x = delta[0] * r[0] + delta[1] * r[3] + delta[2] * r[6];
  const double y = delta[0] * r[1] + delta[1] * r[4] + delta[2] * r[7];
  return std::atan2(y, x);
}

// A geom MuJoCo may make contacts with (a visual geom has contype and conaffinity 0).
bool CanTouch(const mjModel* m, int geom) {
  return geom >= 0 && (m->geom_contype[geom] != 0 || m->geom_conaffinity[geom] != 0);
}

// |a - b| on the circle, in [0, pi].
double AngularDistance(double a, double b) {
  return std::abs(std::remainder(a - b, 2.0 * std::numbers::pi));
}

}  // namespace

void BumperSensorOptions::Validate() const {
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0) {
    throw std::invalid_argument("rate_hz: must be a finite number > 0, got " +
                                msgs::ShortestNumber(rate_hz));
  }
}

BumperSensor::BumperSensor(const Scene& scene, const BumperSensorOptions& options)
    : options_(options) {
  options_.Validate();
  const mjModel* m = scene.model();
  const mjData* d = scene.data();  // forwarded by Scene: geom and body poses are current
  panel_of_geom_.assign(m->ngeom, -1);
  for (int i = 0;; ++i) {
    const int id = mj_name2id(m, mjOBJ_GEOM, ("bumper_" + std::to_string(i)).c_str());
    if (id < 0) break;
    panel_of_geom_[id] = i;
    panel_bearings_rad_.push_back(BearingInBody(d, scene.base_body_id(), d->geom_xpos + 3 * id));
  }
  // Without panels, or with nothing that a contact can press (no colliding ring, visual panels),
  // every sample would read "not pressed" while the chassis pushed a wall.
  if (panel_bearings_rad_.empty()) {
    throw ConfigError(scene.robot_path().string(), "bumper_0",
                      "no such geom on the robot; the bumpers need their panels bumper_0..N "
                      "(models/README.md)");
  }
  ring_geom_ = mj_name2id(m, mjOBJ_GEOM, "bumper_ring");
  bool touchable = CanTouch(m, ring_geom_);
  for (int g = 0; g < m->ngeom; ++g)
    touchable = touchable || (panel_of_geom_[g] >= 0 && CanTouch(m, g));
  if (!touchable) {
    throw ConfigError(scene.robot_path().string(), "bumper_ring",
                      std::string(ring_geom_ < 0 ? "no such geom on the robot"
                                                 : "the geom collides with nothing") +
                          ", and the panels bumper_0.." + std::to_string(panel_count() - 1) +
                          " are visual (contype and conaffinity 0): no contact can press a "
                          "panel; the bumpers need a colliding bumper_ring or colliding panels");
  }
}

int BumperSensor::PanelAtBearing(double bearing_rad) const {
  int best = -1;
  double best_distance = 0.0;
  for (int i = 0; i < panel_count(); ++i) {
    const double distance = AngularDistance(bearing_rad, panel_bearings_rad_[i]);
    if (best < 0 || distance < best_distance) {
      best = i;
      best_distance = distance;
    }
  }
  return best;
}

msgs::Bumpers BumperSensor::Sample(const Scene& scene) const {
  msgs::Bumpers out;
  out.time_s = scene.time_s();
  out.pressed.assign(panel_bearings_rad_.size(), false);
  if (scene.drive() == DriveMode::kPlanar) {
    if (panel_count() == 0) return out;
    for (const double bearing : scene.PlanarContactBearings()) {
      out.pressed[PanelAtBearing(bearing)] = true;
    }
    return out;
  }
  const mjData* d = scene.stepped_data();  // contacts and the base body only
  for (int c = 0; c < d->ncon; ++c) {
    const mjContact& contact = d->contact[c];
    // Contacts inside a geom margin are not touching yet.
    if (contact.dist > 0.0) continue;
    for (const auto& [own, other] :
         {std::pair{contact.geom1, contact.geom2}, std::pair{contact.geom2, contact.geom1}}) {
      if (scene.IsRobotGeom(other)) continue;
      if (own == ring_geom_) {
        // After mj_step, xpos/xmat and the contacts both describe the start of the step.
        out.pressed[PanelAtBearing(BearingInBody(d, scene.base_body_id(), contact.pos))] = true;
      } else if (panel_of_geom_[own] >= 0) {
        out.pressed[panel_of_geom_[own]] = true;
      }
    }
  }
  return out;
}

}  // namespace plywood::sim
