#include "perception/sonar_map/line_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

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

// A lab's own points (docs/errors.md, the s64 fifty-third pass): each bad number refused by name.
TEST(ChiSquareLineFitTest, APointOrSigmaThatIsNotAFiniteNumberIsRefusedByIndex) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto expect_refused = [](const std::vector<double>& x, const std::vector<double>& y,
                                 const std::vector<double>& sigma, const std::string& message) {
    try {
      ChiSquareLineFit(x, y, sigma);
      ADD_FAILURE() << "no exception, expected " << message;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  };
  // Was: a = b = NaN, no error.
  expect_refused({0, 1, 2}, {0, nan, 2}, {1, 1, 1}, "y[1]: must be finite, got nan");
  // Was: "all points share one x".
  expect_refused({0, 1, nan}, {0, 1, 2}, {1, 1, 1}, "x[2]: must be finite, got nan");
  expect_refused({0, inf, 2}, {0, 1, 2}, {1, 1, 1}, "x[1]: must be finite, got inf");
  expect_refused({0, 1, 2}, {0, 1, 2}, {inf, inf, inf},
                 "sigma[0]: must be a finite number > 0, got inf");
  expect_refused({0, 1, 2}, {0, 1, 2}, {1, nan, 1},
                 "sigma[1]: must be a finite number > 0, got nan");
}

}  // namespace
}  // namespace plywood::perception
