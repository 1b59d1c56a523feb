#include "sim/world/planar_obstacles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "sim/config/config_error.h"
#include "sim/world/ground_truth_walls.h"
#include "sim/world/mujoco_pair_rules.h"

namespace plywood::sim {
namespace {

// Andrew's monotone chain: the convex hull of `points`, counter-clockwise, collinear points
// dropped.
std::vector<std::pair<double, double>> ConvexHull(std::vector<std::pair<double, double>> points) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  const auto cross = [](const auto& o, const auto& a, const auto& b) {
    return (a.first - o.first) * (b.second - o.second) -
           (a.second - o.second) * (b.first - o.first);
  };
  std::vector<std::pair<double, double>> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

// The point of segment a-b nearest p.
void NearestOnSegment(const double* a, const double* b, const double* p, double out[2]) {
  const double abx = b[0] - a[0], aby = b[1] - a[1];
  const double length2 = abx * abx + aby * aby;
  double t = length2 > 0.0 ? ((p[0] - a[0]) * abx + (p[1] - a[1]) * aby) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  out[0] = a[0] + t * abx;
  out[1] = a[1] + t * aby;
}

// How the projections of a convex polygon (n vertices `v`) and a rectangle (centre, unit axes u
// and v = u turned by +90 deg, half sizes) overlap on the unit axis (ax, ay): the polygon must
// move `back` along -axis or `ahead` along +axis to leave the rectangle's; either <= 0 means the
// axis separates them.
struct AxisOverlap {
  double back, ahead;
};
AxisOverlap ProjectionOverlap(const double* v, int n, const double centre[2], double ux, double uy,
                              double half_x, double half_y, double ax, double ay) {
  double a_lo = std::numeric_limits<double>::infinity(), a_hi = -a_lo;
  for (int i = 0; i < n; ++i) {
    const double t = v[2 * i] * ax + v[2 * i + 1] * ay;
    a_lo = std::min(a_lo, t);
    a_hi = std::max(a_hi, t);
  }
  const double t0 = centre[0] * ax + centre[1] * ay;
  const double extent =
      half_x * std::abs(ux * ax + uy * ay) + half_y * std::abs(-uy * ax + ux * ay);
  return {a_hi - (t0 - extent), t0 + extent - a_lo};
}

}  // namespace

PlanarObstacles::PlanarObstacles(const mjModel* m, const mjData* d, int base_body,
                                 const std::string& robot_file) {
  const int ring = mj_name2id(m, mjOBJ_GEOM, "bumper_ring");
  if (ring < 0 || m->geom_type[ring] != mjGEOM_MESH) {
    throw ConfigError(
        robot_file, "bumper_ring",
        "physics.drive: planar needs the robot's bumper_ring mesh geom (its footprint)");
  }
  // The ring's vertices in the base frame: p_B = R_WB^T (x_WG + R_WG v - x_WB).
  const mjtNum* xb = d->xpos + 3 * base_body;
  const mjtNum* rb = d->xmat + 9 * base_body;
  const mjtNum* xg = d->geom_xpos + 3 * ring;
  const mjtNum* rg = d->geom_xmat + 9 * ring;
  const int mesh = m->geom_dataid[ring];
  std::vector<std::pair<double, double>> points;
  double z_lo = std::numeric_limits<double>::infinity(), z_hi = -z_lo;
  for (int i = 0; i < m->mesh_vertnum[mesh]; ++i) {
    const float* v = m->mesh_vert + 3 * (m->mesh_vertadr[mesh] + i);
    double w[3];
    for (int r = 0; r < 3; ++r) {
      w[r] = xg[r] + rg[3 * r] * v[0] + rg[3 * r + 1] * v[1] + rg[3 * r + 2] * v[2] - xb[r];
    }
    double b[3];
    for (int c = 0; c < 3; ++c) b[c] = rb[c] * w[0] + rb[3 + c] * w[1] + rb[6 + c] * w[2];
    points.emplace_back(b[0], b[1]);
    z_lo = std::min(z_lo, b[2] + xb[2]);
    z_hi = std::max(z_hi, b[2] + xb[2]);
  }
  const std::vector<std::pair<double, double>> hull = ConvexHull(points);
  if (hull.size() < 3) {
    throw ConfigError(robot_file, "bumper_ring", "the ring's footprint on the floor is degenerate");
  }
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const auto& a = hull[i];
    const auto& b = hull[(i + 1) % hull.size()];
    hull_.push_back(a.first);
    hull_.push_back(a.second);
    const double ex = b.first - a.first, ey = b.second - a.second;
    const double length = std::hypot(ex, ey);
    normals_.push_back(ey / length);  // counter-clockwise: outward is the edge turned clockwise
    normals_.push_back(-ex / length);
    reach_m_ = std::max(reach_m_, std::hypot(a.first, a.second));
  }

  // The ground truth's reading of each geom, so that a shape it holds exactly (a box standing on
  // any of its axes, an upright capsule, a geom upright within its tilt tolerance) stops the robot
  // where the truth and the contact drive put its faces, not at its bounding disc.
  GroundTruthOptions outline;
  outline.excluded_geom_group = -1;  // the drive's obstacles are chosen by the contact bits alone
  std::vector<const UprightGeom*> truth_shape(m->ngeom, nullptr);
  const std::vector<UprightGeom> truth_geoms = ExtractUprightGeoms(m, outline);
  for (const UprightGeom& u : truth_geoms) truth_shape[u.geom_id] = &u;

  for (int g = 0; g < m->ngeom; ++g) {
    if (m->body_weldid[m->geom_bodyid[g]] != 0 || !ContactBitsMatch(m, g, ring)) continue;
    const int type = m->geom_type[g];
    if (type == mjGEOM_PLANE) continue;
    const mjtNum* p = d->geom_xpos + 3 * g;
    const mjtNum* r = d->geom_xmat + 9 * g;
    if (type == mjGEOM_HFIELD) {
      // A height field is driven over as floor; one that rises to the ring's height is an
      // obstacle the footprint test does not hold (its top: the elevation scale when level).
      const bool level = r[2] == 0.0 && r[5] == 0.0 && r[8] > 0.0;
      const double top =
          p[2] + (level ? m->hfield_size[4 * m->geom_dataid[g] + 2] : m->geom_rbound[g]);
      if (top > z_lo) height_field_geom_ids_.push_back(g);
      continue;
    }
    const mjtNum* size = m->geom_size + 3 * g;
    const bool upright = r[2] == 0.0 && r[5] == 0.0;  // local z along world z
    Obstacle o;
    o.cx = p[0];
    o.cy = p[1];
    double half_height = m->geom_rbound[g];
    double z_min = std::numeric_limits<double>::quiet_NaN(), z_max = z_min;
    const UprightGeom* truth = truth_shape[g];
    bool by_bound = false;
    if (upright && type == mjGEOM_BOX) {
      o.ux = r[0];
      o.uy = r[3];
      o.half_x = size[0];
      o.half_y = size[1];
      half_height = size[2];
    } else if (upright && type == mjGEOM_CYLINDER) {
      o.disc = true;
      o.radius_m = size[0];
      half_height = size[1];
    } else if (type == mjGEOM_SPHERE) {
      o.disc = true;
      o.radius_m = size[0];
    } else if (truth != nullptr) {
      o.cx = truth->centre_W.x();
      o.cy = truth->centre_W.y();
      z_min = truth->z_min_m;
      z_max = truth->z_max_m;
      if (truth->shape == UprightGeom::Shape::kBox) {
        const double length = truth->R_WG.col(0).norm();
        o.ux = truth->R_WG(0, 0) / length;
        o.uy = truth->R_WG(1, 0) / length;
        o.half_x = truth->half_size_xy.x();
        o.half_y = truth->half_size_xy.y();
      } else {
        o.disc = true;
        o.radius_m = truth->radius_m;
      }
    } else {
      o.disc = true;
      o.radius_m = m->geom_rbound[g];
      // Its exact height range: one lying below the ring (a log on the floor) is no obstacle.
      half_height = GeomVerticalHalfExtent(
          m, g, Eigen::Map<const Eigen::Matrix<mjtNum, 3, 3, Eigen::RowMajor>>(r));
      by_bound = true;
    }
    if (std::isnan(z_min)) {
      z_min = p[2] - half_height;
      z_max = p[2] + half_height;
    }
    if (z_max < z_lo || z_min > z_hi) continue;
    if (by_bound) bounding_disc_geom_ids_.push_back(g);
    // Padded so that rounding in CentreDistance cannot put a footprint the box test drops within
    // its limit.
    o.bound_m = (o.disc ? o.radius_m : std::hypot(o.half_x, o.half_y)) * (1.0 + 1e-9) + 1e-9;
    obstacles_.push_back(o);
  }
  std::vector<BoxGrid2D::Box> boxes;
  boxes.reserve(obstacles_.size());
  for (const Obstacle& o : obstacles_) {
    boxes.push_back({{o.cx - o.bound_m, o.cy - o.bound_m}, {o.cx + o.bound_m, o.cy + o.bound_m}});
  }
  grid_ = BoxGrid2D(std::move(boxes), kGridCellM);
}

double PlanarObstacles::CentreDistance(const Obstacle& o, double x, double y) {
  const double dx = x - o.cx, dy = y - o.cy;
  if (o.disc) return std::max(0.0, std::hypot(dx, dy) - o.radius_m);
  const double ex = std::max(0.0, std::abs(dx * o.ux + dy * o.uy) - o.half_x);
  const double ey = std::max(0.0, std::abs(-dx * o.uy + dy * o.ux) - o.half_y);
  return std::hypot(ex, ey);
}

const std::vector<int>& PlanarObstacles::Near(double x, double y) {
  if (near_valid_ && std::hypot(x - near_x_, y - near_y_) <= kNearPadM / 2.0) return near_;
  near_.clear();
  const double limit = reach_m_ + kNearPadM;
  // The grid's candidates: every obstacle whose box meets the query box, which is wider than
  // the box test below by far more than rounding, so no obstacle the test keeps is missed.
  const double query = limit * (1.0 + 1e-9) + 1e-6;
  grid_.Query({{x - query, y - query}, {x + query, y + query}}, &grid_hits_);
  for (const int i : grid_hits_) {
    const Obstacle& o = obstacles_[i];
    // A cheap box test first; it only drops obstacles whose footprint is farther than the limit,
    // so the list is CentreDistance's alone.
    const double box = limit * (1.0 + 1e-9) + o.bound_m;
    if (std::abs(x - o.cx) > box || std::abs(y - o.cy) > box) continue;
    if (CentreDistance(o, x, y) <= limit) near_.push_back(i);
  }
  near_x_ = x;
  near_y_ = y;
  near_valid_ = true;
  return near_;
}

PlanarObstacles::DiscAgainstFootprint PlanarObstacles::AgainstFootprint(const double centre[2],
                                                                        double radius_m) const {
  DiscAgainstFootprint relation;
  const int n = static_cast<int>(hull_.size() / 2);
  const double* v = hull_.data();
  for (int i = 0; i < n; ++i) {
    const double* a = v + 2 * i;
    const double signed_distance =
        (centre[0] - a[0]) * normals_[2 * i] + (centre[1] - a[1]) * normals_[2 * i + 1];
    if (signed_distance > 0.0) relation.centre_inside = false;
    if (radius_m - signed_distance < relation.least_depth_m) {
      relation.least_depth_m = radius_m - signed_distance;
      relation.least_edge = i;
    }
    double q[2];
    NearestOnSegment(a, v + 2 * ((i + 1) % n), centre, q);
    const double distance = std::hypot(centre[0] - q[0], centre[1] - q[1]);
    if (distance < relation.nearest_m) {
      relation.nearest_m = distance;
      relation.nearest_point[0] = q[0];
      relation.nearest_point[1] = q[1];
    }
  }
  return relation;
}

double PlanarObstacles::Gap(const Obstacle& o, const msgs::Pose2D& X_WR, double witness[2],
                            bool overlap_only) const {
  // The obstacle in the robot frame.
  const double c = std::cos(X_WR.theta_rad), s = std::sin(X_WR.theta_rad);
  const double dx = o.cx - X_WR.x_m, dy = o.cy - X_WR.y_m;
  const double centre[2] = {c * dx + s * dy, -s * dx + c * dy};
  const int n = static_cast<int>(hull_.size() / 2);
  const double* v = hull_.data();
  if (o.disc) {
    const DiscAgainstFootprint relation = AgainstFootprint(centre, o.radius_m);
    if (relation.centre_inside) {
      witness[0] = centre[0];
      witness[1] = centre[1];
      return -1.0;
    }
    witness[0] = relation.nearest_point[0];
    witness[1] = relation.nearest_point[1];
    return relation.nearest_m < o.radius_m ? -1.0 : relation.nearest_m - o.radius_m;
  }
  // A rectangle: its axes and corners in the robot frame, counter-clockwise.
  const double ux = c * o.ux + s * o.uy, uy = -s * o.ux + c * o.uy;
  const double vx = -uy, vy = ux;
  double corners[8];
  const double signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  for (int k = 0; k < 4; ++k) {
    corners[2 * k] = centre[0] + signs[k][0] * o.half_x * ux + signs[k][1] * o.half_y * vx;
    corners[2 * k + 1] = centre[1] + signs[k][0] * o.half_x * uy + signs[k][1] * o.half_y * vy;
  }
  // Separating axes: the footprint's edge normals and the rectangle's two axes.
  const auto separated_on = [&](double ax, double ay) {
    const AxisOverlap overlap = ProjectionOverlap(v, n, centre, ux, uy, o.half_x, o.half_y, ax, ay);
    return overlap.back <= 0.0 || overlap.ahead <= 0.0;
  };
  bool overlap = !separated_on(ux, uy) && !separated_on(vx, vy);
  for (int i = 0; overlap && i < n; ++i) {
    if (separated_on(normals_[2 * i], normals_[2 * i + 1])) overlap = false;
  }
  if (overlap) {
    // The obstacle's point nearest the base origin, for a bearing.
    const double lx = std::clamp(-(centre[0] * ux + centre[1] * uy), -o.half_x, o.half_x);
    const double ly = std::clamp(-(centre[0] * vx + centre[1] * vy), -o.half_y, o.half_y);
    witness[0] = centre[0] + lx * ux + ly * vx;
    witness[1] = centre[1] + lx * uy + ly * vy;
    return -1.0;
  }
  if (overlap_only) return 0.0;
  // Disjoint convex polygons: the gap is between a vertex of one and an edge of the other.
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const double px = v[2 * i] - centre[0], py = v[2 * i + 1] - centre[1];
    const double ex = std::max(0.0, std::abs(px * ux + py * uy) - o.half_x);
    const double ey = std::max(0.0, std::abs(px * vx + py * vy) - o.half_y);
    const double distance = std::hypot(ex, ey);
    if (distance < best) {
      best = distance;
      witness[0] = v[2 * i];
      witness[1] = v[2 * i + 1];
    }
  }
  for (int k = 0; k < 4; ++k) {
    for (int i = 0; i < n; ++i) {
      double q[2];
      NearestOnSegment(v + 2 * i, v + 2 * ((i + 1) % n), corners + 2 * k, q);
      const double distance = std::hypot(corners[2 * k] - q[0], corners[2 * k + 1] - q[1]);
      if (distance < best) {
        best = distance;
        witness[0] = q[0];
        witness[1] = q[1];
      }
    }
  }
  return best;
}

bool PlanarObstacles::Overlaps(const msgs::Pose2D& X_WR) {
  for (int i : Near(X_WR.x_m, X_WR.y_m)) {
    const Obstacle& o = obstacles_[i];
    if (CentreDistance(o, X_WR.x_m, X_WR.y_m) >= reach_m_) continue;
    double witness[2];
    if (Gap(o, X_WR, witness, /*overlap_only=*/true) < 0.0) return true;
  }
  return false;
}

bool PlanarObstacles::OverlapsFrom(const msgs::Pose2D& start, const msgs::Pose2D& X_WR) {
  for (int i : Near(X_WR.x_m, X_WR.y_m)) {
    const Obstacle& o = obstacles_[i];
    const double centre = CentreDistance(o, X_WR.x_m, X_WR.y_m);
    if (centre >= reach_m_) continue;
    double witness[2];
    if (Gap(o, X_WR, witness, /*overlap_only=*/true) >= 0.0) continue;
    if (Gap(o, start, witness, /*overlap_only=*/true) < 0.0 &&
        centre >= CentreDistance(o, start.x_m, start.y_m)) {
      continue;  // overlapped already, and no deeper
    }
    return true;
  }
  return false;
}

void PlanarObstacles::ContactBearings(const msgs::Pose2D& X_WR, double skin_m,
                                      std::vector<double>* out) {
  for (int i : Near(X_WR.x_m, X_WR.y_m)) {
    const Obstacle& o = obstacles_[i];
    if (CentreDistance(o, X_WR.x_m, X_WR.y_m) > reach_m_ + skin_m) continue;
    double witness[2];
    if (Gap(o, X_WR, witness, /*overlap_only=*/false) <= skin_m)
      out->push_back(std::atan2(witness[1], witness[0]));
  }
}

double PlanarObstacles::Penetration(const Obstacle& o, const msgs::Pose2D& X_WR,
                                    double direction_W[2]) const {
  const double c = std::cos(X_WR.theta_rad), s = std::sin(X_WR.theta_rad);
  const double dx = o.cx - X_WR.x_m, dy = o.cy - X_WR.y_m;
  const double centre[2] = {c * dx + s * dy, -s * dx + c * dy};
  const int n = static_cast<int>(hull_.size() / 2);
  const double* v = hull_.data();
  double depth = 0.0, dir[2] = {0.0, 0.0};  // robot frame
  if (o.disc) {
    // Inside: out through the edge the centre is least deep behind; outside: straight away from
    // the disc's centre, from the footprint's point nearest it.
    const DiscAgainstFootprint relation = AgainstFootprint(centre, o.radius_m);
    const double nearest = relation.nearest_m;
    if (relation.centre_inside) {
      depth = relation.least_depth_m;
      dir[0] = -normals_[2 * relation.least_edge];
      dir[1] = -normals_[2 * relation.least_edge + 1];
    } else if (nearest < o.radius_m && nearest > 0.0) {
      depth = o.radius_m - nearest;
      dir[0] = (relation.nearest_point[0] - centre[0]) / nearest;
      dir[1] = (relation.nearest_point[1] - centre[1]) / nearest;
    }
  } else {
    // A rectangle: the separating axis (its two axes, the footprint's edge normals) along which
    // the two projections overlap least.
    const double ux = c * o.ux + s * o.uy, uy = -s * o.ux + c * o.uy;
    const double vx = -uy, vy = ux;
    depth = std::numeric_limits<double>::infinity();
    const auto try_axis = [&](double ax, double ay) {
      const auto [back, ahead] =
          ProjectionOverlap(v, n, centre, ux, uy, o.half_x, o.half_y, ax, ay);
      const double overlap = std::min(back, ahead);
      if (overlap < depth) {
        depth = overlap;
        dir[0] = back <= ahead ? -ax : ax;
        dir[1] = back <= ahead ? -ay : ay;
      }
    };
    try_axis(ux, uy);
    try_axis(vx, vy);
    for (int i = 0; i < n; ++i) try_axis(normals_[2 * i], normals_[2 * i + 1]);
    depth = std::max(0.0, depth);
  }
  direction_W[0] = c * dir[0] - s * dir[1];
  direction_W[1] = s * dir[0] + c * dir[1];
  return depth;
}

bool PlanarObstacles::PushOut(msgs::Pose2D* X_WR, double max_push_m) {
  // A push clears its obstacle by this much more than the depth, so that rounding cannot leave
  // the two overlapping by a hair.
  constexpr double kClearanceM = 1e-9;
  constexpr int kRounds = 8;
  msgs::Pose2D pose = *X_WR;
  double pushed_m = 0.0;
  for (int round = 0; round < kRounds; ++round) {
    double deepest = 0.0, direction[2] = {0.0, 0.0};
    for (int i : Near(pose.x_m, pose.y_m)) {
      const Obstacle& o = obstacles_[i];
      if (CentreDistance(o, pose.x_m, pose.y_m) >= reach_m_) continue;
      double d[2];
      const double depth = Penetration(o, pose, d);
      if (depth > deepest) {
        deepest = depth;
        direction[0] = d[0];
        direction[1] = d[1];
      }
    }
    if (deepest == 0.0) break;
    pushed_m += deepest + kClearanceM;
    if (pushed_m > max_push_m) return false;
    pose.x_m += (deepest + kClearanceM) * direction[0];
    pose.y_m += (deepest + kClearanceM) * direction[1];
  }
  if (Overlaps(pose)) return false;
  *X_WR = pose;
  return true;
}

}  // namespace plywood::sim
