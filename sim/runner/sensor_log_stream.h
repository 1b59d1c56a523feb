#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"

namespace plywood::sim {

// The bodies of a run's largest append-only sensor logs (laser.log's scan lines, laser_hits.csv's
// rows, sonar.csv's rows), formatted while the run goes on; WriteRunOutputs writes them instead of
// formatting the same records after the run. Each body covers the first `*_records` records.
struct FormattedSensorLogs {
  std::size_t laser_records = 0;
  std::string laser_log;   // empty unless laser.log is written (laser, output.sensor_logs)
  std::string laser_hits;  // empty unless laser_hits.csv is written
  std::size_t sonar_records = 0;
  std::string sonar;  // empty unless sonar.csv is written
  bool laser_log_given = false, laser_hits_given = false, sonar_given = false;
};

// Formats the records a run appends on a thread of its own, so that after the last step only the
// last few are left to format (the snapshot's final frame needs the cores then:
// docs/performance.md, tenth round). Feed it from the thread that runs the ExperimentRunner,
// between steps (the runner's progress callback): it copies the records appended since the last
// call, so the run may go on appending. Records must not change once appended (ExperimentRunner
// never does).
class SensorLogStream {
 public:
  // Starts the thread when `config` writes any of the three logs (else Feed and Finish do nothing
  // but count).
  explicit SensorLogStream(const ExperimentConfig& config);
  // Stops the thread; what was formatted is dropped, errors are not reported.
  ~SensorLogStream();
  SensorLogStream(const SensorLogStream&) = delete;
  SensorLogStream& operator=(const SensorLogStream&) = delete;

  // Hands over copies of the records appended to `record` since the last call.
  // @throws std::logic_error when `record` has fewer laser scans or sonar rings than before.
  void Feed(const RunRecord& record);

  // Feeds the rest of `record`, waits until everything is formatted and returns it.
  // @pre called at most once. @throws what formatting threw (e.g. std::bad_alloc).
  FormattedSensorLogs Finish(const RunRecord& record);

  // True when the thread runs (the config writes at least one of the logs).
  bool active() const { return thread_.joinable(); }

 private:
  struct Batch {
    std::vector<LaserRecord> laser;
    std::vector<msgs::SonarRing> sonar;
  };
  void Work();
  void Format(const Batch& batch);

  double timestep_s_;
  FormattedSensorLogs logs_;  // written by the thread only, until it has been joined
  std::size_t fed_laser_ = 0, fed_sonar_ = 0;  // the feeding thread's counts
  std::mutex mutex_;
  std::condition_variable fed_;
  std::vector<Batch> queue_;  // guarded by mutex_
  bool finished_ = false;     // guarded by mutex_: no more batches
  bool cancelled_ = false;    // guarded by mutex_: drop the rest
  bool finish_called_ = false;
  std::exception_ptr error_;
  std::thread thread_;  // last: starts once everything above exists
};

}  // namespace plywood::sim
