#include "eval/score/run_laser_scans.h"

#include "eval/score/csv_table.h"
#include "eval/score/run_directory.h"
#include "sim/config/config_error.h"
#include "sim/runner/metrics.h"

namespace plywood::eval {

RunLaserScans LoadRunLaserScans(const std::filesystem::path& run_dir) {
  RunLaserScans out;
  const sim::ExperimentConfig config = LoadRunConfig(run_dir, "plywood score lines");
  out.lines = config.lines;
  const char* const kWhy = "written by runs whose experiment has a lines: section";
  const sim::GroundTruthWalls walls =
      ReadWallsCsv(RunFile(run_dir, "walls.csv", "the run's ground-truth wall segments"));
  const CsvTable scans = ReadCsv(RunFile(run_dir, "laser_scans.csv", kWhy));
  const CsvTable hits = ReadCsv(RunFile(run_dir, "laser_hits.csv", kWhy));

  const char* kColumns[] = {"time_s",           "sensor_x_m",    "sensor_y_m",
                            "sensor_theta_rad", "angle_min_rad", "angle_increment_rad",
                            "range_min_m",      "range_max_m"};
  const std::size_t fixed = std::size(kColumns);
  for (std::size_t c = 0; c < scans.header.size(); ++c) {
    const std::string expected =
        c < fixed ? std::string(kColumns[c]) : "range_" + std::to_string(c - fixed) + "_m";
    if (scans.header[c] != expected) {
      throw sim::ConfigError(scans.file + ":" + std::to_string(scans.header_line), scans.header[c],
                             "expected column " + expected);
    }
  }
  if (scans.header.size() <= fixed) {
    throw sim::ConfigError(scans.file + ":" + std::to_string(scans.header_line), "range_0_m",
                           "missing: no beams");
  }
  const std::size_t beams = scans.header.size() - fixed;
  for (std::size_t c = 0; c < hits.header.size() || c < beams + 1; ++c) {
    const std::string expected = c == 0 ? "time_s" : "beam_" + std::to_string(c - 1) + "_segment";
    if (c >= hits.header.size() || c > beams || hits.header[c] != expected) {
      throw sim::ConfigError(hits.file + ":" + std::to_string(hits.header_line),
                             c < hits.header.size() ? hits.header[c] : expected,
                             "expected the header time_s,beam_0_segment,..,beam_" +
                                 std::to_string(beams - 1) +
                                 "_segment (one column per beam of "
                                 "laser_scans.csv)");
    }
  }
  if (hits.rows.size() != scans.rows.size()) {
    throw sim::ConfigError(hits.file, "",
                           std::to_string(hits.rows.size()) + " scans, but laser_scans.csv has " +
                               std::to_string(scans.rows.size()));
  }
  std::vector<sim::LaserRecord> records(scans.rows.size());
  std::vector<msgs::Pose2D> poses(scans.rows.size());
  for (std::size_t k = 0; k < scans.rows.size(); ++k) {
    const CsvRow& row = scans.rows[k];
    msgs::LaserScan& scan = records[k].scan;
    double v[8];
    for (std::size_t c = 0; c < fixed; ++c) v[c] = scans.Number(row, c, kColumns[c]);
    scan.time_s = v[0];
    poses[k] = {v[1], v[2], v[3]};
    scan.angle_min_rad = v[4];
    scan.angle_increment_rad = v[5];
    scan.range_min_m = v[6];
    scan.range_max_m = v[7];
    for (std::size_t i = 0; i < beams; ++i) {
      scan.ranges_m.push_back(scans.Number(row, fixed + i, scans.header[fixed + i]));
    }
    const CsvRow& hit_row = hits.rows[k];  // as many fields as the header (ReadCsv)
    if (hits.Number(hit_row, 0, "time_s") != scan.time_s) {
      hits.Fail(hit_row, "time_s",
                "does not match laser_scans.csv's scan " + std::to_string(k) + " at " +
                    sim::FormatNumber(scan.time_s) + " s");
    }
    for (std::size_t i = 0; i < beams; ++i) {
      const std::string& field = hits.header[i + 1];
      const long id = hits.Integer(hit_row, i + 1, field);
      if (id < -1 || id >= static_cast<long>(walls.segments.size())) {
        hits.Fail(hit_row, field,
                  "segment " + std::to_string(id) + " is not in walls.csv (0.." +
                      std::to_string(static_cast<long>(walls.segments.size()) - 1) + ", or -1)");
      }
      records[k].hit_segment_ids.push_back(static_cast<int>(id));
    }
  }
  out.scans.reserve(records.size());
  for (std::size_t k = 0; k < records.size(); ++k) {
    const sim::LaserRecord* one[] = {&records[k]};
    const msgs::Pose2D pose[] = {poses[k]};
    out.scans.push_back(MakeTruthScanAt(one, pose, walls, out.lines.range_cut_m));
  }
  return out;
}

}  // namespace plywood::eval
