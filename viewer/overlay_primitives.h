#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace plywood::viewer {

// The overlays' line segments and filled quads, batched by colour and width so a frame draws them
// in a handful of GL calls. As MuJoCo geoms each segment was a draw call of its own with its
// material state (~5 us each in software GL): a laser scan, a sonar ring, a long run's paths and
// an occupancy grid's cells are thousands.
class OverlayPrimitives {
 public:
  enum class Kind { kLines, kQuads };
  struct Batch {
    Kind kind = Kind::kLines;
    std::array<float, 4> rgba{};
    float width_px = 1.0f;   // lines only
    std::vector<float> xyz;  // two vertices per segment, four per quad (in order round it)
  };

  void Add(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const float rgba[4],
           double width_px);
  // An axis-aligned rectangle [min, max] filled at height z.
  void AddRectangle(const Eigen::Vector2d& min, const Eigen::Vector2d& max, double z,
                    const float rgba[4]);
  void Clear() { batches_.clear(); }
  const std::vector<Batch>& batches() const { return batches_; }

 private:
  Batch& BatchFor(Kind kind, const float rgba[4], float width_px);

  std::vector<Batch> batches_;  // few (one per overlay colour and width): searched linearly
};

}  // namespace plywood::viewer
