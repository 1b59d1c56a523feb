#include "robot/odometry/odometry_increments.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"
#include "robot/drive/diff_drive_kinematics.h"

namespace plywood::robot {
namespace {

void RequireRatio(const char* field, double value) {
  if (!std::isfinite(value) || value < 0.5 || value > 2.0) {
    throw std::invalid_argument(std::string(field) + ": must be a ratio in [0.5, 2], got " +
                                msgs::ShortestNumber(value));
  }
}

}  // namespace

void OdometryCalibration::Validate() const {
  RequireRatio("wheel_diameter_ratio", wheel_diameter_ratio);
  RequireRatio("track_ratio", track_ratio);
}

OdometryGeometry CalibratedGeometry(const DiffDriveSpec& nominal,
                                    const OdometryCalibration& calibration) {
  nominal.Validate();
  calibration.Validate();
  const double e_d = calibration.wheel_diameter_ratio;
  return {.left_wheel_radius_m = nominal.wheel_radius_m * 2.0 / (e_d + 1.0),
          .right_wheel_radius_m = nominal.wheel_radius_m * 2.0 * e_d / (e_d + 1.0),
          .track_m = nominal.track_m * calibration.track_ratio,
          .ticks_per_rev = nominal.encoder_ticks_per_rev};
}

std::string_view ToString(Integration integration) {
  return integration == Integration::kArc ? "arc" : "midpoint";
}

Integration ParseIntegration(std::string_view text) {
  if (text == "midpoint") return Integration::kMidpoint;
  if (text == "arc") return Integration::kArc;
  throw std::invalid_argument("integration: expected midpoint or arc, got '" + std::string(text) +
                              "'");
}

void IncrementOptions::Validate() const {
  if (!std::isfinite(dead_band_rad) || dead_band_rad < 0.0 || dead_band_rad > 0.5) {
    throw std::invalid_argument("dead_band_rad: must be in [0, 0.5], got " +
                                msgs::ShortestNumber(dead_band_rad));
  }
  // Above 2^62 the modulus no longer fits the signed arithmetic of a delta (2^64 - 1 was cast to
  // -1, and every delta became 0).
  if (counter_modulus != 0 && (counter_modulus < 4 || counter_modulus > (std::uint64_t{1} << 62))) {
    throw std::invalid_argument("counter_modulus: must be 0 (no wrap) or in [4, 2^62], got " +
                                std::to_string(counter_modulus));
  }
}

msgs::Pose2D Integrate(Integration integration, const msgs::Pose2D& X_WR, double ds_m,
                       double dtheta_rad) {
  return integration == Integration::kArc ? IntegrateArc(X_WR, ds_m, dtheta_rad)
                                          : IntegrateMidpoint(X_WR, ds_m, dtheta_rad);
}

IncrementSource::IncrementSource(const OdometryGeometry& geometry, const IncrementOptions& options,
                                 bool uses_gyro)
    : geometry_(geometry), options_(options), uses_gyro_(uses_gyro) {
  options_.Validate();
  if (!(geometry_.left_wheel_radius_m > 0.0) || !(geometry_.right_wheel_radius_m > 0.0) ||
      !(geometry_.track_m > 0.0) || geometry_.ticks_per_rev <= 0) {
    throw std::invalid_argument("geometry: wheel radii, track and ticks_per_rev must be > 0");
  }
}

std::int64_t IncrementSource::Delta(const char* field, std::int64_t from, std::int64_t to) const {
  // A counter that has not wrapped never jumps by 2^31 ticks in one reading (at 1000 ticks per
  // revolution, 10^6 wheel turns): only an int32 counter's wrap read without counter_modulus, or
  // garbage, does. Refused rather than integrated as kilometres of travel.
  constexpr std::int64_t kLargestJump = std::int64_t{1} << 31;
  std::int64_t delta = 0;
  if (__builtin_sub_overflow(to, from, &delta) ||
      (options_.counter_modulus == 0 && (delta >= kLargestJump || delta <= -kLargestJump))) {
    throw std::invalid_argument(std::string(field) + ": jumped from " + std::to_string(from) +
                                " to " + std::to_string(to) +
                                " in one reading; a wrapping counter needs counter_modulus");
  }
  if (options_.counter_modulus == 0) return delta;
  // The counter wrapped if the raw difference exceeds half its range: take the short way round.
  const auto modulus = static_cast<std::int64_t>(options_.counter_modulus);
  delta %= modulus;
  if (delta > modulus / 2) delta -= modulus;
  if (delta < -modulus / 2) delta += modulus;
  return delta;
}

double IncrementSource::DeadBand(double value) const {
  return std::abs(value) < options_.dead_band_rad ? 0.0 : value;
}

void IncrementSource::AddEncoders(const msgs::WheelEncoders& encoders) {
  // A reading without a time, or not after the previous one (a repeated or backward timestamp),
  // is dropped: the counts are cumulative, so the next good reading carries its motion.
  if (!std::isfinite(encoders.time_s) || (previous_ && !(encoders.time_s > previous_->time_s))) {
    return;
  }
  if (previous_) {
    const double radians_per_tick = 2.0 * std::numbers::pi / geometry_.ticks_per_rev;
    const double left_rad = DeadBand(
        radians_per_tick * Delta("left_ticks", previous_->left_ticks, encoders.left_ticks));
    const double right_rad = DeadBand(
        radians_per_tick * Delta("right_ticks", previous_->right_ticks, encoders.right_ticks));
    OdometryIncrement increment;
    increment.start_s = previous_->time_s;
    increment.end_s = encoders.time_s;
    increment.left_m = geometry_.left_wheel_radius_m * left_rad;
    increment.right_m = geometry_.right_wheel_radius_m * right_rad;
    increment.ds_m = (increment.left_m + increment.right_m) / 2.0;
    increment.dtheta_encoder_rad =
        DeadBand((increment.right_m - increment.left_m) / geometry_.track_m);
    pending_.push_back(increment);
  }
  previous_ = encoders;
}

void IncrementSource::AddGyro(const msgs::GyroRate& gyro) {
  if (!uses_gyro_) return;
  // A sample without a rate or a time is dropped: the next one reports the mean rate since the
  // last good one, so it covers the gap. Kept, a NaN made the integrated angle NaN for good.
  if (!std::isfinite(gyro.yaw_rate_rad_s) || !std::isfinite(gyro.time_s)) return;
  if (gyro_.empty()) {
    first_gyro_s_ = gyro.time_s;
    gyro_.push_back({gyro.time_s, 0.0});
  } else if (gyro.time_s > gyro_.back().time_s) {
    // The sample is the mean rate since the previous one.
    gyro_.push_back({gyro.time_s, gyro_.back().angle_rad +
                                      gyro.yaw_rate_rad_s * (gyro.time_s - gyro_.back().time_s)});
  } else {
    // A repeated or backward timestamp: dropped, and not counted either, or a driver that sends
    // every sample twice halved the sample period the EKF's gyro noise scales with.
    return;
  }
  ++gyro_samples_;
}

double IncrementSource::GyroAngleAt(double time_s) const {
  if (gyro_.empty() || time_s <= gyro_.front().time_s)
    return gyro_.empty() ? 0.0 : gyro_.front().angle_rad;
  for (std::size_t i = 1; i < gyro_.size(); ++i) {
    if (gyro_[i].time_s >= time_s) {
      const GyroPoint& a = gyro_[i - 1];
      const GyroPoint& b = gyro_[i];
      return a.angle_rad +
             (b.angle_rad - a.angle_rad) * (time_s - a.time_s) / (b.time_s - a.time_s);
    }
  }
  return gyro_.back().angle_rad;
}

std::optional<OdometryIncrement> IncrementSource::Next() {
  if (pending_.empty()) return std::nullopt;
  OdometryIncrement increment = pending_.front();
  if (uses_gyro_) {
    // Sensors sampled at the same instant may differ by rounding in their timestamps.
    constexpr double kTimeSlack_s = 1e-9;
    if (gyro_.empty() || gyro_.back().time_s < increment.end_s - kTimeSlack_s) return std::nullopt;
    increment.dtheta_gyro_raw_rad = GyroAngleAt(increment.end_s) - GyroAngleAt(increment.start_s);
    increment.dtheta_gyro_rad = DeadBand(increment.dtheta_gyro_raw_rad);
    increment.gyro_sample_period_s =
        gyro_samples_ > 1 ? (gyro_.back().time_s - first_gyro_s_) / (gyro_samples_ - 1) : 0.0;
    // Keep only the points still needed: the last one at or before this increment's end.
    while (gyro_.size() > 2 && gyro_[1].time_s <= increment.end_s) gyro_.pop_front();
  }
  pending_.pop_front();
  return increment;
}

}  // namespace plywood::robot
