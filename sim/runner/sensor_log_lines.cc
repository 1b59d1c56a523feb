#include "sim/runner/sensor_log_lines.h"

#include <charconv>

#include "perception/logs/carmen_log.h"
#include "sim/runner/format_number.h"

namespace plywood::sim {

void WriteLaserLogLine(std::ostream& out, const LaserRecord& laser) {
  perception::CarmenLaserRecord carmen;
  carmen.scan = laser.scan;
  carmen.X_WL = laser.X_WR_truth * laser.scan.X_RS;
  carmen.X_WR_odom = laser.X_WR_odometry * laser.scan.X_RS;
  perception::WriteCarmenLaser(out, carmen);
}

void AppendLaserHitsLine(std::string& line, const LaserRecord& laser, double timestep_s) {
  line += FormatNumber(TimeAtStepPrecision(laser.scan.time_s, timestep_s));
  for (int id : laser.hit_segment_ids) {
    char number[16];
    line += ',';
    line.append(number, std::to_chars(number, number + sizeof(number), id).ptr);
  }
  line += '\n';
}

void WriteRingLine(std::ostream& out, const msgs::RangeRing& ring, double timestep_s) {
  out << FormatNumber(TimeAtStepPrecision(ring.time_s, timestep_s));
  for (const auto& reading : ring.readings) {
    out << ',';
    if (reading.echo) out << FormatNumber(reading.range_m);
  }
  out << '\n';
}

}  // namespace plywood::sim
