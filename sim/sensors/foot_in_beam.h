#pragma once

namespace plywood::sim {

// A cheap pre-test of the sonar's foot condition -x / hypot(x, y) >= cos_half_angle (for a hit
// plane's normal (x, y) in the transducer frame, cos_half_angle > 0): false only when the condition
// cannot hold, i.e. when x >= 0 or x^2 < cos^2 (x^2 + y^2) by a 1e-9 margin, far above the < 1e-15
// rounding of hypot, the quotient and these products. Most hit planes face the transducer from
// outside its beam, and this spares them the hypot.
inline bool FootMayBeInBeam(double x, double y, double cos_half_angle) {
  return x < 0.0 && !(x * x < cos_half_angle * cos_half_angle * (x * x + y * y) * (1.0 - 1e-9));
}

}  // namespace plywood::sim
