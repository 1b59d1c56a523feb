#pragma once

#include <ostream>
#include <string>

#include "msgs/range_ring.h"
#include "sim/runner/experiment_runner.h"

namespace plywood::sim {

// One record's line of each append-only sensor log, shared by WriteRunOutputs and
// SensorLogStream so that a log formatted during the run and one formatted after it have the same
// bytes. `timestep_s` is the run's physics step (times are written at its precision).

// laser.log: the scan as CARMEN FLASER / ROBOTLASER1 at the true and the odometry laser pose.
void WriteLaserLogLine(std::ostream& out, const LaserRecord& laser);

// laser_hits.csv: time_s, then the walls.csv segment each beam hit (-1: none); appended to `line`.
void AppendLaserHitsLine(std::string& line, const LaserRecord& laser, double timestep_s);

// sonar.csv / ir_ring.csv: time_s, then one column per transducer, the range or empty.
void WriteRingLine(std::ostream& out, const msgs::RangeRing& ring, double timestep_s);

}  // namespace plywood::sim
