#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "sim/raycast/ray_caster.h"
#include "sim/sensors/planar_scan.h"
#include "sim/sensors/scan_measurement.h"
#include "sim/world/scene.h"

namespace plywood::sim {

// The rotating infrared range finder of Skrzypczynski & Wozniak (1994): an LED emitter on a
// head turning in the horizontal plane, more accurate than sonar but given to single outliers. The
// paper publishes no figures, so every default here is an assumption: 200 steps per turn (a
// 1.8 deg stepper), 3 m reach, 5 mm Gaussian noise, 1% outliers, 2 turns per second. A full 360 deg
// turn has no repeated beam (beam i at -fov_deg/2 + i * resolution_deg); a partial fov includes
// both ends. The head is treated as sampling a whole turn at one instant (no motion skew). An
// outlier replaces a beam's range with one uniform in [range_min_m, range_max_m), whatever the beam
// hit; beams that hit nothing within range_max_m report range_max_m. Geoms whose material name
// starts with "ir_invisible" (glass, matt black panels: worlds/README.md) do not reflect the
// emitter's light: the beam passes them and reports what lies behind, while the sonar still hears
// them.
struct IrScannerOptions {
  double fov_deg = 360.0;
  double resolution_deg = 1.8;
  double range_min_m = 0.1;
  double range_max_m = 3.0;
  double sigma_m = 0.005;
  double outlier_probability = 0.01;
  bool noise_free = false;  // exact ranges, no noise, no outliers
  double rate_hz = 2.0;

  // @throws std::invalid_argument whose message starts with the offending field's name.
  void Validate() const;
  int BeamCount() const;
};

// Material-name prefix that makes a geom invisible to the IR scanner.
inline constexpr char kIrInvisiblePrefix[] = "ir_invisible";

// Per geom id: 1 when its material's name starts with kIrInvisiblePrefix.
std::vector<char> IrInvisibleGeoms(const mjModel* model);

class IrScannerSensor {
 public:
  // @throws ConfigError naming the robot and the site ("ir_scanner" on the Magellan Pro) when the
  //         robot has no such site; std::invalid_argument from options.Validate().
  IrScannerSensor(const Scene& scene, const std::string& site_name, const IrScannerOptions& options,
                  std::uint64_t seed);

  IrScannerSensor(const IrScannerSensor&) = delete;
  IrScannerSensor& operator=(const IrScannerSensor&) = delete;

  // One turn at the scene's current state, stamped with scene.time_s(); hit_geom_ids is -1 for
  // beams without a return and for outliers.
  ScanMeasurement Measure(const Scene& scene, const RayCaster& caster);
  void Measure(const Scene& scene, const RayCaster& caster, ScanMeasurement* out);

  const IrScannerOptions& options() const { return options_; }
  int site_id() const { return geometry_.site().id; }

 private:
  const IrScannerOptions options_;
  const PlanarScan geometry_;
  const std::vector<char> invisible_;  // by geom id
  std::mt19937_64 rng_;
};

}  // namespace plywood::sim
