#include "eval/lines/lines_csv.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "eval/score/csv_table.h"
#include "eval/score/score_report.h"
#include "perception/lines/line_segment.h"
#include "sim/config/config_error.h"
#include "sim/runner/file_writer.h"
#include "sim/runner/metrics.h"

namespace plywood::eval {

std::vector<LinesCsvRow> LinesCsvRows(std::span<const ExtractorScore> scores,
                                      const std::string& room, long first_scan) {
  std::vector<LinesCsvRow> rows;
  std::size_t scans = 0;
  for (const ExtractorScore& score : scores) scans = std::max(scans, score.scans.size());
  for (std::size_t s = 0; s < scans; ++s) {
    for (const ExtractorScore& score : scores) {
      if (s >= score.scans.size()) continue;
      const ScanLines& found = score.scans[s];
      for (std::size_t l = 0; l < found.segments.size(); ++l) {
        LinesCsvRow row;
        row.room = room;
        row.scan = first_scan + static_cast<long>(s);
        row.extractor = score.name;
        row.segment = found.segments[l];
        row.truth_segment = found.matched_truth[l];
        rows.push_back(std::move(row));
      }
    }
  }
  return rows;
}

void WriteLinesCsv(const std::filesystem::path& path, std::span<const LinesCsvRow> rows,
                   bool with_room) {
  sim::FileWriter file(path);
  std::ostream& out = file.out();
  const auto n = [](double value) { return sim::FormatNumber(value); };
  out << (with_room ? "room," : "")
      << "scan,extractor,x1_m,y1_m,x2_m,y2_m,alpha_rad,r_m,points,truth_segment\n";
  for (const LinesCsvRow& row : rows) {
    const perception::LineSegment& s = row.segment;
    if (with_room) out << CsvField(row.room) << ',';
    out << row.scan << ',' << CsvField(row.extractor) << ',' << n(s.start.x()) << ','
        << n(s.start.y()) << ',' << n(s.end.x()) << ',' << n(s.end.y()) << ',' << n(s.alpha_rad)
        << ',' << n(s.r_m) << ',' << s.num_points << ',';
    if (row.truth_segment >= 0) out << row.truth_segment;
    out << '\n';
  }
  file.Close();
}

std::string CirclesCsvHeader(bool with_room) {
  return std::string(with_room ? "room," : "") + "scan,extractor,x_m,y_m,radius_m,rms_m,points\n";
}

std::string CircleCsvColumns(const perception::CircleFeature& c) {
  const auto n = [](double value) { return sim::FormatNumber(value); };
  return n(c.centre.x()) + "," + n(c.centre.y()) + "," + n(c.radius_m) + "," + n(c.rms_m) + "," +
         std::to_string(c.num_points());
}

std::string CirclesCsvRows(std::span<const ExtractorScore> scores, const std::string& room,
                           long first_scan) {
  std::string out;
  std::size_t scans = 0;
  for (const ExtractorScore& score : scores) scans = std::max(scans, score.scans.size());
  for (std::size_t s = 0; s < scans; ++s) {
    for (const ExtractorScore& score : scores) {
      if (s >= score.scans.size()) continue;
      for (const perception::CircleFeature& c : score.scans[s].circles) {
        if (!room.empty()) out += CsvField(room) + ",";
        out += std::to_string(first_scan + static_cast<long>(s)) + "," + CsvField(score.name) +
               "," + CircleCsvColumns(c) + "\n";
      }
    }
  }
  return out;
}

void WriteCirclesCsv(const std::filesystem::path& path, std::span<const ExtractorScore> scores,
                     const std::string& room, long first_scan) {
  sim::FileWriter file(path);
  file.out() << CirclesCsvHeader(!room.empty()) << CirclesCsvRows(scores, room, first_scan);
  file.Close();
}

std::vector<LinesCsvRow> ReadLinesCsv(const std::filesystem::path& path,
                                      const std::string& default_extractor,
                                      bool extractor_named_by_user) {
  const CsvTable table = ReadCsv(path);
  const auto header_error = [&](const std::string& field, const std::string& what) {
    throw sim::ConfigError(table.file + ":" + std::to_string(table.header_line), field, what);
  };
  static const std::vector<std::string> kKnown = {"scan",   "extractor",    "x1_m",      "y1_m",
                                                  "x2_m",   "y2_m",         "alpha_rad", "r_m",
                                                  "points", "truth_segment"};
  for (const std::string& name : table.header) {
    if (name == "room") {
      header_error(name, "a seed000_rooms lines.csv (several rooms) cannot be scored per run");
    }
    if (std::find(kKnown.begin(), kKnown.end(), name) == kKnown.end()) {
      header_error(name,
                   "unknown column (known: scan, extractor, x1_m, y1_m, x2_m, y2_m, "
                   "alpha_rad, r_m, points, truth_segment)");
    }
  }
  for (const char* required : {"scan", "x1_m", "y1_m", "x2_m", "y2_m"}) {
    if (table.Column(required) < 0) header_error(required, "missing column");
  }
  const int alpha = table.Column("alpha_rad"), r = table.Column("r_m");
  if ((alpha < 0) != (r < 0))
    header_error(alpha < 0 ? "alpha_rad" : "r_m", "alpha_rad and r_m come together or not at all");
  const int extractor = table.Column("extractor"), points = table.Column("points"),
            truth = table.Column("truth_segment");
  // `--name mine` on a file with an extractor column was dropped without a word: the figures came
  // out under the column's names.
  if (extractor >= 0 && extractor_named_by_user) {
    header_error("extractor", "the column names each row's extractor, so --name " +
                                  default_extractor + " would be ignored: leave --name out");
  }
  std::vector<LinesCsvRow> rows;
  for (const CsvRow& csv : table.rows) {
    LinesCsvRow row;
    row.line_number = csv.line_number;
    row.scan = table.Integer(csv, table.Column("scan"), "scan");
    if (row.scan < 0) table.Fail(csv, "scan", "must be >= 0, got " + std::to_string(row.scan));
    row.extractor = extractor < 0 ? default_extractor : csv.fields[extractor];
    if (!IsMetricName(row.extractor)) {
      table.Fail(csv, "extractor", NotAMetricName(row.extractor));
    }
    if (row.extractor == "scans") {  // lines.scans is the run's scan count
      table.Fail(csv, "extractor", "'scans' cannot name an extractor (lines.scans counts scans)");
    }
    perception::LineSegment& s = row.segment;
    s.start = {table.Number(csv, table.Column("x1_m"), "x1_m"),
               table.Number(csv, table.Column("y1_m"), "y1_m")};
    s.end = {table.Number(csv, table.Column("x2_m"), "x2_m"),
             table.Number(csv, table.Column("y2_m"), "y2_m")};
    if (alpha >= 0) {
      s.alpha_rad = table.Number(csv, alpha, "alpha_rad");
      s.r_m = table.Number(csv, r, "r_m");
      const double off =
          std::max(std::abs(s.SignedLineDistance(s.start)), std::abs(s.SignedLineDistance(s.end)));
      if (off > perception::kMaxLineToEndsM) {
        table.Fail(csv, "r_m",
                   "the line (alpha_rad, r_m) passes " + sim::FormatNumber(off) +
                       " m from the segment's endpoints");
      }
    } else {
      const Eigen::Vector2d ab = s.end - s.start;
      if (ab.norm() == 0.0) {
        table.Fail(csv, "x2_m", "zero-length segment (give alpha_rad and r_m for its line)");
      }
      const Eigen::Vector2d n(ab.y() / ab.norm(), -ab.x() / ab.norm());
      perception::CanonicalNormalForm(std::atan2(n.y(), n.x()), n.dot(s.start), &s.alpha_rad,
                                      &s.r_m);
    }
    if (points >= 0 && !csv.fields[points].empty()) {
      const long count = table.Integer(csv, points, "points");
      if (count < 0 || count > 1000000000) {
        table.Fail(csv, "points", "must be in 0..1e9, got " + std::to_string(count));
      }
      s.num_points = static_cast<int>(count);
    }
    if (truth >= 0 && !csv.fields[truth].empty()) {
      const long id = table.Integer(csv, truth, "truth_segment");
      if (id < 0 || id > 1000000000) {
        table.Fail(csv, "truth_segment",
                   "must be a walls.csv segment or empty, got " + std::to_string(id));
      }
      row.truth_segment = static_cast<int>(id);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace plywood::eval
