#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string_view>

#include "msgs/gyro_rate.h"
#include "msgs/pose2d.h"
#include "msgs/wheel_encoders.h"
#include "robot/drive/diff_drive_spec.h"

namespace plywood::robot {

// A calibration of the drive's systematic errors in Borenstein & Feng's two ratios (UMBmark,
// 1996): the robot believes D_R / D_L = wheel_diameter_ratio (mean diameter unchanged) and a track
// of track_ratio * nominal. Identity by default; robot/calibration/umbmark.h computes it.
struct OdometryCalibration {
  double wheel_diameter_ratio = 1.0;  // E_d
  double track_ratio = 1.0;           // E_b

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// What dead reckoning uses: per-wheel radii, track and encoder resolution.
struct OdometryGeometry {
  double left_wheel_radius_m = 0.0;
  double right_wheel_radius_m = 0.0;
  double track_m = 0.0;
  int ticks_per_rev = 0;
};

// The nominal spec with a calibration applied: D_L = 2 D / (E_d + 1), D_R = 2 D E_d / (E_d + 1)
// (Borenstein & Feng's correction factors c_L, c_R), b = E_b b_nominal.
// @throws std::invalid_argument when either is invalid.
OdometryGeometry CalibratedGeometry(const DiffDriveSpec& nominal,
                                    const OdometryCalibration& calibration);

// How an increment becomes a pose change.
enum class Integration {
  kMidpoint,  // seed 004 eq. 3: x += ds cos(theta + dtheta/2); O(dtheta^2) short on arcs
  kArc,       // exact for a constant-curvature step (chord = ds sinc(dtheta/2))
};
std::string_view ToString(Integration integration);
// @throws std::invalid_argument starting with "integration" unless "midpoint" or "arc".
Integration ParseIntegration(std::string_view text);

// Options every dead-reckoning estimator shares.
struct IncrementOptions {
  // Seed 004's threshold: a wheel-angle change |dphi| or heading change |dtheta| below it (rad) is
  // taken as zero, "to avoid accumulating low errors". The seed used 0.01; 0 turns it off.
  double dead_band_rad = 0.0;
  // Width of the motor controller's tick counter, when it wraps (a 16-bit counter: 65536). Deltas
  // are then taken modulo it, assuming less than half a wrap per sample. 0: never wraps; a jump of
  // 2^31 ticks or more in one reading (an int32 counter's wrap) is then refused. At most 2^62.
  std::uint64_t counter_modulus = 0;
  Integration integration = Integration::kMidpoint;

  void Validate() const;
};

// Motion between two encoder readings, with the gyro's heading change over the same interval.
struct OdometryIncrement {
  double start_s = 0.0;
  double end_s = 0.0;
  double left_m = 0.0;  // wheel travel (after the dead band)
  double right_m = 0.0;
  double ds_m = 0.0;                  // (left + right) / 2
  double dtheta_encoder_rad = 0.0;    // (right - left) / track, after the dead band
  double dtheta_gyro_rad = 0.0;       // integral of the gyro's rate, after the dead band
  double dtheta_gyro_raw_rad = 0.0;   // the same without the dead band (for bias estimation)
  double gyro_sample_period_s = 0.0;  // mean spacing of the gyro samples seen so far
};

// Turns time-ordered encoder and gyro messages into increments over encoder intervals. With a gyro,
// an increment is released only once gyro samples cover its whole interval (a gyro sample reports
// the mean rate since the previous one; the integrated angle is interpolated linearly inside a
// sample), so the two sensors may run at different rates and arrive in either order.
class IncrementSource {
 public:
  IncrementSource(const OdometryGeometry& geometry, const IncrementOptions& options,
                  bool uses_gyro);

  // Hardware input: a reading whose time_s is not finite or not after the previous reading's is
  // dropped (the counts are cumulative: the next reading carries its motion); a jump only a wrap
  // explains throws std::invalid_argument "left_ticks: ..." / "right_ticks: ...".
  void AddEncoders(const msgs::WheelEncoders& encoders);
  // A sample whose rate or time is not finite, or whose time is not after the previous one's, is
  // dropped (the next one's mean rate covers the gap).
  void AddGyro(const msgs::GyroRate& gyro);
  // The next complete increment, oldest first.
  std::optional<OdometryIncrement> Next();

  const OdometryGeometry& geometry() const { return geometry_; }
  const IncrementOptions& options() const { return options_; }

 private:
  // @throws std::invalid_argument naming `field` for a jump only a wrap explains (see .cc).
  std::int64_t Delta(const char* field, std::int64_t from, std::int64_t to) const;
  double DeadBand(double value) const;
  // Integrated gyro angle at time_s; @pre gyro samples reach time_s.
  double GyroAngleAt(double time_s) const;

  OdometryGeometry geometry_;
  IncrementOptions options_;
  bool uses_gyro_;
  std::optional<msgs::WheelEncoders> previous_;
  std::deque<OdometryIncrement> pending_;  // encoder part filled, waiting for the gyro
  // Cumulative gyro angle at sample times: (time, angle).
  struct GyroPoint {
    double time_s;
    double angle_rad;
  };
  std::deque<GyroPoint> gyro_;
  double first_gyro_s_ = 0.0;
  long gyro_samples_ = 0;
};

// Advances X_WR by ds and dtheta with the chosen rule.
msgs::Pose2D Integrate(Integration integration, const msgs::Pose2D& X_WR, double ds_m,
                       double dtheta_rad);

}  // namespace plywood::robot
