#include "sim/sensors/sensor_sites.h"

#include <optional>
#include <stdexcept>

#include "sim/config/config_error.h"

namespace plywood::sim {

SensorSite RequireSensorSite(const Scene& scene, const std::string& site_name,
                             const std::string& sensor) {
  const std::optional<int> id = scene.FindSite(site_name);
  if (!id) {
    throw ConfigError(scene.robot_path().string(), site_name,
                      "no such site on the robot; " + sensor + " needs it");
  }
  if (!scene.SiteFixedToBase(*id)) {
    // A joint between the site and the base: its pose in the robot frame changes as it moves,
    // and every scan would be placed with the pose it had when the model was built.
    throw ConfigError(scene.robot_path().string(), site_name,
                      "the site is not fixed to the robot's base body (a joint lies between); " +
                          sensor + " needs a fixed mount");
  }
  return {*id, scene.SitePoseInRobot(*id)};
}

std::vector<SensorSite> RequireSensorSites(const Scene& scene,
                                           const std::vector<std::string>& site_names,
                                           const std::string& sensor) {
  if (site_names.empty()) throw std::invalid_argument("site_names: must not be empty");
  std::vector<SensorSite> sites;
  sites.reserve(site_names.size());
  for (const std::string& name : site_names)
    sites.push_back(RequireSensorSite(scene, name, sensor));
  return sites;
}

std::vector<std::string> NumberedSiteNames(const std::string& prefix, int count) {
  std::vector<std::string> names;
  names.reserve(count);
  for (int i = 0; i < count; ++i) names.push_back(prefix + std::to_string(i));
  return names;
}

}  // namespace plywood::sim
