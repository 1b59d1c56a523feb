#include "eval/geometric_map/joined_faces.h"

#include <algorithm>
#include <cmath>

#include "sim/world/linked_groups.h"

namespace plywood::eval {
namespace {

constexpr double kCollinearDistanceM = 1e-3;
constexpr double kCollinearSine = 1.75e-4;  // 0.01 deg

// Whether faces p and q lie on one line, face the same way and leave a gap of at most max_gap_m.
bool Joinable(const sim::WallSegment& p, const sim::WallSegment& q, double max_gap_m) {
  const double length = p.LengthM();
  if (length < 1e-9 || q.LengthM() < 1e-9) return false;
  const Eigen::Vector2d u = (p.b - p.a) / length, v = (q.b - q.a).normalized();
  if (u.dot(v) <= 0.0 || std::abs(u.x() * v.y() - u.y() * v.x()) > kCollinearSine) return false;
  const Eigen::Vector2d n(u.y(), -u.x());
  if (std::abs(n.dot(q.a - p.a)) > kCollinearDistanceM ||
      std::abs(n.dot(q.b - p.a)) > kCollinearDistanceM) {
    return false;
  }
  const double q0 = u.dot(q.a - p.a), q1 = u.dot(q.b - p.a);
  return std::max(q0 - length, -q1) <= max_gap_m;
}

}  // namespace

std::vector<JoinedFace> JoinCollinearFaces(const std::vector<sim::WallSegment>& faces,
                                           double max_gap_m) {
  const int n = static_cast<int>(faces.size());
  const std::vector<int> group =
      sim::LinkedGroups(n, [&](int i, int j) { return Joinable(faces[i], faces[j], max_gap_m); });
  std::vector<JoinedFace> joined;
  std::vector<int> slot(n, -1);
  for (int k = 0; k < n; ++k) {
    const int r = group[k];
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(joined.size());
      joined.push_back({faces[k].a, faces[k].b, {}});
    }
    JoinedFace& face = joined[slot[r]];
    face.members.push_back(k);
    // Stretch along the first member's direction to the outermost endpoints.
    const Eigen::Vector2d u = (faces[r].b - faces[r].a).normalized();
    for (const Eigen::Vector2d& p : {faces[k].a, faces[k].b}) {
      if (u.dot(p - face.a) < 0.0) face.a = faces[r].a + u * u.dot(p - faces[r].a);
      if (u.dot(p - face.b) > 0.0) face.b = faces[r].a + u * u.dot(p - faces[r].a);
    }
  }
  return joined;
}

double CoveredLengthM(const sim::WallSegment& face, const Eigen::Vector2d& start,
                      const Eigen::Vector2d& end) {
  const double length = face.LengthM();
  if (length < 1e-9) return 0.0;
  const Eigen::Vector2d u = (face.b - face.a) / length;
  const double s0 = u.dot(start - face.a), s1 = u.dot(end - face.a);
  return std::max(0.0, std::min(length, std::max(s0, s1)) - std::max(0.0, std::min(s0, s1)));
}

}  // namespace plywood::eval
