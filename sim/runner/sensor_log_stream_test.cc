// SensorLogStream: laser.log, laser_hits.csv and sonar.csv formatted on a thread during the run
// have the bytes WriteRunOutputs gives when it formats the finished record itself.

#include "sim/runner/sensor_log_stream.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>

#include "plywood_paths.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/run_writer.h"
#include "tests/support/cli_test_support.h"

namespace plywood::sim {
namespace {

ExperimentConfig Config(const std::string& extra) {
  const std::string yaml =
      "name: log_stream\nseed: 3\nduration_s: 6.35\nworld: worlds/office.xml\n"
      "robot: {model: p3dx, spawn: {x_m: -6.5, y_m: 0.0, theta_deg: 0}}\n"
      "controller: {type: wall_following, sensor: sonar, side: left, distance_m: 0.6}\n"
      "sensors:\n"
      "  laser: {resolution_deg: 0.5, range_max_m: 8, range_noise_sigma_m: 0.01, rate_hz: 10}\n"
      "  sonar: {rate_hz: 10}\n"
      "  encoders: {slip_sigma: 0.01}\n"
      "  gyro: {noise_sigma_rad_s: 0.002}\n"
      "  bumpers: {}\n" +
      extra;
  return ParseExperimentConfig(yaml, "inline", std::filesystem::path(PLYWOOD_SOURCE_ROOT));
}

std::map<std::string, std::string> Files(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    files[entry.path().filename().string()] = testing::Slurp(entry.path());
  }
  return files;
}

std::filesystem::path TempDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("plywood-sensor-log-stream-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

// Runs `config`, feeding the stream from the progress callback (every simulated second; the run
// ends 0.35 s after the last call, so Finish has records of its own to hand over).
void ExpectSameBytes(const ExperimentConfig& config, const std::string& name) {
  ExperimentRunner runner(config);
  SensorLogStream stream(config);
  runner.Run([&](double, double) { stream.Feed(runner.record()); });
  stream.Feed(runner.record());  // nothing new: no batch
  const FormattedSensorLogs formatted = stream.Finish(runner.record());
  if (config.sensors.laser && config.output.sensor_logs) {
    EXPECT_EQ(formatted.laser_records, runner.record().laser.size());
    EXPECT_FALSE(formatted.laser_log.empty());
  }
  const auto plain = TempDir(name + "-plain"), streamed = TempDir(name + "-streamed");
  WriteRunOutputs(config, runner.record(), plain);
  WriteRunOutputs(config, runner.record(), streamed, &formatted);
  const auto a = Files(plain), b = Files(streamed);
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [file, bytes] : a) {
    ASSERT_TRUE(b.count(file)) << file;
    EXPECT_TRUE(bytes == b.at(file)) << file << " differs";
  }
  std::filesystem::remove_all(plain);
  std::filesystem::remove_all(streamed);
}

TEST(SensorLogStreamTest, FormattedDuringTheRunGivesTheSameBytes) {
  ExpectSameBytes(Config(""), "default");
}

TEST(SensorLogStreamTest, WithoutSensorLogsNothingIsStreamedAndTheOutputsAgree) {
  const ExperimentConfig config = Config("output: {sensor_logs: false}\n");
  EXPECT_FALSE(SensorLogStream(config).active());
  ExpectSameBytes(config, "no-logs");
}

TEST(SensorLogStreamTest, ARecordThatGrewAfterFinishIsFormattedAfresh) {
  const ExperimentConfig config = Config("");
  ExperimentRunner runner(config);
  SensorLogStream stream(config);
  runner.Run([&](double, double) { stream.Feed(runner.record()); });
  RunRecord record = runner.record();
  const FormattedSensorLogs formatted = stream.Finish(record);
  ASSERT_GE(record.laser.size(), 2u);
  // One scan and one ring more than the stream saw: its bodies no longer cover the record.
  record.laser.push_back(record.laser.front());
  record.sonar.push_back(record.sonar.front());
  const auto plain = TempDir("grown-plain"), streamed = TempDir("grown-streamed");
  WriteRunOutputs(config, record, plain);
  WriteRunOutputs(config, record, streamed, &formatted);
  EXPECT_EQ(Files(plain), Files(streamed));
  std::filesystem::remove_all(plain);
  std::filesystem::remove_all(streamed);
}

TEST(SensorLogStreamTest, FinishTwiceIsAnErrorAndAnUnfinishedStreamStopsCleanly) {
  const ExperimentConfig config = Config("");
  RunRecord record;
  {
    SensorLogStream unfinished(config);
    EXPECT_TRUE(unfinished.active());
    unfinished.Feed(record);
  }  // destroyed without Finish: the thread stops, nothing hangs
  SensorLogStream stream(config);
  const FormattedSensorLogs empty = stream.Finish(record);
  EXPECT_EQ(empty.laser_records, 0u);
  EXPECT_TRUE(empty.laser_log.empty());
  EXPECT_THROW(stream.Finish(record), std::logic_error);
}

TEST(SensorLogStreamTest, RecordsRemovedAfterAFeedAreAnError) {
  const ExperimentConfig config = Config("");
  ExperimentRunner runner(config);
  runner.Run();
  RunRecord record = runner.record();
  ASSERT_FALSE(record.laser.empty());
  SensorLogStream stream(config);
  stream.Feed(record);
  record.laser.pop_back();
  EXPECT_THROW(stream.Feed(record), std::logic_error);
}

}  // namespace
}  // namespace plywood::sim
