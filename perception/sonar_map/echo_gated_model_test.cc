#include "perception/sonar_map/echo_gated_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>

namespace plywood::perception {
namespace {

// Answers 0.9 for every cell, so any other answer comes from the gate.
class Constant final : public SonarCellModel {
 public:
  double Probability(const msgs::RangeRing&, const Eigen::Vector2d&) const override { return 0.9; }
};

// Four transducers at 0, 90, 180, 270 deg; only the one facing +y heard an echo.
msgs::RangeRing FourWay() {
  msgs::RangeRing ring;
  ring.range_min_m = 0.15;
  ring.range_max_m = 5.0;
  for (int i = 0; i < 4; ++i) {
    msgs::RangeReading r;
    r.X_RS = {0.2 * std::cos(i * M_PI / 2), 0.2 * std::sin(i * M_PI / 2), i * M_PI / 2};
    r.echo = i == 1;
    r.range_m = r.echo ? 1.0 : 0.0;
    ring.readings.push_back(r);
  }
  return ring;
}

TEST(EchoGatedModelTest, CellsOfATransducerThatHeardNothingStayUnknown) {
  const EchoGatedModel model(std::make_shared<Constant>());
  const msgs::RangeRing ring = FourWay();
  EXPECT_EQ(model.Probability(ring, {0.0, 0.5}), 0.9);  // facing the echo
  EXPECT_EQ(model.Probability(ring, {0.3, 0.5}), 0.9);  // 59 deg: still nearest to +y
  EXPECT_EQ(model.Probability(ring, {0.5, 0.0}), 0.5);  // facing a miss
  EXPECT_EQ(model.Probability(ring, {0.5, 0.3}), 0.5);  // 31 deg: nearest to +x, a miss
  EXPECT_EQ(model.Probability(ring, {-0.5, -0.1}), 0.5);
}

TEST(EchoGatedModelTest, NeedsAModel) {
  EXPECT_THROW(EchoGatedModel(nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace plywood::perception
