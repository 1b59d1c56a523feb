#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "msgs/laser_scan.h"
#include "msgs/pose2d.h"

namespace plywood::perception {

// One FLASER line (a 180-degree scan starting at -90 deg) or ROBOTLASER1 line (any start and
// spacing, its own maximum range). FLASER: with the laser's pose in the world and the
// robot's odometry pose. Beams are spread as pi / (n - 1), so 361 beams are the LMS 200's 0.5 deg.
struct CarmenLaserRecord {
  msgs::LaserScan scan;
  msgs::Pose2D X_WL;       // laser pose (corrected, or ground truth in simulated logs)
  msgs::Pose2D X_WR_odom;  // odometry pose as logged
  std::size_t line_number = 0;
};

// What a CARMEN log held that Plywood uses: front laser scans and PARAM values.
struct CarmenLog {
  std::vector<CarmenLaserRecord> lasers;
  std::map<std::string, std::string> params;
  std::size_t skipped_lines = 0;  // malformed lines passed over with skip_bad
};

struct CarmenReadOptions {
  // Maximum range used when a log gives no PARAM front_laser_max: the largest range in the log.
  bool skip_bad = false;
};

// Reads a CARMEN text log, plain or gzip-compressed (by content, not by name). Unknown message
// types, NEFF and # comments are skipped.
// @throws std::runtime_error "FILE:LINE: message" on a malformed FLASER/ROBOTLASER1/PARAM line
// unless options.skip_bad, on corrupt or truncated gzip data, "FILE: message" when the file
// cannot be read or holds no usable laser scan.
CarmenLog ReadCarmenLog(const std::filesystem::path& path, const CarmenReadOptions& options = {});

// Parses one line; exposed for tests and fuzzing. Returns false for lines Plywood ignores.
// @throws std::runtime_error "message" (no file or line prefix) on a malformed line.
bool ParseCarmenLine(const std::string& line, CarmenLog* log);

// Writes one laser line for `record` (timestamps from record.scan.time_s, hostname "plywood"):
// FLASER when the scan starts at -90 deg at FlaserAngleIncrementRad's step (all FLASER can say),
// else ROBOTLASER1, which carries the start angle and spacing (the laser pose as its laser pose,
// X_WR_odom as its robot pose). Ranges at or beyond range_max_m are written as range_max_m, as a
// real LMS 200 reports them.
void WriteCarmenLaser(std::ostream& out, const CarmenLaserRecord& record);

// True when WriteCarmenLaser writes `scan` as FLASER.
bool IsFlaserScan(const msgs::LaserScan& scan);

// True for the FLASER beam counts readers take for different fans (400 / 401 beams: CARMEN's own
// reader a 100 deg scan at 0.25 deg, others 180 deg at 0.45 deg): ReadCarmenLog refuses such
// lines, WriteCarmenLaser writes such scans as ROBOTLASER1.
bool FlaserCountIsAmbiguous(std::size_t beams);

// The spacing CARMEN's readers give a FLASER line of `beams` beams, from -90 deg: 1 and 0.5 deg
// for 180 and 360 beams (a SICK's 181 and 361 with the last dropped), 180 / (beams - 1) deg
// otherwise. ReadCarmenLog places the beams so and WriteCarmenLaser writes FLASER only for it.
double FlaserAngleIncrementRad(std::size_t beams);

// Writes a PARAM line.
void WriteCarmenParam(std::ostream& out, const std::string& name, const std::string& value);

}  // namespace plywood::perception
