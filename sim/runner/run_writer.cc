#include "sim/runner/run_writer.h"

#include <charconv>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "perception/logs/carmen_log.h"
#include "perception/logs/tum_trajectory.h"
#include "sim/runner/file_writer.h"
#include "sim/runner/metrics.h"
#include "sim/runner/sensor_log_lines.h"

namespace plywood::sim {
namespace {

// One output file, checked when it goes out of scope: a failed write ends the run naming the
// file and the OS's reason.
class OutputFile {
 public:
  OutputFile(const std::filesystem::path& dir, const std::string& name,
             std::vector<std::string>* written)
      : file_(dir / name) {
    written->push_back(name);
  }
  ~OutputFile() noexcept(false) {
    if (std::uncaught_exceptions() == 0) file_.Close();
  }
  std::ostream& out() { return file_.out(); }

 private:
  FileWriter file_;
};

std::string N(double value) { return FormatNumber(value); }

// The header, then the rows (`rows`: already formatted, else from `rings`).
void WriteRing(std::ostream& out, const std::vector<msgs::RangeRing>& rings, double timestep_s,
               const std::string* rows) {
  // time_s, then one column per transducer: the range, or empty for no echo.
  out << "time_s";
  const std::size_t count = rings.empty() ? 0 : rings.front().readings.size();
  for (std::size_t i = 0; i < count; ++i) out << ",range_" << i << "_m";
  out << '\n';
  if (rows != nullptr) {
    out << *rows;
    return;
  }
  for (const auto& ring : rings) WriteRingLine(out, ring, timestep_s);
}

}  // namespace

std::vector<std::string> WriteRunOutputs(const ExperimentConfig& config, const RunRecord& record,
                                         const std::filesystem::path& dir,
                                         const FormattedSensorLogs* formatted) {
  std::filesystem::create_directories(dir);
  std::vector<std::string> written;
  // Times at the timestep's precision ("0.1", not the clock's running sum 0.10000000000000007).
  const double timestep_s = config.physics.timestep_s;
  const auto time = [timestep_s](double t) { return TimeAtStepPrecision(t, timestep_s); };
  const auto T = [&time](double t) { return FormatNumber(time(t)); };
  const bool laser_formatted = formatted && formatted->laser_records == record.laser.size();
  const bool sonar_formatted =
      formatted && formatted->sonar_given && formatted->sonar_records == record.sonar.size();
  OutputFile(dir, "config.yaml", &written).out() << ExperimentConfigToYaml(config);
  {
    OutputFile file(dir, "trajectory.csv", &written);
    std::ostream& out = file.out();
    out << "time_s,truth_x_m,truth_y_m,truth_theta_rad";
    for (const auto& name : record.estimator_names) {
      out << ',' << name << "_x_m," << name << "_y_m," << name << "_theta_rad";
    }
    out << '\n';
    for (const auto& sample : record.trajectory) {
      out << T(sample.time_s) << ',' << N(sample.truth.x_m) << ',' << N(sample.truth.y_m) << ','
          << N(sample.truth.theta_rad);
      for (const auto& e : sample.estimates) {
        out << ',' << N(e.x_m) << ',' << N(e.y_m) << ',' << N(e.theta_rad);
      }
      out << '\n';
    }
  }
  // The same poses as TUM files, one per trajectory, for tools in any language.
  for (std::size_t e = 0; e <= record.estimator_names.size(); ++e) {
    const std::string name = e == 0 ? "truth" : record.estimator_names[e - 1];
    OutputFile file(dir, "trajectory." + name + ".tum", &written);
    file.out() << "# " << name
               << ": timestamp tx ty tz qx qy qz qw (TUM); heading = 2 atan2(qz, qw) exactly\n";
    for (const auto& sample : record.trajectory) {
      perception::WriteTumPose(file.out(), time(sample.time_s),
                               e == 0 ? sample.truth : sample.estimates[e - 1]);
    }
  }
  OutputFile(dir, "metrics.json", &written).out() << record.metrics.ToJson();
  {
    OutputFile file(dir, "walls.csv", &written);
    file.out() << "segment,geom_id,face,ax_m,ay_m,bx_m,by_m\n";
    for (std::size_t i = 0; i < record.walls.segments.size(); ++i) {
      const WallSegment& s = record.walls.segments[i];
      file.out() << i << ',' << s.geom_id << ',' << s.face_index << ',' << N(s.a.x()) << ','
                 << N(s.a.y()) << ',' << N(s.b.x()) << ',' << N(s.b.y()) << '\n';
    }
  }
  if (config.sensors.laser && config.output.sensor_logs) {
    OutputFile log(dir, "laser.log", &written);
    if (record.laser.empty() || perception::IsFlaserScan(record.laser.front().scan)) {
      log.out()
          << "# Plywood simulated laser log, CARMEN FLASER format: x y theta is the true laser\n"
             "# pose, odom_x odom_y odom_theta the encoder-odometry laser pose.\n";
    } else {
      // A FLASER reader would place these beams elsewhere (perception::FlaserAngleIncrementRad),
      // or (400 / 401 beams) take them for another fan: ROBOTLASER1 says where they point.
      log.out()
          << (perception::FlaserCountIsAmbiguous(record.laser.front().scan.ranges_m.size())
                  ? "# Plywood simulated laser log, CARMEN ROBOTLASER1 format (FLASER readers "
                    "take\n# 400 or 401 beams for a 100 deg fan): "
                  : "# Plywood simulated laser log, CARMEN ROBOTLASER1 format (the fov is "
                    "not 180\n# deg): ")
          << "laser_pose is the true laser pose, robot_pose the encoder-odometry\n"
             "# laser pose.\n";
    }
    if (!record.laser.empty()) {
      perception::WriteCarmenParam(log.out(), "front_laser_max",
                                   N(record.laser.front().scan.range_max_m));
      perception::WriteCarmenParam(log.out(), "robot_frontlaser_offset",
                                   N(record.laser.front().scan.X_RS.x_m));
    }
    if (laser_formatted && formatted->laser_log_given) {
      log.out() << formatted->laser_log;
    } else {
      for (const auto& laser : record.laser) WriteLaserLogLine(log.out(), laser);
    }
  }
  // With a lines: section, the scans at full precision (laser.log keeps millimetres and
  // micro-radians) and their hits: `plywood score lines` rebuilds every scan's truth from them.
  const bool lines_truth = config.sensors.laser && config.lines.given;
  if (config.sensors.laser && (config.output.sensor_logs || lines_truth)) {
    OutputFile hits(dir, "laser_hits.csv", &written);
    // time_s, then per beam the walls.csv segment it hit (-1: none).
    hits.out() << "time_s";
    const std::size_t beams =
        record.laser.empty() ? 0 : record.laser.front().hit_segment_ids.size();
    for (std::size_t i = 0; i < beams; ++i) hits.out() << ",beam_" << i << "_segment";
    hits.out() << '\n';
    if (laser_formatted && formatted->laser_hits_given) {
      hits.out() << formatted->laser_hits;
    } else {
      std::string line;  // one write per scan: per-id stream insertion cost more than the scan
      for (const auto& laser : record.laser) {
        line.clear();
        AppendLaserHitsLine(line, laser, timestep_s);
        hits.out() << line;
      }
    }
  }
  if (lines_truth) {
    OutputFile file(dir, "laser_scans.csv", &written);
    file.out() << "time_s,sensor_x_m,sensor_y_m,sensor_theta_rad,angle_min_rad,"
                  "angle_increment_rad,range_min_m,range_max_m";
    const std::size_t beams = record.laser.empty() ? 0 : record.laser.front().scan.ranges_m.size();
    for (std::size_t i = 0; i < beams; ++i) file.out() << ",range_" << i << "_m";
    file.out() << '\n';
    for (const auto& laser : record.laser) {
      const msgs::LaserScan& scan = laser.scan;
      const msgs::Pose2D X_WS = laser.X_WR_truth * scan.X_RS;
      file.out() << T(scan.time_s) << ',' << N(X_WS.x_m) << ',' << N(X_WS.y_m) << ','
                 << N(X_WS.theta_rad) << ',' << N(scan.angle_min_rad) << ','
                 << N(scan.angle_increment_rad) << ',' << N(scan.range_min_m) << ','
                 << N(scan.range_max_m);
      for (double r : scan.ranges_m) file.out() << ',' << N(r);
      file.out() << '\n';
    }
  }
  if (!config.output.sensor_logs) return written;
  if (config.sensors.sonar)
    WriteRing(OutputFile(dir, "sonar.csv", &written).out(), record.sonar, timestep_s,
              sonar_formatted ? &formatted->sonar : nullptr);
  if (config.sensors.ir_ring) {
    WriteRing(OutputFile(dir, "ir_ring.csv", &written).out(), record.ir_ring, timestep_s, nullptr);
  }
  if (config.sensors.ir_scanner) {
    OutputFile file(dir, "ir_scanner.csv", &written);
    file.out() << "time_s,angle_min_rad,angle_increment_rad,range_max_m";
    const std::size_t beams =
        record.ir_scanner.empty() ? 0 : record.ir_scanner.front().scan.ranges_m.size();
    for (std::size_t i = 0; i < beams; ++i) file.out() << ",range_" << i << "_m";
    file.out() << '\n';
    for (const auto& ir : record.ir_scanner) {
      const msgs::LaserScan& scan = ir.scan;
      file.out() << T(scan.time_s) << ',' << N(scan.angle_min_rad) << ','
                 << N(scan.angle_increment_rad) << ',' << N(scan.range_max_m);
      for (double r : scan.ranges_m) file.out() << ',' << N(r);
      file.out() << '\n';
    }
  }
  if (config.sensors.encoders) {
    OutputFile file(dir, "encoders.csv", &written);
    file.out() << "time_s,left_ticks,right_ticks\n";
    for (const auto& e : record.encoders) {
      file.out() << T(e.time_s) << ',' << e.left_ticks << ',' << e.right_ticks << '\n';
    }
  }
  if (config.sensors.gyro) {
    OutputFile file(dir, "gyro.csv", &written);
    file.out() << "time_s,yaw_rate_rad_s\n";
    for (const auto& g : record.gyro)
      file.out() << T(g.time_s) << ',' << N(g.yaw_rate_rad_s) << '\n';
  }
  if (config.sensors.bumpers) {
    OutputFile file(dir, "bumpers.csv", &written);
    file.out() << "time_s,pressed_panels\n";
    for (const auto& b : record.bumpers) {
      file.out() << T(b.time_s) << ',';
      bool first = true;
      for (std::size_t i = 0; i < b.pressed.size(); ++i) {
        if (!b.pressed[i]) continue;
        file.out() << (first ? "" : " ") << i;
        first = false;
      }
      file.out() << '\n';
    }
  }
  return written;
}

}  // namespace plywood::sim
