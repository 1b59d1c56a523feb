#include "viewer/overlay_lines.h"

#include <algorithm>

namespace plywood::viewer {

void OverlayLines::Add(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const float rgba[4],
                       double width_px) {
  const std::array<float, 4> colour{rgba[0], rgba[1], rgba[2], rgba[3]};
  const float width = static_cast<float>(width_px);
  auto batch = std::find_if(batches_.begin(), batches_.end(), [&](const Batch& candidate) {
    return candidate.rgba == colour && candidate.width_px == width;
  });
  if (batch == batches_.end()) {
    batches_.push_back({colour, width, {}});
    batch = std::prev(batches_.end());
  }
  for (const Eigen::Vector3d* p : {&a, &b}) {
    batch->xyz.insert(batch->xyz.end(), {static_cast<float>(p->x()), static_cast<float>(p->y()),
                                         static_cast<float>(p->z())});
  }
}

std::size_t OverlayLines::segment_count() const {
  std::size_t n = 0;
  for (const Batch& batch : batches_) n += batch.xyz.size() / 6;
  return n;
}

}  // namespace plywood::viewer
