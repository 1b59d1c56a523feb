#include "sim/world/continuing_faces.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

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
  constexpr double tol = kContinuingFaceToleranceM;
  if (OffLine(p.a, u, q.a) > tol || OffLine(p.a, u, q.b) > tol || OffLine(q.a, v, p.a) > tol ||
      OffLine(q.a, v, p.b) > tol) {
    return false;
  }
  // q spans [u.(q.a - p.a), u.(q.b - p.a)] along p, which spans [0, length_p].
  return std::max(u.dot(q.a - p.a) - length_p, -u.dot(q.b - p.a)) <= tol;
}

}  // namespace

void JoinContinuingFaces(GroundTruthWalls* walls) {
  const std::vector<WallSegment>& faces = walls->segments;
  const int n = static_cast<int>(faces.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (Continues(faces[i], faces[j])) {
        const int ri = root(i), rj = root(j);
        parent[std::max(ri, rj)] = std::min(ri, rj);
      }
    }
  }
  walls->surfaces.clear();
  walls->surface_of_segment.assign(n, -1);
  std::vector<int> slot(n, -1);  // by root: the surface's index
  for (int k = 0; k < n; ++k) {
    const int r = root(k);
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(walls->surfaces.size());
      walls->surfaces.push_back({faces[k].a, faces[k].b, {}});
    }
    walls->surface_of_segment[k] = slot[r];
    WallSurface& surface = walls->surfaces[slot[r]];
    surface.segments.push_back(k);
    // The root is the surface's first face (roots are the smallest index): ends are measured along
    // it and taken from the faces themselves, so a lone face keeps its own ends bit for bit.
    const WallSegment& first = faces[r];
    const Eigen::Vector2d u = first.b - first.a;
    if (u.dot(faces[k].a - first.a) < u.dot(surface.a - first.a)) surface.a = faces[k].a;
    if (u.dot(faces[k].b - first.a) > u.dot(surface.b - first.a)) surface.b = faces[k].b;
  }
}

}  // namespace plywood::sim
