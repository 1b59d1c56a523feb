// Line extractors on the real CARMEN logs in ../shared/data/carmen (skipped, visibly, when that
// folder is absent). Thresholds are the acceptance figures of issue 4 for split_and_merge.

#include "perception/logs/log_replay.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "perception/lines/line_extractor_factory.h"
#include "plywood_paths.h"

namespace plywood::perception {
namespace {

std::filesystem::path CarmenDir() {
  return std::filesystem::path(PLYWOOD_SOURCE_ROOT) / ".." / "shared" / "data" / "carmen";
}

struct LogCase {
  const char* file;
  double min_explained;
};

class RealLogTest : public ::testing::TestWithParam<LogCase> {};

TEST_P(RealLogTest, SplitAndMergeExplainsTheRealScans) {
  const auto path = CarmenDir() / GetParam().file;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "real log not found: " << path;
  const CarmenLog log = ReadCarmenLog(path);
  ASSERT_GT(log.lasers.size(), 100u);
  const auto extractor = MakeLineExtractor("split_and_merge");
  const ReplayResult result = ReplayLog(log, *extractor, false);
  EXPECT_GE(result.rays.Fraction(), GetParam().min_explained) << GetParam().file;
  EXPECT_GE(result.RaysPerLine(), 15.0) << GetParam().file;
  EXPECT_LT(result.rays.RmsM(), 0.03) << GetParam().file;
  // The per-scan figures (scans.csv) add up to the totals.
  ASSERT_EQ(static_cast<long>(result.per_scan.size()), result.scans);
  long rays = 0, explained = 0, lines = 0;
  for (const ReplayResult::Scan& scan : result.per_scan) {
    rays += scan.valid_rays, explained += scan.explained, lines += scan.lines;
  }
  EXPECT_EQ(rays, result.rays.rays);
  EXPECT_EQ(explained, result.rays.explained);
  EXPECT_EQ(lines, result.lines);
}

INSTANTIATE_TEST_SUITE_P(Carmen, RealLogTest,
                         ::testing::Values(LogCase{"intel-corrected.log.gz", 0.80},
                                           LogCase{"aces-corrected.log.gz", 0.70},
                                           LogCase{"freiburg-079-corrected.log.gz", 0.80}));

}  // namespace
}  // namespace plywood::perception
