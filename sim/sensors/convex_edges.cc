#include "sim/sensors/convex_edges.h"

#include <algorithm>

#include "sim/world/ground_truth_walls.h"

namespace plywood::sim {

std::vector<ConvexEdge> ExposedBoxEdges(const mjModel* model) {
  const std::vector<UprightGeom> geoms = ExtractUprightGeoms(model);
  std::vector<ConvexEdge> edges;
  const double signs[4][2] = {{1.0, 1.0}, {-1.0, 1.0}, {-1.0, -1.0}, {1.0, -1.0}};
  for (std::size_t i = 0; i < geoms.size(); ++i) {
    const UprightGeom& box = geoms[i];
    if (box.shape != UprightGeom::Shape::kBox) continue;
    for (const auto& s : signs) {
      const Eigen::Vector2d corner_G(s[0] * box.half_size_xy.x(), s[1] * box.half_size_xy.y());
      const Eigen::Vector2d outward_G = Eigen::Vector2d(s[0], s[1]).normalized();
      const Eigen::Vector2d corner_W = box.centre_W + box.R_WG * corner_G;
      const Eigen::Vector2d probe_W = corner_W + kBuriedProbeM * (box.R_WG * outward_G);
      const bool buried = std::any_of(geoms.begin(), geoms.end(), [&](const UprightGeom& other) {
        return &other != &box && other.z_max_m > box.z_min_m && other.z_min_m < box.z_max_m &&
               other.ContainsXY(probe_W);
      });
      if (!buried) edges.push_back({corner_W, box.z_min_m, box.z_max_m});
    }
  }
  return edges;
}

}  // namespace plywood::sim
