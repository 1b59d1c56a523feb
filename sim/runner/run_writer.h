#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/sensor_log_stream.h"

namespace plywood::sim {

// Writes a finished run to `dir` (created if needed) in the formats of docs/run_outputs.md:
// config.yaml, trajectory.csv, trajectory.<truth|estimator>.tum, metrics.json, walls.csv, with
// output.sensor_logs laser.log (CARMEN FLASER), laser_hits.csv, sonar.csv, ir_ring.csv,
// ir_scanner.csv, encoders.csv, gyro.csv, bumpers.csv, and with a lines: section laser_hits.csv
// and laser_scans.csv (what `plywood score lines` rebuilds each scan's truth from). Numbers are
// written in shortest round-trip form, so equal runs give equal bytes. Returns the names of the
// files written. `formatted` (optional: SensorLogStream::Finish's, for this record) holds
// laser.log's, laser_hits.csv's and sonar.csv's lines already formatted; a body that does not
// cover all of the record's scans or rings is formatted afresh. @throws std::runtime_error naming
// a file it cannot write.
std::vector<std::string> WriteRunOutputs(const ExperimentConfig& config, const RunRecord& record,
                                         const std::filesystem::path& dir,
                                         const FormattedSensorLogs* formatted = nullptr);

}  // namespace plywood::sim
