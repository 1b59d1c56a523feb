#include "sim/world/generator/wall_builder.h"

#include <cmath>
#include <numbers>

#include "sim/world/generator/footprint_2d.h"

namespace plywood::sim::worldgen {
namespace {

using Eigen::Vector2d;

// The left turn from direction `in` to direction `out`, in (-pi, pi).
double TurnRad(const Vector2d& in, const Vector2d& out) {
  return std::atan2(Cross(in, out), in.dot(out));
}

}  // namespace

WorldGeom& AddWallAlong(GeneratedWorld& world, const Vector2d& a, const Vector2d& b,
                        double extend_a_m, double extend_b_m) {
  const Vector2d along = (b - a).normalized();
  const Vector2d outward(along.y(), -along.x());  // the room is on the left
  const double length = (b - a).norm();
  const double mid = (length + extend_b_m - extend_a_m) / 2.0;
  const Vector2d centre = a + mid * along + outward * (kWallThicknessM / 2.0);
  const double half_length = (length + extend_a_m + extend_b_m) / 2.0;
  const double yaw_deg = std::atan2(along.y(), along.x()) * 180.0 / std::numbers::pi;
  return world.AddWallBox(centre, half_length, yaw_deg);
}

double MitreExtensionM(double turn_rad) {
  if (turn_rad <= 0.0) return 0.0;  // reflex or straight
  const double interior = std::numbers::pi - turn_rad;
  return kWallThicknessM / std::tan(interior / 2.0);
}

std::vector<std::vector<int>> AddOutlineWalls(GeneratedWorld& world,
                                              const std::vector<Vector2d>& outline,
                                              const std::vector<OutlineEdge>& edges) {
  const size_t n = outline.size();
  std::vector<std::vector<int>> built(n);
  for (size_t i = 0; i < n; ++i) {
    const OutlineEdge& edge = edges[i];
    if (!edge.built) continue;
    const Vector2d a = outline[i];
    const Vector2d b = outline[(i + 1) % n];
    const Vector2d prev = outline[(i + n - 1) % n];
    const Vector2d next = outline[(i + 2) % n];
    const double length = (b - a).norm();
    const Vector2d along = (b - a) / length;
    // Mitres only where the neighbouring edge is built too.
    const double extend_start =
        edges[(i + n - 1) % n].built ? MitreExtensionM(TurnRad(a - prev, b - a)) : 0.0;
    const double extend_end =
        edges[(i + 1) % n].built ? MitreExtensionM(TurnRad(b - a, next - b)) : 0.0;
    double from = 0.0;
    std::vector<std::pair<double, double>> pieces;
    for (const auto& [o0, o1] : edge.openings) {
      pieces.emplace_back(from, o0);
      from = o1;
    }
    pieces.emplace_back(from, length);
    for (const auto& [s0, s1] : pieces) {
      if (s1 - s0 < 1e-9) continue;
      AddWallAlong(world, a + s0 * along, a + s1 * along, s0 == 0.0 ? extend_start : 0.0,
                   s1 == length ? extend_end : 0.0);
      built[i].push_back(static_cast<int>(world.geoms.size()) - 1);
    }
  }
  return built;
}

std::vector<Vector2d> SimplifyOutline(const std::vector<Vector2d>& outline) {
  std::vector<Vector2d> out;
  for (const Vector2d& p : outline) {
    if (out.empty() || (p - out.back()).norm() > 1e-9) out.push_back(p);
  }
  while (out.size() > 1 && (out.front() - out.back()).norm() <= 1e-9) out.pop_back();
  bool changed = true;
  while (changed && out.size() > 3) {
    changed = false;
    for (size_t i = 0; i < out.size(); ++i) {
      const Vector2d& prev = out[(i + out.size() - 1) % out.size()];
      const Vector2d& next = out[(i + 1) % out.size()];
      const Vector2d in = out[i] - prev, outgoing = next - out[i];
      if (std::abs(Cross(in.normalized(), outgoing.normalized())) < 1e-9 && in.dot(outgoing) > 0) {
        out.erase(out.begin() + static_cast<long>(i));
        changed = true;
        break;
      }
    }
  }
  return out;
}

double SignedArea(const std::vector<Vector2d>& outline) {
  double area = 0.0;
  for (size_t i = 0; i < outline.size(); ++i) {
    area += Cross(outline[i], outline[(i + 1) % outline.size()]);
  }
  return area / 2.0;
}

}  // namespace plywood::sim::worldgen
