// A round object whose near side alone lies inside a range cut (round_past_range_cut.h).

#include "perception/lines/round_past_range_cut.h"

#include <gtest/gtest.h>

#include <vector>

#include "perception/lines/line_scoring.h"
#include "perception/lines/scan_scene_test_support.h"
#include "perception/lines/split_and_merge_extractor.h"

namespace plywood::perception {
namespace {

constexpr double kCutM = 4.0;
// A room whose walls all lie beyond the cut: only what stands inside 4 m gives lines.
const std::vector<Eigen::Vector2d> kRoom{{-6.0, -6.0}, {6.0, -6.0}, {6.0, 6.0}, {-6.0, 6.0}};

std::vector<LineSegment> Lines(const ScanPoints& scan, bool past_cut) {
  SplitAndMergeOptions options;
  options.round_objects.round_past_range_cut = past_cut;
  return SplitAndMergeExtractor(options).Extract(scan);
}

int LinesNearPoint(const std::vector<LineSegment>& lines, const Eigen::Vector2d& p, double r_m) {
  int count = 0;
  for (const LineSegment& s : lines) count += s.SegmentDistance(p) < r_m;
  return count;
}

TEST(RoundPastRangeCutTest, AColumnsCapAtTheCutIsNoLine) {
  // A 0.2 m column whose near side lies 3.96 m away: a 4 m cut keeps a 4-6 point cap, flat
  // within the 1 cm noise, framed by missing beams -- a line in a third of the scans. Past the cut
  // its flanks curve away to 4.16 m and more, then the wall behind at 6 m: one round object.
  const testing::Disc column{{4.16, 0.0}, 0.2};
  int before = 0, after = 0, returns_past_cut = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const ScanPoints scan = testing::ScanScene({kRoom}, {column}, 0.01, 20.0, seed, kCutM);
    returns_past_cut += !scan.beyond_cut_range_m.empty();
    before += LinesNearPoint(Lines(scan, false), column.centre, column.radius_m + 0.05);
    after += LinesNearPoint(Lines(scan, true), column.centre, column.radius_m + 0.05);
  }
  EXPECT_EQ(returns_past_cut, 40);
  EXPECT_GE(before, 10);  // 13 of the 40 scans keep the cap as a line without the rule
  EXPECT_EQ(after, 0);
}

TEST(RoundPastRangeCutTest, AWallOrABoxCornerAtTheCutStaysALine) {
  // A wall facing the sensor with its foot 3.97 m away (it continues past the cut along its own
  // line) and a box corner pointing at the sensor 3.95 m away (two straight faces past the cut):
  // the same lines with and without the rule, bit for bit.
  const auto wall = testing::Panel({3.97, -1.5}, {3.97, 1.5});
  const Eigen::Vector2d c(-4.15, 0.0);
  const std::vector<Eigen::Vector2d> box{
      c + Eigen::Vector2d(0.2, 0.0), c + Eigen::Vector2d(0.0, 0.2), c + Eigen::Vector2d(-0.2, 0.0),
      c + Eigen::Vector2d(0.0, -0.2)};
  int wall_lines = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const ScanPoints scan = testing::ScanScene({kRoom, wall, box}, {}, 0.01, 20.0, seed, kCutM);
    const std::vector<LineSegment> with = Lines(scan, true), without = Lines(scan, false);
    ASSERT_EQ(with.size(), without.size()) << seed;
    for (std::size_t k = 0; k < with.size(); ++k) {
      EXPECT_EQ(with[k].start, without[k].start) << seed;
      EXPECT_EQ(with[k].end, without[k].end) << seed;
    }
    wall_lines += LinesNearPoint(with, {3.97, 0.0}, 0.05);
  }
  EXPECT_GE(wall_lines, 40);  // the wall is found in every scan
}

TEST(RoundPastRangeCutTest, AWallGrazingTheCutStaysALine) {
  // A 1.4 m wall facing the sensor with its foot 3.987 m away (doorways_s71_00005's, which an
  // earlier form of the rule lost once in 300 runs): within 1 cm of the cut over a dozen beams,
  // whose returns fall inside or outside it by the noise alone. The pieces left inside are those
  // the noise brought nearer, and with the returns past the cut beside them they bulge towards
  // the sensor like a cap; but the wall comes back inside the cut past them: no object seen whole.
  // (A guard: this scene did not trigger that earlier form either.)
  const auto wall = testing::Panel({3.987, -0.5}, {3.987, 0.9});
  int with_rule = 0, without_rule = 0;
  for (unsigned seed = 1; seed <= 100; ++seed) {
    const ScanPoints scan = testing::ScanScene({kRoom, wall}, {}, 0.01, 20.0, seed, kCutM);
    with_rule += static_cast<int>(Lines(scan, true).size());
    without_rule += static_cast<int>(Lines(scan, false).size());
  }
  EXPECT_GT(without_rule, 0);
  EXPECT_EQ(with_rule, without_rule);
}

TEST(RoundPastRangeCutTest, ReturnsPastTheCutAreKeptAsContext) {
  msgs::LaserScan scan;
  scan.angle_min_rad = 0.0;
  scan.angle_increment_rad = 0.01;
  scan.range_max_m = 8.0;
  scan.ranges_m = {3.0, 4.5, 8.0, 0.01, 3.9};
  const ScanPoints points = MakeScanPoints(scan, ScanFilter{.range_cut_m = kCutM});
  EXPECT_EQ(points.beam_index, (std::vector<int>{0, 4}));
  EXPECT_EQ(points.beyond_cut_beam_index, (std::vector<int>{1}));  // not the no-return, nor 0.01
  EXPECT_EQ(points.beyond_cut_range_m, (std::vector<double>{4.5}));
}

}  // namespace
}  // namespace plywood::perception
