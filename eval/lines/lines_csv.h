#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "eval/lines/line_scan_scorer.h"
#include "perception/lines/circle_feature.h"
#include "perception/lines/line_segment.h"

namespace plywood::eval {

// lines.csv (docs/run_outputs.md): one row per extracted segment per scan per extractor,
//   scan,extractor,x1_m,y1_m,x2_m,y2_m,alpha_rad,r_m,points,truth_segment
// endpoints and normal form in the sensor frame, the points the extractor fitted, the walls.csv
// segment it matched (empty: none). seed000_rooms adds a leading `room` column (the world's stem).
struct LinesCsvRow {
  std::string room;
  long scan = 0;
  std::string extractor;
  perception::LineSegment segment;  // start, end, alpha_rad, r_m, num_points
  int truth_segment = -1;
  std::size_t line_number = 0;  // when read from a file
};

// The rows of `scores` (scan-major, extractors in order); scans numbered from first_scan.
std::vector<LinesCsvRow> LinesCsvRows(std::span<const ExtractorScore> scores,
                                      const std::string& room = "", long first_scan = 0);

// Writes `rows` with one header row (RFC 4180 with LF line ends, numbers in shortest round-trip
// form). @throws std::runtime_error naming `path` when it cannot be written.
void WriteLinesCsv(const std::filesystem::path& path, std::span<const LinesCsvRow> rows,
                   bool with_room = false);

// circles.csv (docs/run_outputs.md), beside lines.csv: one row per circle (round object) an
// extractor reported per scan, scans and extractors in lines.csv's order,
//   scan,extractor,x_m,y_m,radius_m,rms_m,points
// centre in the sensor frame, RMS residual of the points used, their number; seed000_rooms adds
// the leading `room` column. @throws std::runtime_error naming `path` when it cannot be written.
void WriteCirclesCsv(const std::filesystem::path& path, std::span<const ExtractorScore> scores,
                     const std::string& room = "", long first_scan = 0);
// The rows of WriteCirclesCsv without the header (to concatenate rooms).
std::string CirclesCsvRows(std::span<const ExtractorScore> scores, const std::string& room = "",
                           long first_scan = 0);
std::string CirclesCsvHeader(bool with_room);
// One circle's columns of circles.csv and spot_round_objects.csv: `x_m,y_m,radius_m,rms_m,points`.
std::string CircleCsvColumns(const perception::CircleFeature& circle);

// A segments file as `plywood score lines` takes it: a header row naming the columns, in any
// order. Required: scan, x1_m, y1_m, x2_m, y2_m. Optional: extractor (else every row is
// `default_extractor`), alpha_rad and r_m together (else the line through the endpoints), points,
// truth_segment (read and checked, not used: the scorer matches again). When
// `extractor_named_by_user` (score's --name), a file with an extractor column is refused: the
// name would be ignored.
// @throws sim::ConfigError "FILE:LINE: FIELD: what is wrong" for an unknown or missing column, a
// wrong column count, a non-numeric, non-finite or negative field, a zero-length segment without a
// normal form, a normal form more than 1 mm off the endpoints, an empty file.
std::vector<LinesCsvRow> ReadLinesCsv(const std::filesystem::path& path,
                                      const std::string& default_extractor,
                                      bool extractor_named_by_user = false);

}  // namespace plywood::eval
