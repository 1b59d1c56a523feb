#include "sim/world/physical_deviation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace plywood::sim {
namespace {

TEST(PhysicalDeviationTest, DefaultIsTheNominalRobot) {
  const robot::DiffDriveSpec spec = robot::P3dxSpec();
  const WheelGeometry g = DeviatedWheelGeometry(spec, PhysicalDeviation{});
  EXPECT_DOUBLE_EQ(g.left_radius_m, spec.wheel_radius_m);
  EXPECT_DOUBLE_EQ(g.right_radius_m, spec.wheel_radius_m);
  EXPECT_DOUBLE_EQ(g.track_m, spec.track_m);
}

TEST(PhysicalDeviationTest, DiameterRatioKeepsTheMeanDiameterNominal) {
  const robot::DiffDriveSpec spec = robot::MagellanProSpec();
  const WheelGeometry g =
      DeviatedWheelGeometry(spec, {.wheel_diameter_ratio = 1.01, .track_ratio = 1.03});
  EXPECT_NEAR(g.right_radius_m / g.left_radius_m, 1.01, 1e-12);
  EXPECT_NEAR((g.left_radius_m + g.right_radius_m) / 2.0, spec.wheel_radius_m, 1e-15);
  EXPECT_NEAR(g.track_m, 1.03 * spec.track_m, 1e-15);
  // Borenstein & Feng's closed forms.
  EXPECT_NEAR(g.right_radius_m, 2.0 * spec.wheel_radius_m * 1.01 / 2.01, 1e-15);
  EXPECT_NEAR(g.left_radius_m, 2.0 * spec.wheel_radius_m / 2.01, 1e-15);
}

void ExpectInvalid(const PhysicalDeviation& d, const std::string& field) {
  try {
    d.Validate();
    ADD_FAILURE() << "expected " << field << " to be rejected";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
  }
}

TEST(PhysicalDeviationTest, ValidateNamesTheField) {
  EXPECT_NO_THROW(PhysicalDeviation{}.Validate());
  ExpectInvalid({.wheel_diameter_ratio = 0.0}, "wheel_diameter_ratio");
  ExpectInvalid({.wheel_diameter_ratio = -1.0}, "wheel_diameter_ratio");
  ExpectInvalid({.track_ratio = 3.0}, "track_ratio");
  ExpectInvalid({.track_ratio = std::nan("")}, "track_ratio");
  EXPECT_THROW(DeviatedWheelGeometry(robot::P3dxSpec(), {.track_ratio = 0.1}),
               std::invalid_argument);
}

}  // namespace
}  // namespace plywood::sim
