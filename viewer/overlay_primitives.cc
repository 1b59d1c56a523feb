#include "viewer/overlay_primitives.h"

#include <algorithm>

namespace plywood::viewer {

OverlayPrimitives::Batch& OverlayPrimitives::BatchFor(Kind kind, const float rgba[4],
                                                      float width_px) {
  const std::array<float, 4> colour{rgba[0], rgba[1], rgba[2], rgba[3]};
  auto batch = std::find_if(batches_.begin(), batches_.end(), [&](const Batch& candidate) {
    return candidate.kind == kind && candidate.rgba == colour && candidate.width_px == width_px;
  });
  if (batch != batches_.end()) return *batch;
  batches_.push_back({kind, colour, width_px, {}});
  return batches_.back();
}

void OverlayPrimitives::Add(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const float rgba[4],
                            double width_px) {
  Batch& batch = BatchFor(Kind::kLines, rgba, static_cast<float>(width_px));
  for (const Eigen::Vector3d* p : {&a, &b}) {
    batch.xyz.insert(batch.xyz.end(), {static_cast<float>(p->x()), static_cast<float>(p->y()),
                                       static_cast<float>(p->z())});
  }
}

void OverlayPrimitives::AddRectangle(const Eigen::Vector2d& min, const Eigen::Vector2d& max,
                                     double z, const float rgba[4]) {
  Batch& batch = BatchFor(Kind::kQuads, rgba, 0.0f);
  const float zf = static_cast<float>(z);
  const float x0 = static_cast<float>(min.x()), y0 = static_cast<float>(min.y());
  const float x1 = static_cast<float>(max.x()), y1 = static_cast<float>(max.y());
  batch.xyz.insert(batch.xyz.end(), {x0, y0, zf, x1, y0, zf, x1, y1, zf, x0, y1, zf});
}

}  // namespace plywood::viewer
