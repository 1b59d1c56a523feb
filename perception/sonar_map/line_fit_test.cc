#include "perception/sonar_map/line_fit.h"

#include <gtest/gtest.h>

#include <cmath>

namespace plywood::perception {
namespace {

TEST(ChiSquareLineFitTest, PointsOnAKnownLine) {
  // y = 2 + 0.5 x at x = 0..3, sigma 1: exact parameters, chi^2 = 0, and NR's uncertainties:
  // S = 4, Sx = 6, Stt = sum (x - 1.5)^2 = 5 -> sigma_b = 1/sqrt(5),
  // sigma_a = sqrt((1 + 36 / 20) / 4) = sqrt(0.7).
  const LineFit fit = ChiSquareLineFit({0, 1, 2, 3}, {2, 2.5, 3, 3.5}, {1, 1, 1, 1});
  EXPECT_NEAR(fit.a, 2.0, 1e-14);
  EXPECT_NEAR(fit.b, 0.5, 1e-14);
  EXPECT_NEAR(fit.chi2, 0.0, 1e-24);
  EXPECT_NEAR(fit.sigma_b, 1.0 / std::sqrt(5.0), 1e-14);
  EXPECT_NEAR(fit.sigma_a, std::sqrt(0.7), 1e-14);
}

TEST(ChiSquareLineFitTest, WeightsAndResiduals) {
  // y = {2, 0, 2} at x = -1, 0, 1 with sigma 2 gives b = 0, a = 4/3, chi^2 = ((2/3)^2 + (4/3)^2 +
  // (2/3)^2) / 4 = 2/3.
  const LineFit fit = ChiSquareLineFit({-1, 0, 1}, {2, 0, 2}, {2, 2, 2});
  EXPECT_NEAR(fit.b, 0.0, 1e-15);
  EXPECT_NEAR(fit.a, 4.0 / 3.0, 1e-15);
  EXPECT_NEAR(fit.chi2, 2.0 / 3.0, 1e-14);
}

TEST(ChiSquareLineFitTest, RejectsDegenerateInput) {
  EXPECT_THROW(ChiSquareLineFit({1}, {1}, {1}), std::invalid_argument);
  EXPECT_THROW(ChiSquareLineFit({1, 1}, {0, 2}, {1, 1}), std::invalid_argument);
  EXPECT_THROW(ChiSquareLineFit({0, 1}, {0, 2}, {1, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace plywood::perception
