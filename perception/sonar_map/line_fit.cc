#include "perception/sonar_map/line_fit.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"

namespace plywood::perception {

LineFit ChiSquareLineFit(const std::vector<double>& x, const std::vector<double>& y,
                         const std::vector<double>& sigma) {
  if (x.size() < 2) throw std::invalid_argument("x: need at least 2 points");
  if (y.size() != x.size() || sigma.size() != x.size())
    throw std::invalid_argument("y: x, y and sigma must have the same size");
  double S = 0, Sx = 0, Sy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    // A NaN or inf point made the fit NaN (y) or was called "all points share one x" (x).
    const auto where = [i](const char* field) { return field + ("[" + std::to_string(i) + "]"); };
    if (!std::isfinite(x[i]))
      throw std::invalid_argument(where("x") + ": must be finite, got " +
                                  msgs::ShortestNumber(x[i]));
    if (!std::isfinite(y[i]))
      throw std::invalid_argument(where("y") + ": must be finite, got " +
                                  msgs::ShortestNumber(y[i]));
    if (!(std::isfinite(sigma[i]) && sigma[i] > 0.0))
      throw std::invalid_argument(where("sigma") + ": must be a finite number > 0, got " +
                                  msgs::ShortestNumber(sigma[i]));
    const double w = 1.0 / (sigma[i] * sigma[i]);
    S += w;
    Sx += x[i] * w;
    Sy += y[i] * w;
  }
  // Numerical Recipes' centred form (t_i = (x_i - Sx/S) / sigma_i) avoids round-off.
  const double sxoss = Sx / S;
  double Stt = 0.0, b = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double t = (x[i] - sxoss) / sigma[i];
    Stt += t * t;
    b += t * y[i] / sigma[i];
  }
  if (!(Stt > 0.0)) throw std::invalid_argument("x: all points share one x; fit x = a + b y");
  LineFit fit;
  fit.b = b / Stt;
  fit.a = (Sy - Sx * fit.b) / S;
  fit.sigma_a = std::sqrt((1.0 + Sx * Sx / (S * Stt)) / S);
  fit.sigma_b = std::sqrt(1.0 / Stt);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = (y[i] - fit.a - fit.b * x[i]) / sigma[i];
    fit.chi2 += r * r;
  }
  return fit;
}

}  // namespace plywood::perception
