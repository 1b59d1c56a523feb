#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "msgs/pose2d.h"
#include "msgs/range_ring.h"

namespace plywood::perception {

// The real 8-sonar log of ../shared/data/sonar8 (udacity/RoboND-OccupancyGridMappingAlgorithm):
// measurement.txt `timestamp r1..r8` in mm (5110 = no echo), poses.txt `timestamp x y theta` in mm
// and tenths of a degree. Bearings -90, -37.5, -22.5, -7.5, 7.5, 22.5, 37.5, 90 deg; usable range
// 170-5000 mm. Transducers are placed on the axis through the robot centre (the log gives no
// offsets).
struct Sonar8Record {
  msgs::Pose2D X_WR;
  msgs::RangeRing ring;
};

// @throws std::runtime_error "<file>: line N: <what>" for a malformed line, a missing file, or
// mismatched timestamps or line counts between the two files.
std::vector<Sonar8Record> LoadSonar8Log(const std::filesystem::path& folder);

}  // namespace plywood::perception
