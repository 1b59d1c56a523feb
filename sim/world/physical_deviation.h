#pragma once

#include "robot/drive/diff_drive_spec.h"
#include "sim/world/scene.h"

namespace plywood::sim {

// How the simulated robot's drive differs from its nominal spec, in the two dimensionless ratios of
// Borenstein & Feng, "Measurement and correction of systematic odometry errors in mobile robots",
// IEEE Trans. Robotics and Automation 12(6), 1996 (UMBmark):
//   E_d = D_R / D_L          (unequal wheel diameters)
//   E_b = b_actual / b_nominal (wheelbase error)
// The robot's software keeps using the nominal spec, so these become systematic odometry errors.
struct PhysicalDeviation {
  double wheel_diameter_ratio = 1.0;  // E_d
  double track_ratio = 1.0;           // E_b

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// The as-built wheel geometry: the mean wheel diameter stays nominal (as in Borenstein & Feng's
// eq. for D_R and D_L), D_R = 2 D E_d / (E_d + 1), D_L = 2 D / (E_d + 1), and b = E_b b_nominal.
// Apply it with Scene::SetWheelGeometry.
// @throws std::invalid_argument when `deviation` or `nominal` is invalid.
WheelGeometry DeviatedWheelGeometry(const robot::DiffDriveSpec& nominal,
                                    const PhysicalDeviation& deviation);

}  // namespace plywood::sim
