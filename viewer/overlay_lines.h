#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace plywood::viewer {

// The overlays' line segments, batched by colour and width so a frame draws them in a handful of
// GL calls. As MuJoCo geoms each segment was a draw call of its own with its material state
// (~5 us each in software GL): a laser scan, a sonar ring and a long run's paths are thousands.
class OverlayLines {
 public:
  struct Batch {
    std::array<float, 4> rgba{};
    float width_px = 1.0f;
    std::vector<float> xyz;  // two vertices per segment
  };

  void Add(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const float rgba[4],
           double width_px);
  void Clear() { batches_.clear(); }
  const std::vector<Batch>& batches() const { return batches_; }
  std::size_t segment_count() const;

 private:
  std::vector<Batch> batches_;  // few (one per overlay colour and width): searched linearly
};

}  // namespace plywood::viewer
