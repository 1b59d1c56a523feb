// CARMEN logs (perception/logs/carmen_log.h), plain or gzip, strict and with skip_bad: every scan
// read has finite, non-negative ranges, a positive finite maximum range and finite poses.
#include <cmath>

#include "fuzz/fuzz_support.h"
#include "fuzz/fuzz_target.h"
#include "perception/logs/carmen_log.h"

namespace plywood::fuzz {
namespace {

bool Finite(const msgs::Pose2D& pose) {
  return std::isfinite(pose.x_m) && std::isfinite(pose.y_m) && std::isfinite(pose.theta_rad);
}

void CheckLog(const perception::CarmenLog& log) {
  Require(!log.lasers.empty(), "a log without scans was accepted");
  for (const perception::CarmenLaserRecord& record : log.lasers) {
    const msgs::LaserScan& scan = record.scan;
    Require(!scan.ranges_m.empty(), "a scan without beams");
    Require(record.line_number > 0, "a scan without its line number");
    Require(std::isfinite(scan.range_max_m) && scan.range_max_m > 0.0,
            "a scan without a positive finite maximum range");
    Require(std::isfinite(scan.angle_min_rad) && std::isfinite(scan.angle_increment_rad) &&
                std::isfinite(scan.time_s),
            "a scan with a non-finite angle or time");
    for (double r : scan.ranges_m) Require(std::isfinite(r) && r >= 0.0, "a bad range");
    Require(Finite(record.X_WL) && Finite(record.X_WR_odom), "a non-finite pose");
  }
}

void FuzzCarmenLog(std::span<const std::uint8_t> data) {
  const std::filesystem::path path = WriteScratchFile("fuzz.log", data);
  for (const bool skip_bad : {false, true}) {
    try {
      CheckLog(perception::ReadCarmenLog(path, {.skip_bad = skip_bad}));
    } catch (const std::runtime_error& e) {
      RequireCleanError(e, path.string());
    }
  }
}

}  // namespace
}  // namespace plywood::fuzz

PLYWOOD_FUZZ_TARGET("carmen_log", plywood::fuzz::FuzzCarmenLog)
