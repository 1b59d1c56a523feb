// Segment files of `plywood score lines` (eval/lines/lines_csv.h): every row read has a scan index
// >= 0 and finite endpoints and normal form.
#include <cmath>

#include "eval/lines/lines_csv.h"
#include "fuzz/fuzz_support.h"
#include "fuzz/fuzz_target.h"

namespace plywood::fuzz {
namespace {

void FuzzScoreLines(std::span<const std::uint8_t> data) {
  const std::filesystem::path path = WriteScratchFile("lines.fuzz.csv", data);
  try {
    for (const eval::LinesCsvRow& row : eval::ReadLinesCsv(path, "fuzz")) {
      Require(row.scan >= 0, "a negative scan index");
      Require(!row.extractor.empty(), "a row without an extractor");
      const perception::LineSegment& s = row.segment;
      Require(s.start.allFinite() && s.end.allFinite() && std::isfinite(s.alpha_rad) &&
                  std::isfinite(s.r_m),
              "a non-finite segment");
    }
  } catch (const std::runtime_error& e) {  // sim::ConfigError
    RequireCleanError(e, path.string());
  }
}

}  // namespace
}  // namespace plywood::fuzz

PLYWOOD_FUZZ_TARGET("score_lines", plywood::fuzz::FuzzScoreLines)
