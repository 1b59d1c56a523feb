#include "sim/sensors/foot_in_beam.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace plywood::sim {
namespace {

// The condition the pre-test guards, as SonarSensor::EchoRange evaluates it.
bool FootInBeam(double x, double y, double cos_half_angle) {
  const double foot_len = std::hypot(x, y);
  return foot_len > 1e-9 && -x / foot_len >= cos_half_angle;
}

// Never false where the condition holds (the same feet as without it), on normals of every
// direction, lengths and half angles, half of them within 1e-12 rad of the beam's edge; and false
// for nearly every normal of a random direction outside the beam (it spares hypot).
TEST(FootInBeamTest, FalseOnlyWhereTheFootConditionFails) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int in_beam = 0, outside_random = 0, spared_random = 0;
  for (const double half_deg : {0.0, 1e-6, 5.0, 15.0, 30.0, 45.0, 75.0, 89.9}) {
    const double half = half_deg * std::numbers::pi / 180.0, c = std::cos(half);
    for (int i = 0; i < 200000; ++i) {
      double a;
      if (i % 2 == 0) {  // near the edge of the beam
        a = (i % 4 == 0 ? 1.0 : -1.0) * half + 1e-12 * (2.0 * unit(rng) - 1.0) * (i % 8 < 4);
      } else {
        a = 2.0 * std::numbers::pi * unit(rng);
      }
      const double length = i % 3 == 0 ? 1.0 : std::pow(10.0, -12.0 + 13.0 * unit(rng));
      const double x = -length * std::cos(a), y = length * std::sin(a);
      const bool holds = FootInBeam(x, y, c), may = FootMayBeInBeam(x, y, c);
      ASSERT_TRUE(may || !holds) << "half " << half_deg << " deg, a " << a << ", x " << x << " y "
                                 << y;
      in_beam += holds;
      const bool random_long = i % 2 == 1 && length > 1e-8;  // not cut by foot_len > 1e-9
      outside_random += random_long && !holds;
      spared_random += random_long && !may;
    }
  }
  EXPECT_GT(in_beam, 100000);
  EXPECT_GT(spared_random, outside_random * 99 / 100);
}

}  // namespace
}  // namespace plywood::sim
