// WriteScoreJson (`plywood score --out`) when the scores cannot be written.

#include "eval/score/score_report.h"

#include <gtest/gtest.h>

#include <string>

#include "sim/config/config_error.h"
#include "sim/runner/text_file.h"
#include "tests/support/file_size_limit.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::eval {
namespace {

namespace fs = std::filesystem;

// audit s35: the scores were written in place, so a full disk or a file-size limit cut an earlier
// scores file to 0 bytes (and left it so beside the error). Now they are staged and renamed into
// place: the error names --out and the reason, the earlier file is as it was, nothing is left.
TEST(ScoreReportTest, AFailedWriteKeepsTheEarlierScoresAndLeavesNoPartialFile) {
  const fs::path dir = testing::MakeTempDir("score_report_limit");
  const fs::path run = testing::MakeTempDir("score_report_run");
  const fs::path scored = testing::WriteFile(dir / "est.tum", "0 0 0 0 0 0 0 1\n");
  const fs::path out = dir / "scores.json";
  sim::WriteTextFile(out, "earlier scores\n");
  ScoreReport report;
  for (const char* key : {"odometry.est.ate_rms_m", "odometry.est.final_error_m",
                          "odometry.est.drift_percent", "odometry.est.heading_error_deg"}) {
    report.metrics.Set(key, 0.125);
  }
  std::string error;
  try {
    const testing::FileSizeLimit limit(64);
    ASSERT_TRUE(limit.active());
    WriteScoreJson(report, out, run, scored);
  } catch (const sim::ConfigError& e) {
    error = e.what();
  }
  EXPECT_EQ(error, out.string() + ": --out: write failed: File too large");
  EXPECT_EQ(sim::ReadTextFile(out), "earlier scores\n");
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_TRUE(entry.path() == out || entry.path() == scored) << entry.path() << " left behind";
  }
  // Without the limit the same call replaces the earlier file.
  WriteScoreJson(report, out, run, scored);
  EXPECT_EQ(sim::ReadTextFile(out), report.metrics.ToJson());
}

}  // namespace
}  // namespace plywood::eval
