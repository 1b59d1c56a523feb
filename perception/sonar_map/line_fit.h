#pragma once

#include <vector>

namespace plywood::perception {

// Straight-line fit y = a + b x by minimising chi^2 = sum ((y_i - a - b x_i) / sigma_i)^2
// (Numerical Recipes 15.2, routine `fit`), as seed 001 fits boundary points. sigma_a and sigma_b
// are the standard uncertainties of the parameters.
struct LineFit {
  double a = 0.0;
  double b = 0.0;
  double sigma_a = 0.0;
  double sigma_b = 0.0;
  double chi2 = 0.0;
};

// @throws std::invalid_argument for fewer than 2 points, mismatched sizes, an x or y that is not
// finite, a sigma that is not a finite number > 0 (each naming its index and value), or all x
// equal (a vertical line: fit x = a + b y instead).
LineFit ChiSquareLineFit(const std::vector<double>& x, const std::vector<double>& y,
                         const std::vector<double>& sigma);

}  // namespace plywood::perception
