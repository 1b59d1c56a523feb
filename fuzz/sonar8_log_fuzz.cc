// The 8-sonar log (perception/logs/sonar8_log.h): two files, measurement.txt then poses.txt,
// split at the input's first NUL byte. Every record read is finite.
#include <algorithm>
#include <cmath>

#include "fuzz/fuzz_support.h"
#include "fuzz/fuzz_target.h"
#include "perception/logs/sonar8_log.h"

namespace plywood::fuzz {
namespace {

void FuzzSonar8Log(std::span<const std::uint8_t> data) {
  const auto split = std::find(data.begin(), data.end(), std::uint8_t{0});
  const std::size_t first = static_cast<std::size_t>(split - data.begin());
  WriteScratchFile("measurement.txt", data.first(first));
  WriteScratchFile("poses.txt", data.subspan(std::min(first + 1, data.size())));
  const std::filesystem::path folder = ScratchFolder();
  try {
    for (const perception::Sonar8Record& record : perception::LoadSonar8Log(folder)) {
      Require(std::isfinite(record.X_WR.x_m) && std::isfinite(record.X_WR.y_m) &&
                  std::isfinite(record.X_WR.theta_rad),
              "a non-finite pose");
      for (const msgs::RangeReading& reading : record.ring.readings) {
        Require(std::isfinite(reading.range_m), "a non-finite range");
      }
    }
  } catch (const std::runtime_error& e) {
    RequireCleanError(e, folder.string());
  }
}

}  // namespace
}  // namespace plywood::fuzz

PLYWOOD_FUZZ_TARGET("sonar8_log", plywood::fuzz::FuzzSonar8Log)
