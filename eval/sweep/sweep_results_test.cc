#include "eval/sweep/sweep_results.h"

#include <gtest/gtest.h>

#include <cmath>

#include "eval/sweep/sweep_cells.h"
#include "eval/sweep/sweep_csv.h"
#include "eval/sweep/sweep_runner.h"

namespace plywood::eval {
namespace {

TEST(SweepResultsTest, SummaryMatchesClosedForm) {
  const SampleSummary s = Summarise({1, 2, 3, 4, 5});
  EXPECT_EQ(s.n, 5);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(2.5));
  const double half = 2.776 * std::sqrt(2.5) / std::sqrt(5.0);
  EXPECT_NEAR(s.ci95_low, 3.0 - half, 1e-12);
  EXPECT_NEAR(s.ci95_high, 3.0 + half, 1e-12);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 5.0);
  // audit s49: one run was summarised as std 0 and a 95 % CI of [7, 7]; both are undefined.
  const SampleSummary one = Summarise({7});
  EXPECT_EQ(one.n, 1);
  EXPECT_EQ(one.mean, 7.0);
  EXPECT_EQ(one.min, 7.0);
  EXPECT_EQ(one.max, 7.0);
  EXPECT_TRUE(std::isnan(one.std));
  EXPECT_TRUE(std::isnan(one.ci95_low));
  EXPECT_TRUE(std::isnan(one.ci95_high));
  // Identical runs (noise-free) have exactly no spread.
  const SampleSummary same = Summarise({7, 7, 7});
  EXPECT_EQ(same.std, 0.0);
  EXPECT_EQ(same.ci95_low, 7.0);
  EXPECT_EQ(same.ci95_high, 7.0);
  EXPECT_EQ(Summarise({}).n, 0);
}

// Issue 14's bar is on the 90th percentile (nearest rank), so a sweep's summary reports it.
TEST(SweepResultsTest, NinetiethPercentileIsTheNearestRank) {
  EXPECT_EQ(Summarise({5, 1, 4, 2, 3}).p90, 5.0);  // ceil(4.5) = 5th smallest
  std::vector<double> ten;
  for (int i = 10; i >= 1; --i) ten.push_back(i);
  EXPECT_EQ(Summarise(ten).p90, 9.0);  // the 9th smallest of 1..10, not interpolated
  ten.push_back(11);
  EXPECT_EQ(Summarise(ten).p90, 10.0);  // ceil(9.9) = 10th of 11
  std::vector<double> many;
  for (int i = 0; i < 150; ++i) many.push_back(150 - i);  // 1..150, as a 50 x 3 sweep
  EXPECT_EQ(Summarise(many).p90, 135.0);
  EXPECT_EQ(Summarise({7}).p90, 7.0);
}

TEST(SweepResultsTest, StudentQuantilesApproachTheNormalOne) {
  EXPECT_DOUBLE_EQ(StudentT95(1), 12.706);
  EXPECT_DOUBLE_EQ(StudentT95(30), 2.042);
  EXPECT_NEAR(StudentT95(60), 2.000, 0.002);   // tabulated 2.000
  EXPECT_NEAR(StudentT95(120), 1.980, 0.002);  // tabulated 1.980
  EXPECT_NEAR(StudentT95(100000), 1.960, 0.001);
}

TEST(SweepResultsTest, ShardsPartitionTheCells) {
  std::vector<SweepCell> cells(53);
  for (int i = 0; i < 53; ++i) cells[i].index = i;
  for (int n = 1; n <= 8; ++n) {
    for (const SweepCell& cell : cells) {
      int owners = 0;
      for (int i = 0; i < n; ++i) owners += InShard(cell, i, n) ? 1 : 0;
      EXPECT_EQ(owners, 1) << "cell " << cell.index << " of " << n << " shards";
    }
  }
}

TEST(SweepResultsTest, CsvQuotesAndParsesBack) {
  const std::vector<std::string> fields{"a", "b,c", "say \"hi\"", "two\nlines", ""};
  const std::string row = CsvLine(fields);
  EXPECT_EQ(row, "a,\"b,c\",\"say \"\"hi\"\"\",\"two\nlines\",\n");
  const auto parsed = ParseCsv(row + CsvLine({"1", "2", "3", "4", "5"}));
  ASSERT_EQ(parsed.size(), 2u);
  EXPECT_EQ(parsed[0], fields);
}

TEST(SweepResultsTest, StableHashIsFnv1a) {
  EXPECT_EQ(StableHash(""), "cbf29ce484222325");
  EXPECT_EQ(StableHash("a"), "af63dc4c8601ec8c");
}

}  // namespace
}  // namespace plywood::eval
