#include "sim/runner/sensor_log_stream.h"

#include <sstream>
#include <stdexcept>
#include <utility>

#include "sim/runner/sensor_log_lines.h"
#include "sim/runner/start_thread.h"

namespace plywood::sim {

SensorLogStream::SensorLogStream(const ExperimentConfig& config)
    : timestep_s_(config.physics.timestep_s) {
  // The same conditions as WriteRunOutputs'.
  const bool laser = config.sensors.laser.has_value();
  logs_.laser_log_given = laser && config.output.sensor_logs;
  logs_.laser_hits_given = laser && (config.output.sensor_logs || config.lines.given);
  logs_.sonar_given = config.sensors.sonar.has_value() && config.output.sensor_logs;
  if (logs_.laser_log_given || logs_.laser_hits_given || logs_.sonar_given) {
    thread_ = StartThread("write the sensor logs", [this] { Work(); });
  }
}

SensorLogStream::~SensorLogStream() {
  {
    std::lock_guard lock(mutex_);
    cancelled_ = true;
  }
  fed_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void SensorLogStream::Feed(const RunRecord& record) {
  if (!active()) return;
  if (record.laser.size() < fed_laser_ || record.sonar.size() < fed_sonar_) {
    throw std::logic_error("SensorLogStream::Feed: records were removed, not appended");
  }
  Batch batch;
  if (logs_.laser_log_given || logs_.laser_hits_given) {
    batch.laser.assign(record.laser.begin() + static_cast<std::ptrdiff_t>(fed_laser_),
                       record.laser.end());
    fed_laser_ = record.laser.size();
  }
  if (logs_.sonar_given) {
    batch.sonar.assign(record.sonar.begin() + static_cast<std::ptrdiff_t>(fed_sonar_),
                       record.sonar.end());
    fed_sonar_ = record.sonar.size();
  }
  if (batch.laser.empty() && batch.sonar.empty()) return;
  {
    std::lock_guard lock(mutex_);
    queue_.push_back(std::move(batch));
  }
  fed_.notify_one();
}

FormattedSensorLogs SensorLogStream::Finish(const RunRecord& record) {
  if (finish_called_) throw std::logic_error("SensorLogStream::Finish: called twice");
  finish_called_ = true;
  if (!active()) return {};
  Feed(record);
  {
    std::lock_guard lock(mutex_);
    finished_ = true;
  }
  fed_.notify_one();
  thread_.join();
  if (error_) std::rethrow_exception(error_);
  return std::move(logs_);
}

void SensorLogStream::Work() {
  try {
    for (;;) {
      std::vector<Batch> batches;
      {
        std::unique_lock lock(mutex_);
        fed_.wait(lock, [this] { return !queue_.empty() || finished_ || cancelled_; });
        if (cancelled_) return;
        if (queue_.empty()) return;  // finished, everything formatted
        batches.swap(queue_);
      }
      for (const Batch& batch : batches) Format(batch);
    }
  } catch (...) {
    error_ = std::current_exception();
  }
}

void SensorLogStream::Format(const Batch& batch) {
  if (!batch.laser.empty()) {
    if (logs_.laser_log_given) {
      std::ostringstream out;
      for (const LaserRecord& laser : batch.laser) WriteLaserLogLine(out, laser);
      logs_.laser_log += std::move(out).str();
    }
    if (logs_.laser_hits_given) {
      for (const LaserRecord& laser : batch.laser) {
        AppendLaserHitsLine(logs_.laser_hits, laser, timestep_s_);
      }
    }
    logs_.laser_records += batch.laser.size();
  }
  if (!batch.sonar.empty()) {
    std::ostringstream out;
    for (const msgs::SonarRing& ring : batch.sonar) WriteRingLine(out, ring, timestep_s_);
    logs_.sonar += std::move(out).str();
    logs_.sonar_records += batch.sonar.size();
  }
}

}  // namespace plywood::sim
