#pragma once

#include <string>
#include <vector>

#include "msgs/pose2d.h"
#include "sim/world/scene.h"

namespace plywood::sim {

// Where a sensor is mounted: a site on the robot's base body or on a body welded to it.
struct SensorSite {
  int id = -1;        // MuJoCo site id
  msgs::Pose2D X_RS;  // planar pose of the site S in the robot frame R
};

// Looks `site_name` up on the scene's robot; `sensor` names who needs it ("the laser"), whose
// beams reach `range_max_m` in the site's x-y plane.
// @throws ConfigError "<robot file>: <site_name>: no such site on the robot; <sensor> needs it",
// or naming the joint-mounted site ("not fixed to the robot's base body"), a site off the robot
// (beyond the box of its geoms' bounding spheres, or at or below the floor), or a scan plane so
// tilted that its beams drift further up or down within range_max_m than the site's height: the
// scans are logged and used as level (X_RS is planar), and such beams meet the floor. Also, naming
// the world file and the geom, a static world geom that spans the site's height with its underside
// above the robot's colliding geoms under the site: the robot can drive under it, site inside.
SensorSite RequireSensorSite(const Scene& scene, const std::string& site_name,
                             const std::string& sensor, double range_max_m);

// RequireSensorSite for every name, in order.
// @throws std::invalid_argument for an empty `site_names`; ConfigError for the first bad site.
std::vector<SensorSite> RequireSensorSites(const Scene& scene,
                                           const std::vector<std::string>& site_names,
                                           const std::string& sensor, double range_max_m);

// prefix + "0" .. prefix + (count - 1): a ring's default sites ("sonar_0" .. "sonar_15").
std::vector<std::string> NumberedSiteNames(const std::string& prefix, int count);

}  // namespace plywood::sim
