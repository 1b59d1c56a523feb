#include "perception/logs/carmen_log.h"

#include <zlib.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "msgs/shortest_number.h"
#include "perception/logs/byte_order_mark.h"
#include "perception/logs/fixed_decimals.h"
#include "perception/logs/gzip_trailing_bytes.h"
#include "perception/logs/parse_number.h"
#include "perception/logs/regular_file.h"

namespace plywood::perception {
namespace {

// Strict number parsing: the whole token must be a finite number.
double ParseNumber(const std::string& token, const char* field) {
  const std::optional<double> value = ParseFiniteNumber(token);
  if (!value) {
    throw std::runtime_error(std::string(field) + ": not a finite number: '" + token + "'");
  }
  return *value;
}

// A time stamp as CARMEN writes it (%.6f): 1e9-odd seconds since 1970 in full.
std::string FormatTime(double time_s) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.6f", time_s);
  return text;
}

// The line's words, split where `std::istream >> std::string` splits in the C locale (space,
// \t, \n, \v, \f, \r), without a stream: a log of 10^4 scans has 10^6 of them.
std::vector<std::string> Tokens(const std::string& line) {
  const auto is_space = [](char c) { return c == ' ' || (c >= '\t' && c <= '\r'); };
  std::vector<std::string> tokens;
  std::size_t i = 0;
  while (true) {
    while (i < line.size() && is_space(line[i])) ++i;
    if (i == line.size()) return tokens;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    tokens.emplace_back(line, start, i - start);
  }
}

// A count field ("FLASER beam count"): a whole number in min..100000.
std::size_t ParseCount(const std::string& token, const std::string& what, int min) {
  const double value = ParseNumber(token, what.c_str());
  if (value < min || value > 100000 || value != std::floor(value)) {
    throw std::runtime_error(what + ": must be a whole number in " + std::to_string(min) +
                             "..100000");
  }
  return static_cast<std::size_t>(value);
}

constexpr double kMaxLaserRangeM = 10000.0;

// n ranges from t[first]; a negative range, or one beyond kMaxLaserRangeM, is refused.
std::vector<double> ParseRanges(const std::vector<std::string>& t, std::size_t first, std::size_t n,
                                const std::string& kind) {
  const std::string field = kind + " range";  // once per scan, not per beam
  std::vector<double> ranges(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = ParseNumber(t[first + i], field.c_str());
    if (r < 0.0) throw std::runtime_error(field + ": negative range " + t[first + i]);
    // A log without PARAM front_laser_max is scored against its largest range: one absurd value
    // (1e300) became the maximum, every no-return reading (81.91 m on a SICK) then counted as a
    // hit and rays_explained changed without a word. No robot's laser measures 10 km.
    if (r > kMaxLaserRangeM) {
      throw std::runtime_error(field + ": must be at most 10000 m (no robot's laser measures " +
                               "further), got " + t[first + i]);
    }
    ranges[i] = r;
  }
  return ranges;
}

void ParseFlaser(const std::vector<std::string>& t, CarmenLog* log) {
  if (t.size() < 2) throw std::runtime_error("FLASER: missing beam count");
  const std::size_t n = ParseCount(t[1], "FLASER beam count", 1);
  if (FlaserCountIsAmbiguous(n)) {
    throw std::runtime_error(
        "FLASER beam count: " + std::to_string(n) +
        " beams, which CARMEN's reader takes as a 100 deg scan at 0.25 deg and others as 180 deg "
        "at " +
        msgs::ShortestNumber(180.0 / static_cast<double>(n - 1)) +
        " deg: FLASER gives no angles, so the beams' bearings are unknown; write the scan as "
        "ROBOTLASER1 with its start_angle and angular_resolution");
  }
  // n ranges, then x y theta odom_x odom_y odom_theta ipc_timestamp hostname logger_timestamp.
  if (t.size() != 2 + n + 9) {
    throw std::runtime_error("FLASER: expected " + std::to_string(2 + n + 9) + " fields for " +
                             std::to_string(n) + " beams, got " + std::to_string(t.size()));
  }
  CarmenLaserRecord record;
  record.scan.ranges_m = ParseRanges(t, 2, n, "FLASER");
  const std::size_t p = 2 + n;
  record.X_WL = {ParseNumber(t[p], "FLASER x"), ParseNumber(t[p + 1], "FLASER y"),
                 ParseNumber(t[p + 2], "FLASER theta")};
  record.X_WR_odom = {ParseNumber(t[p + 3], "FLASER odom_x"),
                      ParseNumber(t[p + 4], "FLASER odom_y"),
                      ParseNumber(t[p + 5], "FLASER odom_theta")};
  record.scan.time_s = ParseNumber(t[p + 6], "FLASER ipc_timestamp");
  ParseNumber(t[p + 8], "FLASER logger_timestamp");
  record.scan.angle_min_rad = -std::numbers::pi / 2.0;
  record.scan.angle_increment_rad = FlaserAngleIncrementRad(n);
  log->lasers.push_back(std::move(record));
}

// ROBOTLASER1 laser_type start_angle fov resolution max_range accuracy remission_mode n ranges...
// m remissions... laser_x laser_y laser_theta robot_x robot_y robot_theta tv rv
// forward_safety_dist side_safety_dist turn_axis ipc_timestamp hostname logger_timestamp.
// Unlike FLASER it carries the beams' start angle and spacing, so any fov reads back right.
void ParseRobotLaser1(const std::vector<std::string>& t, CarmenLog* log) {
  if (t.size() < 9) throw std::runtime_error("ROBOTLASER1: missing fields before the ranges");
  const std::size_t n = ParseCount(t[8], "ROBOTLASER1 beam count", 1);
  if (t.size() < 9 + n + 1) throw std::runtime_error("ROBOTLASER1: fewer ranges than announced");
  const std::size_t m = ParseCount(t[9 + n], "ROBOTLASER1 remission count", 0);
  const std::size_t p = 9 + n + 1 + m;
  if (t.size() != p + 14) {
    throw std::runtime_error("ROBOTLASER1: expected " + std::to_string(p + 14) + " fields for " +
                             std::to_string(n) + " beams and " + std::to_string(m) +
                             " remissions, got " + std::to_string(t.size()));
  }
  CarmenLaserRecord record;
  record.scan.angle_min_rad = ParseNumber(t[2], "ROBOTLASER1 start_angle");
  const double fov = ParseNumber(t[3], "ROBOTLASER1 field_of_view");
  record.scan.angle_increment_rad = ParseNumber(t[4], "ROBOTLASER1 angular_resolution");
  // A spacing of 0 puts every beam on one bearing, a negative one or a fan wider than a turn has
  // no scanner behind it: the extractors would fit lines to points that were never measured there.
  if (!(record.scan.angle_increment_rad > 0.0) ||
      record.scan.angle_increment_rad * static_cast<double>(n - 1) >
          2.0 * std::numbers::pi + 1e-6) {
    throw std::runtime_error("ROBOTLASER1 angular_resolution: must be > 0 with the " +
                             std::to_string(n) + " beams spanning at most 360 deg, got " + t[4]);
  }
  if (std::abs(record.scan.angle_min_rad) > 2.0 * std::numbers::pi) {
    throw std::runtime_error("ROBOTLASER1 start_angle: must be in [-2 pi, 2 pi] rad, got " + t[2]);
  }
  // The beams are placed by the resolution alone. A log thinned to every second beam that kept the
  // resolution put them in half the fan (rays_explained 0.80 where the right angles give 0.87).
  // Writers differ on whether the fov spans n - 1 or n steps, so both pass, with half a step over.
  const double step = record.scan.angle_increment_rad;
  const double spanned = step * static_cast<double>(n - 1);
  if (fov < spanned - step / 2.0 || fov > spanned + step * 1.5) {
    throw std::runtime_error(
        "ROBOTLASER1 field_of_view: " + t[3] + " rad, but " + std::to_string(n) +
        " beams at angular_resolution " + t[4] + " rad span " + msgs::ShortestNumber(spanned) +
        " rad (" + msgs::ShortestNumber(spanned + step) +
        " counting n steps): the beams' angles are unknown (a log thinned to every k-th beam "
        "needs k times the resolution)");
  }
  record.scan.range_max_m = ParseNumber(t[5], "ROBOTLASER1 maximum_range");
  if (!(record.scan.range_max_m > 0.0)) {
    throw std::runtime_error("ROBOTLASER1 maximum_range: must be > 0, got " + t[5]);
  }
  record.scan.ranges_m = ParseRanges(t, 9, n, "ROBOTLASER1");
  record.X_WL = {ParseNumber(t[p], "ROBOTLASER1 laser_x"),
                 ParseNumber(t[p + 1], "ROBOTLASER1 laser_y"),
                 ParseNumber(t[p + 2], "ROBOTLASER1 laser_theta")};
  record.X_WR_odom = {ParseNumber(t[p + 3], "ROBOTLASER1 robot_x"),
                      ParseNumber(t[p + 4], "ROBOTLASER1 robot_y"),
                      ParseNumber(t[p + 5], "ROBOTLASER1 robot_theta")};
  record.scan.time_s = ParseNumber(t[p + 11], "ROBOTLASER1 ipc_timestamp");
  ParseNumber(t[p + 13], "ROBOTLASER1 logger_timestamp");
  log->lasers.push_back(std::move(record));
}

// True when FLASER's fixed geometry (n beams from -90 deg to +90 deg) is the scan's own.
// A count readers take for another fan (FlaserCountIsAmbiguous) goes out as ROBOTLASER1.
bool FlaserCanCarry(const msgs::LaserScan& scan) {
  const std::size_t n = scan.ranges_m.size();
  if (n < 2 || FlaserCountIsAmbiguous(n)) return false;
  constexpr double kTolerance = 1e-9;
  return std::abs(scan.angle_min_rad + std::numbers::pi / 2.0) < kTolerance &&
         std::abs(scan.angle_increment_rad - FlaserAngleIncrementRad(n)) < kTolerance;
}

// Line-oriented reader over plain or gzip files (zlib reads both transparently).
class LineReader {
 public:
  explicit LineReader(const std::filesystem::path& path)
      : path_(path), file_(gzopen(path.c_str(), "rb")) {
    if (file_ == nullptr) throw std::runtime_error(path.string() + ": cannot open");
  }
  ~LineReader() { gzclose(file_); }
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // The next line, without its "\n" or "\r\n", NUL bytes and all: gzgets ended its text at a
  // NUL, so a line starting with NULs (a block a crash left zero-filled) was read as empty and
  // its scan lost without a word, and a NUL inside a line joined the rest of it to the next one.
  // @throws std::runtime_error with zlib's message when the gzip stream is corrupt or truncated
  // (gzread reports those as the end of the file).
  bool Next(std::string* line) {
    line->clear();
    for (;;) {
      if (next_ < have_) {
        const char* start = buffer_.data() + next_;
        const auto* end = static_cast<const char*>(std::memchr(start, '\n', have_ - next_));
        if (end != nullptr) {
          line->append(start, end);
          next_ += static_cast<std::size_t>(end - start) + 1;
          if (!line->empty() && line->back() == '\r') line->pop_back();
          return true;
        }
        line->append(start, have_ - next_);
        next_ = have_;
      }
      const int got = gzread(file_, buffer_.data(), static_cast<unsigned>(buffer_.size()));
      if (got <= 0) break;
      have_ = static_cast<std::size_t>(got);
      next_ = 0;
    }
    int error = Z_OK;
    const char* message = gzerror(file_, &error);
    if (error != Z_OK && error != Z_STREAM_END) {
      throw std::runtime_error(std::string("corrupt or truncated gzip data (zlib: ") +
                               (message ? message : "unknown error") + ")");
    }
    // zlib ends a gzip stream at the first bytes after a member that start no other member, as
    // if the file ended there: a plain log appended to a compressed one lost its scans, exit 0.
    if (!end_checked_ && gzdirect(file_) == 0) {
      end_checked_ = true;
      if (const auto trailing = DescribeBytesAfterGzipData(path_)) {
        throw std::runtime_error(*trailing);
      }
    }
    return !line->empty();
  }

 private:
  std::filesystem::path path_;
  gzFile file_;
  // On the heap, as SkipMember's buffers: the reader lives on the stack of ReadCarmenLog, and
  // `ulimit -s 128` crashed a replay (s65 fifty-fourth pass).
  std::vector<char> buffer_ = std::vector<char>(65536);
  std::size_t have_ = 0;  // bytes in buffer_
  std::size_t next_ = 0;  // the first not yet returned
  bool end_checked_ = false;
};

}  // namespace

bool ParseCarmenLine(const std::string& line, CarmenLog* log) {
  const std::vector<std::string> t = Tokens(line);
  if (t.empty() || t[0][0] == '#') return false;
  if (t[0] == "FLASER") {
    ParseFlaser(t, log);
    return true;
  }
  if (t[0] == "ROBOTLASER1") {
    ParseRobotLaser1(t, log);
    return true;
  }
  if (t[0] == "PARAM") {
    if (t.size() < 3) throw std::runtime_error("PARAM: expected a name and a value");
    // Plywood writes front_laser_max; CARMEN's own logs name it robot_front_laser_max.
    if (t[1] == "front_laser_max" || t[1] == "robot_front_laser_max") {
      const std::string what = "PARAM " + t[1];
      const double range_max = ParseNumber(t[2], what.c_str());
      if (!(range_max > 0.0)) throw std::runtime_error(what + ": must be > 0, got " + t[2]);
      // One value serves every FLASER scan of the log, those before the line too: a second,
      // different one (two logs joined with cat) silently rescored the first log's scans.
      const auto earlier = log->params.find(t[1]);
      if (earlier != log->params.end() && ParseFiniteNumber(earlier->second) != range_max) {
        throw std::runtime_error(what + ": given again as " + t[2] + " after an earlier " +
                                 earlier->second +
                                 ": one maximum range serves every FLASER scan of the log, so a "
                                 "log of two lasers cannot be scored as one; split it");
      }
    }
    log->params[t[1]] = t[2];
    return true;
  }
  return false;
}

namespace {

// Every number of the two records alike: one scan written twice, not two scans.
bool SameScan(const CarmenLaserRecord& a, const CarmenLaserRecord& b) {
  return a.scan.ranges_m == b.scan.ranges_m && a.scan.angle_min_rad == b.scan.angle_min_rad &&
         a.scan.angle_increment_rad == b.scan.angle_increment_rad &&
         a.scan.range_max_m == b.scan.range_max_m && a.X_WL == b.X_WL && a.X_WR_odom == b.X_WR_odom;
}

}  // namespace

namespace {

// The program that compressed `path` when it starts as xz, bzip2, zstd, zip or 7-Zip data, which
// zlib reads as plain bytes: such a log read as binary lines ("no usable laser scan in 43 lines",
// or a NUL byte on line 1), not as the compressed log it is.
std::optional<std::string> OtherCompressor(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(6, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const struct {
    std::string_view magic, program, undo;
  } kKnown[] = {{"\xFD\x37zXZ", "xz", "xz -dk"},
                {"BZh", "bzip2", "bunzip2 -k"},
                {"\x28\xB5\x2F\xFD", "zstd", "zstd -d"},
                {"PK\x03\x04", "zip", "unzip"},
                {"7z\xBC\xAF\x27\x1C", "7-Zip", "7z x"}};
  for (const auto& known : kKnown) {
    const bool bzip2_level =
        known.program != "bzip2" || (head.size() > 3 && head[3] >= '1' && head[3] <= '9');
    if (head.starts_with(known.magic) && bzip2_level) {
      return "compressed with " + std::string(known.program) +
             ", which Plywood does not read (plain text or gzip only): decompress it first (" +
             std::string(known.undo) + " " + path.filename().string() + ")";
    }
  }
  return std::nullopt;
}

}  // namespace

CarmenLog ReadCarmenLog(const std::filesystem::path& path, const CarmenReadOptions& options) {
  if (!IsRegularFile(path)) {
    throw std::runtime_error(path.string() + ": " + WhyNotARegularFile(path, "log file"));
  }
  if (const auto compressor = OtherCompressor(path)) {
    throw std::runtime_error(path.string() + ": " + *compressor);
  }
  CarmenLog log;
  LineReader reader(path);
  std::string line;
  std::size_t number = 1;
  const auto next_line = [&] {
    try {
      return reader.Next(&line);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(path.string() + ":" + std::to_string(number) + ": " + e.what());
    }
  };
  // The line and index in log.lasers of each scan's time stamp, FLASER's and ROBOTLASER1's apart.
  std::unordered_map<double, std::pair<std::size_t, std::size_t>> scan_lines[2];
  for (; next_line(); ++number) {
    // A UTF-8 byte-order mark (an editor's "UTF-8 with BOM") made the first line an unknown
    // message, skipped without a word: a log's PARAM front_laser_max was lost, its scans scored
    // against their largest range instead.
    if (number == 1) DropUtf8ByteOrderMark(line);
    const std::size_t before = log.lasers.size();
    try {
      if (const std::size_t nul = line.find('\0'); nul != std::string::npos) {
        throw std::runtime_error(
            "a NUL byte at column " + std::to_string(nul + 1) +
            ": a log is text (a file a crash left with zero-filled blocks, or not a log?); the "
            "line cannot be read");
      }
      ParseCarmenLine(line, &log);
      if (log.lasers.size() > before) {
        // Some converters write every scan twice, as FLASER and as ROBOTLASER1 at one time stamp:
        // the replay counted each scan twice (scans, lines, circles and valid_rays doubled).
        const std::size_t type = line.find_first_not_of(" \t");
        const bool robot_laser = line.compare(type, 11, "ROBOTLASER1") == 0;
        const double time_s = log.lasers.back().scan.time_s;
        const auto other = scan_lines[!robot_laser].find(time_s);
        const std::string kind = robot_laser ? "ROBOTLASER1" : "FLASER";
        if (other != scan_lines[!robot_laser].end()) {
          log.lasers.pop_back();
          throw std::runtime_error(
              kind + " ipc_timestamp: " + FormatTime(time_s) + " s is line " +
              std::to_string(other->second.first) + "'s " +
              (robot_laser ? "FLASER" : "ROBOTLASER1") +
              " scan again: the log records each scan twice, as FLASER and ROBOTLASER1 (a laser "
              "gives one scan at a time), so the replay would count it twice; keep one kind "
              "(grep -v '^FLASER' keeps ROBOTLASER1, which carries the beams' angles)");
        }
        // One kind at one time stamp is the log's content (a logger's coarse clock), but with
        // every range, angle and pose the same it is one scan written twice: a log joined to itself
        // (`cat a.log a.log`) replayed every scan twice, exit 0 (s57's left item). No FLASER scan
        // of the three shipped logs (6,141) repeats an earlier one's time stamp.
        const auto same = scan_lines[robot_laser].find(time_s);
        if (same != scan_lines[robot_laser].end() &&
            SameScan(log.lasers[same->second.second], log.lasers.back())) {
          log.lasers.pop_back();
          throw std::runtime_error(
              kind + " ipc_timestamp: " + FormatTime(time_s) +
              " s, every range and pose repeat line " + std::to_string(same->second.first) +
              "'s scan: the log holds this scan twice (a log joined to itself?), so the replay "
              "would count it twice; remove the repeat");
        }
        scan_lines[robot_laser].try_emplace(time_s, number, log.lasers.size() - 1);
      }
    } catch (const std::exception& e) {
      if (!options.skip_bad) {
        throw std::runtime_error(path.string() + ":" + std::to_string(number) + ": " + e.what());
      }
      ++log.skipped_lines;
      continue;
    }
    if (log.lasers.size() > before) log.lasers.back().line_number = number;
  }
  if (log.lasers.empty()) {
    throw std::runtime_error(
        path.string() + ": no usable laser scan (FLASER or ROBOTLASER1 line) in " +
        std::to_string(number - 1) + " lines" +
        (log.skipped_lines ? " (" + std::to_string(log.skipped_lines) + " malformed lines skipped)"
                           : std::string()));
  }
  // FLASER range limits: PARAM front_laser_max when the log has it (checked when read), else
  // CARMEN's robot_front_laser_max, else the largest range in the log (which, in a stretch of log
  // where the laser always saw something, is a real return and not the maximum).
  // ROBOTLASER1 lines carry their own.
  double range_max = 0.0;
  for (const char* name : {"front_laser_max", "robot_front_laser_max"}) {
    if (auto it = log.params.find(name); it != log.params.end()) {
      range_max = ParseFiniteNumber(it->second).value_or(0.0);
      break;
    }
  }
  if (!(range_max > 0.0)) {
    for (const auto& record : log.lasers) {
      for (double r : record.scan.ranges_m) range_max = std::max(range_max, r);
    }
  }
  for (auto& record : log.lasers) {
    if (record.scan.range_max_m != 0.0) continue;
    // Every range 0 and no PARAM: nothing says how far the scanner sees (found by fuzzing).
    if (!(range_max > 0.0)) {
      throw std::runtime_error(path.string() + ":" + std::to_string(record.line_number) +
                               ": the maximum range is unknown: no PARAM front_laser_max and no "
                               "positive range in the log");
    }
    record.scan.range_max_m = range_max;
  }
  return log;
}

bool IsFlaserScan(const msgs::LaserScan& scan) { return FlaserCanCarry(scan); }

// FLASER carries no angles: readers guess them from the beam count. For 400 and 401 beams they
// disagree about the scanner itself: CARMEN's own reader (carmen_laser_guess_fov) takes a SICK in
// its 100 deg mode at 0.25 deg, vasco and Plywood a 180 deg fan at 0.45 deg, so every beam but the
// first points up to 80 deg apart between the two. 180 / 181 and 360 / 361 beams are 1 and 0.5 deg
// steps from -90 deg in both (FlaserAngleIncrementRad).
bool FlaserCountIsAmbiguous(std::size_t beams) { return beams == 400 || beams == 401; }

// CARMEN's FLASER writers took 180 and 360 beams from a SICK's 181 and 361 by dropping the last
// one (carmen_laser_guess_fov: "last beam ignored"), so those counts step 1 and 0.5 deg from -90
// deg and end at 89 and 89.5 deg; every other count spans -90..+90 deg. Spreading 180 beams over
// 180 deg, as Plywood did to stop 50, put the last beam 1 deg off: the corrected intel, aces and
// freiburg-079 logs' scans agree better with each other (nearest returns of the next ten scans,
// at their corrected poses) at CARMEN's steps.
double FlaserAngleIncrementRad(std::size_t beams) {
  if (beams == 180 || beams == 360) return std::numbers::pi / static_cast<double>(beams);
  return beams > 1 ? std::numbers::pi / static_cast<double>(beams - 1) : 0.0;
}

void WriteCarmenLaser(std::ostream& out, const CarmenLaserRecord& record) {
  // The line is built in one buffer and written once. std::to_chars with a precision formats
  // exactly as printf's %.Nf / %.Ng in the C locale (the standard says so), at a fraction of
  // snprintf's cost: 361 ranges per scan made snprintf most of a run's output writing. The fixed
  // numbers go through WriteFixedDecimals, which gives to_chars' bytes with integer arithmetic
  // (to_chars' generic fixed-precision path was ~280 instructions per range).
  std::string line;
  line.reserve(32 + 8 * record.scan.ranges_m.size());
  const auto put = [&](double v, std::chars_format format, int precision) {
    // Room for any double in %.3f (DBL_MAX has 309 digits before the point): never truncated.
    char number[400];
    const auto [end, error] = std::to_chars(number, number + sizeof(number), v, format, precision);
    line += ' ';
    line.append(number, error == std::errc() ? end : number);
  };
  const auto put_fixed = [&](double v, int decimals) {
    char number[400];
    line += ' ';
    line.append(number, WriteFixedDecimals(number, number + sizeof(number), v, decimals));
  };
  const msgs::LaserScan& scan = record.scan;
  // Both messages carry the ranges, the laser and odometry poses and the time stamps alike.
  const auto put_ranges = [&] {
    line += ' ' + std::to_string(scan.ranges_m.size());
    for (double r : scan.ranges_m) put_fixed(std::min(r, scan.range_max_m), 3);
  };
  const auto put_poses = [&] {
    for (const msgs::Pose2D* pose : {&record.X_WL, &record.X_WR_odom}) {
      put_fixed(pose->x_m, 6);
      put_fixed(pose->y_m, 6);
      put_fixed(pose->theta_rad, 6);
    }
  };
  const auto put_times = [&] {
    put_fixed(scan.time_s, 6);
    line += " plywood";
    put_fixed(scan.time_s, 6);
    line += '\n';
  };
  if (!FlaserCanCarry(scan)) {
    // laser_type 0 (SICK LMS), accuracy 0, remission_mode 0, no remissions; tv rv, the safety
    // distances and the turn axis are unknown (0).
    line += "ROBOTLASER1 0";
    // Angles to the last bit: a rounded resolution would add up over hundreds of beams.
    put(scan.angle_min_rad, std::chars_format::general, 17);
    put(scan.angle_increment_rad * static_cast<double>(scan.ranges_m.size() - 1),
        std::chars_format::general, 17);
    put(scan.angle_increment_rad, std::chars_format::general, 17);
    put_fixed(scan.range_max_m, 3);
    line += " 0 0";
    put_ranges();
    line += " 0";
    put_poses();
    line += " 0 0 0 0 0";
  } else {
    line += "FLASER";
    put_ranges();
    put_poses();
  }
  put_times();
  out << line;
}

void WriteCarmenParam(std::ostream& out, const std::string& name, const std::string& value) {
  out << "PARAM " << name << ' ' << value << " plywood 0.000000\n";
}

}  // namespace plywood::perception
