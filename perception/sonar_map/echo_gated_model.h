#pragma once

#include <Eigen/Core>
#include <memory>

#include "msgs/range_ring.h"
#include "perception/sonar_map/sonar_cell_model.h"

namespace plywood::perception {

// A sonar model that says nothing (0.5) about a cell whose nearest transducer heard nothing, and
// defers to `inner` otherwise. On smooth plywood most misses are specular: the face is there but
// echoed away. The network learnt that a miss usually means free space (it does, on average), so
// a face passed at a grazing angle was wiped out of the grid by the passes that did not hear it.
class EchoGatedModel final : public SonarCellModel {
 public:
  // @throws std::invalid_argument when inner is null.
  explicit EchoGatedModel(std::shared_ptr<const SonarCellModel> inner);
  double Probability(const msgs::RangeRing& ring, const Eigen::Vector2d& p_R) const override;

 private:
  std::shared_ptr<const SonarCellModel> inner_;
};

}  // namespace plywood::perception
