#include "tests/support/sensor_test_support.h"

#include <cmath>
#include <numbers>

#include "tests/support/mujoco_test_support.h"

namespace plywood::testing {

bool SegmentCaster::Cast(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W,
                         double max_range_m, sim::RayHit* hit) const {
  const Eigen::Vector2d o = origin_W.head<2>(), d = dir_W.head<2>();
  const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return u.x() * v.y() - u.y() * v.x();
  };
  bool found = false;
  for (const Segment& s : segments_) {
    const Eigen::Vector2d e = s.b - s.a, w = s.a - o;
    const double denom = cross(d, e);
    if (std::abs(denom) < 1e-15) continue;
    const double t = cross(w, e) / denom, u = cross(w, d) / denom;
    if (t <= 1e-12 || u < 0.0 || u > 1.0 || t > max_range_m) continue;
    if (found && t >= hit->distance_m) continue;
    found = true;
    Eigen::Vector2d n(-e.y(), e.x());
    n.normalize();
    if (n.dot(d) > 0.0) n = -n;
    hit->distance_m = t;
    hit->geom_id = s.geom_id;
    hit->normal_W = Eigen::Vector3d(n.x(), n.y(), 0.0);
  }
  return found;
}

Eigen::Vector2d ToWorld(const Eigen::Isometry3d& X_WS, double x, double y) {
  return (X_WS * Eigen::Vector3d(x, y, 0.0)).head<2>();
}

std::vector<Segment> RoomSegments(const Rectangle& r, int first_geom_id) {
  return {{{r.x_min, r.y_min}, {r.x_max, r.y_min}, first_geom_id},
          {{r.x_max, r.y_min}, {r.x_max, r.y_max}, first_geom_id + 1},
          {{r.x_max, r.y_max}, {r.x_min, r.y_max}, first_geom_id + 2},
          {{r.x_min, r.y_max}, {r.x_min, r.y_min}, first_geom_id + 3}};
}

std::pair<double, std::string> RoomRange(const Rectangle& r, double px, double py, double phi_rad) {
  const double c = std::cos(phi_rad), s = std::sin(phi_rad);
  std::pair<double, std::string> best{1e9, ""};
  const auto consider = [&](double t, const char* wall) {
    if (t > 0.0 && t < best.first) best = {t, wall};
  };
  if (c > 1e-12) consider((r.x_max - px) / c, "east");
  if (c < -1e-12) consider((r.x_min - px) / c, "west");
  if (s > 1e-12) consider((r.y_max - py) / s, "north");
  if (s < -1e-12) consider((r.y_min - py) / s, "south");
  return best;
}

std::filesystem::path FloorWorld(const std::string& name) {
  return WriteFile(MakeTempDir(name) / "floor.xml", R"(<mujoco>
  <worldbody><geom name="floor" type="plane" size="10 10 0.1"/></worldbody>
</mujoco>
)");
}

std::filesystem::path RoomWorld(const std::string& name, const Rectangle& r, double yaw_rad) {
  struct Wall {
    const char* name;
    double x, y, hx, hy;
  };
  const double cx = (r.x_min + r.x_max) / 2.0, cy = (r.y_min + r.y_max) / 2.0;
  // Half-lengths reach 0.2 m past the interior so the corners are closed.
  const double hx = (r.x_max - r.x_min) / 2.0 + 0.2, hy = (r.y_max - r.y_min) / 2.0 + 0.2;
  const Wall walls[] = {{"east", r.x_max + 0.05, cy, 0.05, hy},
                        {"west", r.x_min - 0.05, cy, 0.05, hy},
                        {"north", cx, r.y_max + 0.05, hx, 0.05},
                        {"south", cx, r.y_min - 0.05, hx, 0.05}};
  std::string xml =
      "<mujoco>\n  <worldbody>\n    <geom name=\"floor\" type=\"plane\" size=\"10 10 0.1\"/>\n";
  const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
  for (const Wall& w : walls) {
    xml += "    <geom name=\"" + std::string(w.name) + "\" type=\"box\" pos=\"" +
           std::to_string(c * w.x - s * w.y) + " " + std::to_string(s * w.x + c * w.y) +
           " 0.5\" size=\"" + std::to_string(w.hx) + " " + std::to_string(w.hy) +
           " 0.5\" euler=\"0 0 " + std::to_string(yaw_rad * 180.0 / std::numbers::pi) + "\"/>\n";
  }
  xml += "  </worldbody>\n</mujoco>\n";
  return WriteFile(MakeTempDir(name) / "room.xml", xml);
}

sim::SceneOptions RobotIn(const std::string& robot, const std::filesystem::path& world,
                          msgs::Pose2D spawn) {
  sim::SceneOptions options;
  options.world_mjcf = world;
  options.robot_mjcf = SourceRoot() / "models" / (robot + ".xml");
  options.spawn = spawn;
  return options;
}

}  // namespace plywood::testing
