#include "sim/sensors/sensor_schedule.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"

namespace plywood::sim {
namespace {

bool Reached(double time_s, double target_s) {
  return time_s >= target_s - 1e-9 * std::max(1.0, std::abs(time_s));
}

}  // namespace

SensorSchedule::SensorSchedule(double rate_hz) : rate_hz_(rate_hz) {
  if (!(rate_hz > 0.0) || !std::isfinite(rate_hz)) {
    throw std::invalid_argument("rate_hz: must be a finite number > 0, got " +
                                msgs::ShortestNumber(rate_hz));
  }
}

bool SensorSchedule::Due(double time_s) {
  if (!Reached(time_s, NextTimeS())) return false;
  // Skip every sample whose time has already come: one sample per call at most.
  next_sample_ = std::max<std::int64_t>(
      next_sample_ + 1, static_cast<std::int64_t>(std::floor(time_s * rate_hz_)) + 1);
  while (Reached(time_s, NextTimeS())) ++next_sample_;
  return true;
}

}  // namespace plywood::sim
