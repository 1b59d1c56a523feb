#include "render/geom_footprint.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace plywood::render {
namespace {

constexpr int kCircleSamples = 24;

Eigen::Quaterniond Quat(const mjtNum* q) { return Eigen::Quaterniond(q[0], q[1], q[2], q[3]); }

Eigen::Isometry3d Pose(const mjtNum* pos, const mjtNum* quat) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Quat(quat).normalized().toRotationMatrix();
  X.translation() = Eigen::Vector3d(pos[0], pos[1], pos[2]);
  return X;
}

// Andrew's monotone chain; returns the hull counter-clockwise without repeating the first point.
std::vector<Eigen::Vector2d> ConvexHull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (points.size() < 3) return points;
  const auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i > 0; --i) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0) --k;
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

Rgb ColourOf(const mjModel* m, int g) {
  const float* rgba =
      m->geom_matid[g] >= 0 ? m->mat_rgba + 4 * m->geom_matid[g] : m->geom_rgba + 4 * g;
  const auto channel = [](float v) {
    return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(v, 0.0f, 1.0f)));
  };
  return {channel(rgba[0]), channel(rgba[1]), channel(rgba[2])};
}

float AlphaOf(const mjModel* m, int g) {
  return m->geom_matid[g] >= 0 ? m->mat_rgba[4 * m->geom_matid[g] + 3] : m->geom_rgba[4 * g + 3];
}

// Points on a horizontal circle of `radius` about `centre` (the outline of a sphere seen from
// above).
void AddHorizontalCircle(const Eigen::Vector3d& centre, double radius,
                         std::vector<Eigen::Vector3d>& points) {
  for (int i = 0; i < kCircleSamples; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kCircleSamples;
    points.push_back(centre + radius * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0));
  }
}

}  // namespace

bool IsStaticGeom(const mjModel* m, int g) {
  const int body = m->geom_bodyid[g];
  // A mocap body (a child of the world, no joint) is welded to the world for body_weldid, and so
  // is a body on it, yet mjData::mocap_pos moves both.
  return m->body_weldid[body] == 0 && m->body_mocapid[m->body_rootid[body]] < 0;
}

Eigen::Isometry3d StaticGeomPose(const mjModel* m, int g) {
  Eigen::Isometry3d X_WG = Pose(m->geom_pos + 3 * g, m->geom_quat + 4 * g);
  for (int b = m->geom_bodyid[g]; b > 0; b = m->body_parentid[b]) {
    X_WG = Pose(m->body_pos + 3 * b, m->body_quat + 4 * b) * X_WG;
  }
  return X_WG;
}

GeomFootprint FootprintOf(const mjModel* m, int g, const Eigen::Isometry3d& X_WG) {
  GeomFootprint footprint;
  footprint.geom_id = g;
  footprint.colour = ColourOf(m, g);
  const mjtNum* size = m->geom_size + 3 * g;
  const Eigen::Vector3d p = X_WG.translation();
  const Eigen::Matrix3d R = X_WG.linear();
  std::vector<Eigen::Vector3d> points;
  double z_extra = 0.0;  // height above the sampled points (spheres reach above their equator)
  switch (m->geom_type[g]) {
    case mjGEOM_PLANE:
      footprint.z_top_m = p.z();
      return footprint;
    case mjGEOM_BOX:
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d s((corner & 1) ? size[0] : -size[0],
                                (corner & 2) ? size[1] : -size[1],
                                (corner & 4) ? size[2] : -size[2]);
        points.push_back(p + R * s);
      }
      break;
    case mjGEOM_CYLINDER:
      for (double end : {-1.0, 1.0}) {
        for (int i = 0; i < kCircleSamples; ++i) {
          const double a = 2.0 * std::numbers::pi * i / kCircleSamples;
          points.push_back(
              p + R * Eigen::Vector3d(size[0] * std::cos(a), size[0] * std::sin(a), end * size[1]));
        }
      }
      break;
    case mjGEOM_SPHERE:
      AddHorizontalCircle(p, size[0], points);
      z_extra = size[0];
      break;
    case mjGEOM_CAPSULE:
      for (double end : {-1.0, 1.0}) {
        AddHorizontalCircle(p + R.col(2) * end * size[1], size[0], points);
      }
      z_extra = size[0];
      break;
    case mjGEOM_ELLIPSOID:
      for (int i = 0; i < kCircleSamples; ++i) {
        for (int j = 1; j < kCircleSamples / 2; ++j) {
          const double a = 2.0 * std::numbers::pi * i / kCircleSamples;
          const double e = std::numbers::pi * j / (kCircleSamples / 2) - std::numbers::pi / 2;
          points.push_back(p + R * Eigen::Vector3d(size[0] * std::cos(e) * std::cos(a),
                                                   size[1] * std::cos(e) * std::sin(a),
                                                   size[2] * std::sin(e)));
        }
      }
      break;
    default:  // meshes, height fields: their bounding sphere
      AddHorizontalCircle(p, m->geom_rbound[g], points);
      z_extra = m->geom_rbound[g];
      break;
  }
  std::vector<Eigen::Vector2d> points_xy;
  footprint.z_top_m = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& q : points) {
    points_xy.push_back(q.head<2>());
    footprint.z_top_m = std::max(footprint.z_top_m, q.z() + z_extra);
  }
  footprint.outline_W = ConvexHull(std::move(points_xy));
  return footprint;
}

std::vector<GeomFootprint> StaticFootprints(const mjModel* m) {
  std::vector<GeomFootprint> footprints;
  for (int g = 0; g < m->ngeom; ++g) {
    if (!IsStaticGeom(m, g) || m->geom_type[g] == mjGEOM_PLANE || AlphaOf(m, g) <= 0.0f) continue;
    footprints.push_back(FootprintOf(m, g, StaticGeomPose(m, g)));
  }
  return footprints;
}

StaticExtent StaticGeometryExtent(const mjModel* m) {
  StaticExtent extent{WorldBounds::Empty(), 0.0};
  for (const GeomFootprint& f : StaticFootprints(m)) {
    for (const Eigen::Vector2d& v : f.outline_W) extent.bounds.Extend(v);
    extent.z_max_m = std::max(extent.z_max_m, f.z_top_m);
  }
  if (!extent.bounds.IsEmpty()) return extent;
  for (int g = 0; g < m->ngeom; ++g) {
    const mjtNum* size = m->geom_size + 3 * g;
    if (m->geom_type[g] != mjGEOM_PLANE || !IsStaticGeom(m, g) || size[0] <= 0 || size[1] <= 0) {
      continue;
    }
    const Eigen::Isometry3d X_WG = StaticGeomPose(m, g);
    for (double sx : {-1.0, 1.0}) {
      for (double sy : {-1.0, 1.0}) {
        extent.bounds.Extend(
            Eigen::Vector2d((X_WG * Eigen::Vector3d(sx * size[0], sy * size[1], 0.0)).head<2>()));
      }
    }
  }
  if (extent.bounds.IsEmpty()) extent.bounds = {-1.0, 1.0, -1.0, 1.0};
  return extent;
}

}  // namespace plywood::render
