#include "perception/sonar_map/echo_gated_model.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace plywood::perception {

EchoGatedModel::EchoGatedModel(std::shared_ptr<const SonarCellModel> inner)
    : inner_(std::move(inner)) {
  if (!inner_) throw std::invalid_argument("sonar_model: no model to gate");
}

double EchoGatedModel::Probability(const msgs::RangeRing& ring, const Eigen::Vector2d& p_R) const {
  // The nearest transducer by angle, as ComputeCellFeatures picks it (ties to the lower index).
  const double bearing = std::atan2(p_R.y(), p_R.x());
  int nearest = -1;
  double best = 1e9;
  for (int i = 0; i < static_cast<int>(ring.readings.size()); ++i) {
    const double offset = std::abs(msgs::WrapAngle(bearing - ring.readings[i].X_RS.theta_rad));
    if (offset < best) {
      best = offset;
      nearest = i;
    }
  }
  if (nearest < 0 || !ring.readings[nearest].HeardEcho()) return 0.5;
  return inner_->Probability(ring, p_R);
}

}  // namespace plywood::perception
