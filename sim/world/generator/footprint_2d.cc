#include "sim/world/generator/footprint_2d.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plywood::sim::worldgen {
namespace {

using Eigen::Vector2d;

// Inside or on a convex counter-clockwise polygon.
bool InsideConvex(const std::vector<Vector2d>& corners, const Vector2d& p) {
  for (size_t i = 0; i < corners.size(); ++i) {
    const Vector2d& a = corners[i];
    const Vector2d& b = corners[(i + 1) % corners.size()];
    if (Cross(b - a, p - a) < 0.0) return false;
  }
  return true;
}

bool SegmentsCross(const Vector2d& a, const Vector2d& b, const Vector2d& c, const Vector2d& d) {
  const double d1 = Cross(b - a, c - a), d2 = Cross(b - a, d - a);
  const double d3 = Cross(d - c, a - c), d4 = Cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 &&
         d4 != 0;
}

double SegmentSegment(const Vector2d& a, const Vector2d& b, const Vector2d& c, const Vector2d& d) {
  if (SegmentsCross(a, b, c, d)) return 0.0;
  return std::min({DistanceToSegment(a, c, d), DistanceToSegment(b, c, d),
                   DistanceToSegment(c, a, b), DistanceToSegment(d, a, b)});
}

double PolygonPolygon(const Footprint& a, const Footprint& b) {
  if (InsideConvex(a.corners, b.corners[0]) || InsideConvex(b.corners, a.corners[0])) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  const size_t n = a.corners.size(), m = b.corners.size();
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < m; ++j) {
      best = std::min(best, SegmentSegment(a.corners[i], a.corners[(i + 1) % n], b.corners[j],
                                           b.corners[(j + 1) % m]));
    }
  }
  return best;
}

// Signed separation along the polygons' edge normals (separating axis theorem): positive when a
// gap exists, negative by the smallest penetration depth otherwise.
double Separation(const Footprint& a, const Footprint& b) {
  double best = -std::numeric_limits<double>::infinity();
  for (const Footprint* f : {&a, &b}) {
    const Footprint* other = f == &a ? &b : &a;
    const size_t n = f->corners.size();
    for (size_t i = 0; i < n; ++i) {
      const Vector2d e = f->corners[(i + 1) % n] - f->corners[i];
      const Vector2d normal = Vector2d(e.y(), -e.x()).normalized();  // outward (counter-clockwise)
      double min_other = std::numeric_limits<double>::infinity();
      for (const Vector2d& q : other->corners) {
        min_other = std::min(min_other, normal.dot(q - f->corners[i]));
      }
      best = std::max(best, min_other);
    }
  }
  return best;
}

}  // namespace

Footprint Footprint::Box(const Vector2d& centre, const Vector2d& half_size, double yaw_rad) {
  const Vector2d ux(std::cos(yaw_rad), std::sin(yaw_rad));
  const Vector2d uy(-ux.y(), ux.x());
  Footprint f;
  f.shape = Shape::kPolygon;
  f.centre = centre;
  f.corners = {centre + half_size.x() * ux - half_size.y() * uy,
               centre + half_size.x() * ux + half_size.y() * uy,
               centre - half_size.x() * ux + half_size.y() * uy,
               centre - half_size.x() * ux - half_size.y() * uy};
  return f;
}

Footprint Footprint::Disc(const Vector2d& centre, double radius_m) {
  Footprint f;
  f.shape = Shape::kDisc;
  f.centre = centre;
  f.radius_m = radius_m;
  return f;
}

double DistanceToSegment(const Vector2d& p, const Vector2d& a, const Vector2d& b) {
  const Vector2d d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

double DistanceToPoint(const Footprint& f, const Vector2d& p) {
  if (f.shape == Footprint::Shape::kDisc) return std::max(0.0, (p - f.centre).norm() - f.radius_m);
  if (InsideConvex(f.corners, p)) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < f.corners.size(); ++i) {
    best =
        std::min(best, DistanceToSegment(p, f.corners[i], f.corners[(i + 1) % f.corners.size()]));
  }
  return best;
}

double Distance(const Footprint& a, const Footprint& b) {
  using Shape = Footprint::Shape;
  if (a.shape == Shape::kDisc && b.shape == Shape::kDisc) {
    return std::max(0.0, (a.centre - b.centre).norm() - a.radius_m - b.radius_m);
  }
  if (a.shape == Shape::kDisc) return std::max(0.0, DistanceToPoint(b, a.centre) - a.radius_m);
  if (b.shape == Shape::kDisc) return std::max(0.0, DistanceToPoint(a, b.centre) - b.radius_m);
  return PolygonPolygon(a, b);
}

bool Overlap(const Footprint& a, const Footprint& b, double tolerance_m) {
  using Shape = Footprint::Shape;
  if (a.shape == Shape::kDisc && b.shape == Shape::kDisc) {
    return (a.centre - b.centre).norm() < a.radius_m + b.radius_m - tolerance_m;
  }
  if (a.shape == Shape::kDisc || b.shape == Shape::kDisc) {
    const Footprint& disc = a.shape == Shape::kDisc ? a : b;
    const Footprint& polygon = a.shape == Shape::kDisc ? b : a;
    if (InsideConvex(polygon.corners, disc.centre)) return true;
    return DistanceToPoint(polygon, disc.centre) < disc.radius_m - tolerance_m;
  }
  return Separation(a, b) < -tolerance_m;
}

std::optional<double> RayHit(const Footprint& f, const Vector2d& p, const Vector2d& direction) {
  if (f.shape == Footprint::Shape::kDisc) {
    const Vector2d m = p - f.centre;
    const double b = m.dot(direction);
    const double c = m.squaredNorm() - f.radius_m * f.radius_m;
    if (c <= 0.0) return 0.0;
    const double disc = b * b - c;
    if (b > 0.0 || disc < 0.0) return std::nullopt;
    return -b - std::sqrt(disc);
  }
  if (InsideConvex(f.corners, p)) return 0.0;
  std::optional<double> best;
  const size_t n = f.corners.size();
  for (size_t i = 0; i < n; ++i) {
    const Vector2d a = f.corners[i];
    const Vector2d e = f.corners[(i + 1) % n] - a;
    const double denom = Cross(direction, e);
    if (denom == 0.0) continue;
    const double t = Cross(a - p, e) / denom;
    const double s = Cross(a - p, direction) / denom;
    if (t >= 0.0 && s >= 0.0 && s <= 1.0 && (!best || t < *best)) best = t;
  }
  return best;
}

bool InsidePolygon(const std::vector<Vector2d>& polygon, const Vector2d& p) {
  bool inside = false;
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vector2d& a = polygon[i];
    const Vector2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace plywood::sim::worldgen
