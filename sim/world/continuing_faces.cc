#include "sim/world/continuing_faces.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "sim/world/linked_groups.h"

namespace plywood::sim {
namespace {

// Distance of `p` from the line through `origin` along the unit vector `u`.
double OffLine(const Eigen::Vector2d& origin, const Eigen::Vector2d& u, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = p - origin;
  return std::abs(u.x() * d.y() - u.y() * d.x());
}

bool Continues(const WallSegment& p, const WallSegment& q) {
  const double length_p = p.LengthM(), length_q = q.LengthM();
  if (!(length_p > 0.0) || !(length_q > 0.0)) return false;
  const Eigen::Vector2d u = (p.b - p.a) / length_p, v = (q.b - q.a) / length_q;
  if (u.dot(v) <= 0.0) return false;  // opposite normals: two sides, never one surface
  constexpr double tol = kContinuingFaceOffLineM;
  if (OffLine(p.a, u, q.a) > tol || OffLine(p.a, u, q.b) > tol || OffLine(q.a, v, p.a) > tol ||
      OffLine(q.a, v, p.b) > tol) {
    return false;
  }
  // q spans [u.(q.a - p.a), u.(q.b - p.a)] along p, which spans [0, length_p]: the seam between
  // them, negative where they overlap.
  return std::max(u.dot(q.a - p.a) - length_p, -u.dot(q.b - p.a)) <= kContinuingFaceSeamM;
}

}  // namespace

void JoinContinuingFaces(GroundTruthWalls* walls) {
  const std::vector<WallSegment>& faces = walls->segments;
  const int n = static_cast<int>(faces.size());
  const std::vector<int> group =
      LinkedGroups(n, [&](int i, int j) { return Continues(faces[i], faces[j]); });
  walls->surfaces.clear();
  walls->surface_of_segment.assign(n, -1);
  std::vector<int> slot(n, -1);  // by group: the surface's index
  for (int k = 0; k < n; ++k) {
    const int r = group[k];
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(walls->surfaces.size());
      walls->surfaces.emplace_back();
    }
    walls->surface_of_segment[k] = slot[r];
    WallSurface& surface = walls->surfaces[slot[r]];
    surface.segments.push_back(k);
    // Faces come in ascending rows: a face longer by more than the tolerance names the surface,
    // so equal faces (lengths differing only by rounding) leave it to the lowest row.
    if (surface.name < 0 ||
        faces[k].LengthM() > faces[surface.name].LengthM() + kContinuingFaceToleranceM) {
      surface.name = k;
    }
  }
  // Ends on the longest face's line: the extreme ends of the faces projected onto it (the joined
  // faces lie within the tolerance of it), the face's own ends where they are the extremes, so a
  // lone face keeps its ends bit for bit.
  for (WallSurface& surface : walls->surfaces) {
    const WallSegment& longest = faces[surface.name];
    const Eigen::Vector2d u = (longest.b - longest.a) / longest.LengthM();
    double t_min = 0.0, t_max = longest.LengthM();
    surface.a = longest.a;
    surface.b = longest.b;
    for (int k : surface.segments) {
      if (k == surface.name) continue;  // its own ends are a and b already, exactly
      for (const Eigen::Vector2d& end : {faces[k].a, faces[k].b}) {
        const double t = u.dot(end - longest.a);
        if (t < t_min) {
          t_min = t;
          surface.a = longest.a + t * u;
        }
        if (t > t_max) {
          t_max = t;
          surface.b = longest.a + t * u;
        }
      }
    }
  }
}

}  // namespace plywood::sim
