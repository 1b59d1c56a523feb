#include "perception/lines/round_object_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "perception/lines/scan_points.h"
#include "perception/lines/scan_scene_test_support.h"
#include "perception/lines/split_and_merge_extractor.h"

namespace plywood::perception {
namespace {

constexpr double kPi = std::numbers::pi;

using testing::Disc;
using testing::ScanScene;

const std::vector<Eigen::Vector2d> kRoom{{-2.5, -2.0}, {3.5, -2.0}, {3.5, 3.0}, {-2.5, 3.0}};

int LinesNear(const std::vector<LineSegment>& lines, const Eigen::Vector2d& p, double radius_m) {
  int count = 0;
  for (const LineSegment& s : lines) count += s.SegmentDistance(p) < radius_m;
  return count;
}

TEST(RoundObjectFilterTest, AColumnGivesNoLinesAndTheWallsStayExact) {
  const Disc column{{1.2, 0.6}, 0.15};
  const ScanPoints scan = ScanScene({kRoom}, {column});
  SplitAndMergeOptions keep_round;
  keep_round.round_objects.reject_round_objects = false;
  EXPECT_GE(LinesNear(SplitAndMergeExtractor(keep_round).Extract(scan), column.centre, 0.2), 2)
      << "without the filter the column is cut into chords";

  const std::vector<LineSegment> lines = SplitAndMergeExtractor().Extract(scan);
  EXPECT_EQ(LinesNear(lines, column.centre, 0.2), 0);
  // The four walls, the one behind the column in two pieces, each exact.
  EXPECT_EQ(lines.size(), 5u);
  for (const LineSegment& s : lines) {
    const double x = s.r_m * std::cos(s.alpha_rad), y = s.r_m * std::sin(s.alpha_rad);
    const bool on_wall = std::abs(x - 3.5) < 1e-6 || std::abs(x + 2.5) < 1e-6 ||
                         std::abs(y - 3.0) < 1e-6 || std::abs(y + 2.0) < 1e-6;
    EXPECT_TRUE(on_wall) << "alpha " << s.alpha_rad << " r " << s.r_m;
  }
}

TEST(RoundObjectFilterTest, NoisyColumnsGoAndABoxCornerStays) {
  // 1 cm range noise (the LMS 200); columns at 1.3 and 2.4 m; a 0.4 m square box turned 45 deg so
  // the sensor sees one of its convex corners with two 0.4 m faces.
  const Disc near_column{{1.3, 0.2}, 0.2}, far_column{{-1.0, 2.2}, 0.2};
  const Eigen::Vector2d box_centre(0.3, -1.4);
  std::vector<Eigen::Vector2d> box;
  for (int k = 0; k < 4; ++k) {
    const double a = k * kPi / 2.0;
    box.push_back(box_centre + 0.2 * std::sqrt(2.0) * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  const ScanPoints scan = ScanScene({kRoom, box}, {near_column, far_column}, 0.01);
  const std::vector<LineSegment> lines = SplitAndMergeExtractor().Extract(scan);
  EXPECT_EQ(LinesNear(lines, near_column.centre, near_column.radius_m + 0.05), 0);
  EXPECT_EQ(LinesNear(lines, far_column.centre, far_column.radius_m + 0.05), 0);
  // Both visible box faces, each within 3 deg of its true direction (normals at -45 and -135 deg
  // seen from the box centre, so normal-form alpha -135 or 45 and -45 or 135 from the origin).
  int faces = 0;
  for (const LineSegment& s : lines) {
    if (s.SegmentDistance(box_centre) > 0.35) continue;
    const double folded = std::remainder(s.alpha_rad - kPi / 4.0, kPi / 2.0);
    EXPECT_LT(std::abs(folded), 3.0 * kPi / 180.0);
    ++faces;
  }
  EXPECT_EQ(faces, 2);
}

TEST(RoundObjectFilterTest, ArcsAroundTheSensorAndStraightChordsStay) {
  // Points on a circle of radius 0.4 m around the sensor (a curved wall seen from inside), cut in
  // two "lines": never an object.
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < 20; ++k) {
    const double a = -0.8 + 1.6 * k / 19.0;
    points.push_back(0.4 * Eigen::Vector2d(std::cos(a), std::sin(a)) + Eigen::Vector2d(0.1, 0));
  }
  std::vector<std::vector<int>> lines{{}, {}};
  for (int k = 0; k < 20; ++k) lines[k < 10 ? 0 : 1].push_back(k);
  RemoveRoundObjects(points, 0.01, {}, &lines);
  EXPECT_EQ(lines.size(), 2u);

  // The arc turned to face the sensor from 2 m away is what a laser sees of a column, but over
  // 92 deg only. As a whole breakpoint group (both ends are breaks, every point on the circle)
  // it is a round object seen whole: dropped (noise shrinks a small column's fitted arc under
  // 100 deg). Beside a wall line in its group (a piece of something larger) it goes too: 92 deg
  // is over the default 45 deg and the points bend far away from one straight line (a column in
  // one group with the wall behind it); at a 100 deg minimum it stays.
  for (auto& p : points) p = Eigen::Vector2d(2.1, 0.0) - (p - Eigen::Vector2d(0.1, 0.0));
  std::vector<std::vector<int>> whole = lines;
  RemoveRoundObjects(points, 0.01, {}, &whole);
  EXPECT_TRUE(whole.empty());
  std::vector<Eigen::Vector2d> with_wall = points;
  std::vector<std::vector<int>> copy = lines;
  copy.emplace_back();
  for (int k = 0; k < 8; ++k) {
    with_wall.push_back(points.back() + Eigen::Vector2d(0.0, -0.03 * (k + 1)));
    copy.back().push_back(20 + k);
  }
  std::vector<std::vector<int>> at_default = copy;
  RemoveRoundObjects(with_wall, 0.01, {}, &at_default);
  EXPECT_EQ(at_default.size(), 1u);
  RoundObjectOptions full_arc;
  full_arc.min_round_arc_deg = 100.0;
  RemoveRoundObjects(with_wall, 0.01, full_arc, &copy);
  EXPECT_EQ(copy.size(), 3u);
  RoundObjectOptions any_arc;
  any_arc.min_round_arc_deg = 0.0;
  RemoveRoundObjects(with_wall, 0.01, any_arc, &copy);
  EXPECT_EQ(copy.size(), 1u);
  // Its far side (mirrored through the centre) is never visible: kept.
  std::vector<Eigen::Vector2d> far_side;
  for (const auto& p : points) far_side.push_back(Eigen::Vector2d(4.2, 0.0) - p);
  copy = lines;
  RemoveRoundObjects(far_side, 0.01, any_arc, &copy);
  EXPECT_EQ(copy.size(), 2u);

  // A single line that is its whole group (a thin column's one chord) goes when round over
  // >= 100 deg; a straight one (a box face) stays.
  std::vector<Eigen::Vector2d> column, face;
  for (int k = 0; k < 7; ++k) {
    const double a = kPi - 1.2 + 2.4 * k / 6.0;  // 137 deg of a 5 cm column 1.5 m away
    column.push_back(Eigen::Vector2d(1.5, 0.0) + 0.05 * Eigen::Vector2d(std::cos(a), std::sin(a)));
    face.push_back(Eigen::Vector2d(1.45, -0.05 + 0.1 * k / 6.0));
  }
  std::vector<std::vector<int>> one{{0, 1, 2, 3, 4, 5, 6}};
  std::vector<std::vector<int>> copy_one = one;
  RemoveRoundObjects(face, 0.01, {}, &copy_one);
  EXPECT_EQ(copy_one.size(), 1u);
  RemoveRoundObjects(column, 0.01, {}, &one);
  EXPECT_TRUE(one.empty()) << "a thin column's single chord";
}

TEST(RoundObjectFilterTest, AThinColumnsChordOverLessThan100DegGoes) {
  // 1 cm noise shrinks the arc a thin column's few points show of their fitted circle: a 7-point
  // chord over 70 deg of a 10 cm column 2 m away, its whole breakpoint group. Round at the
  // default 45 deg; a line at the 100 deg minimum used before (issue 13: the `columns` family's
  // main false lines).
  std::vector<Eigen::Vector2d> column;
  for (int k = 0; k < 7; ++k) {
    const double a = kPi + (-35.0 + 70.0 * k / 6.0) * kPi / 180.0;
    column.push_back(Eigen::Vector2d(2.0, 0.0) + 0.1 * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  std::vector<std::vector<int>> chord{{0, 1, 2, 3, 4, 5, 6}};
  RoundObjectOptions full_arc;
  full_arc.min_round_arc_deg = 100.0;
  std::vector<std::vector<int>> before = chord;
  RemoveRoundObjects(column, 0.01, full_arc, &before);
  EXPECT_EQ(before.size(), 1u);
  RemoveRoundObjects(column, 0.01, {}, &chord);
  EXPECT_TRUE(chord.empty());

  // Thin columns (r 4-8 cm, 1.5-3 m away) in a room, 1 cm noise, 50 seeds: the chords left on
  // them by split_and_merge, now and at the old 100 deg minimum.
  const std::vector<Disc> columns{
      {{1.5, 0.8}, 0.04}, {{-1.2, 2.0}, 0.06}, {{2.6, -1.0}, 0.08}, {{-2.0, -1.2}, 0.05}};
  SplitAndMergeOptions old_options;
  old_options.round_objects.min_round_arc_deg = 100.0;
  int now = 0, old = 0;
  for (unsigned seed = 1; seed <= 50; ++seed) {
    const ScanPoints scan = ScanScene({kRoom}, columns, 0.01, 20.0, seed);
    const std::vector<LineSegment> lines = SplitAndMergeExtractor().Extract(scan);
    const std::vector<LineSegment> old_lines = SplitAndMergeExtractor(old_options).Extract(scan);
    for (const Disc& c : columns) {
      now += LinesNear(lines, c.centre, c.radius_m + 0.03);
      old += LinesNear(old_lines, c.centre, c.radius_m + 0.03);
    }
  }
  EXPECT_GT(old, 40);
  EXPECT_LT(now, 0.6 * old) << "now " << now << ", at 100 deg " << old;
}

TEST(RoundObjectFilterTest, RansacAndHoughLoseAThinColumnsSingleChordToo) {
  // A 14 cm column 2.6 m away shows 6 beams: one breakpoint group of fewer points than a run of
  // lines needs (min_round_points, 8), but enough for the single-chord rule (5). The stage RANSAC
  // and Hough share (RoundObjectPoints) must test such a group as split_and_merge does; it skipped
  // every group below min_round_points (issue 13, round 10: RANSAC's `columns` false lines).
  const Disc column{{2.6, 0.3}, 0.07};
  const auto on_column = [&](const Eigen::Vector2d& p) {
    return std::abs((p - column.centre).norm() - column.radius_m) < 0.03;
  };
  int round_seeds = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    // Seed 1 noise-free, the others with the LMS 200's 1 cm.
    const ScanPoints scan = ScanScene({kRoom}, {column}, seed == 1 ? 0.0 : 0.01, 20.0, seed);
    const std::vector<char> round =
        RoundObjectPoints(scan, BreakpointOptions{}, 0.03, RoundObjectOptions{});
    int here = 0, here_marked = 0;
    for (std::size_t i = 0; i < scan.size(); ++i) {
      if (!on_column(scan.points[i])) {
        EXPECT_FALSE(round[i]) << "a wall point marked round, seed " << seed;
        continue;
      }
      ++here;
      here_marked += round[i] != 0;
    }
    ASSERT_EQ(here, 6) << "seed " << seed;
    if (seed == 1) {
      EXPECT_EQ(here_marked, here) << "the noise-free column is round";
    }
    round_seeds += here_marked == here;
  }
  // With noise a 6-point chord's bulge and arc often fall short of the rule's (the noise-free one
  // is the test); some noisy ones pass it.
  EXPECT_GE(round_seeds, 2);
}

TEST(RoundObjectFilterTest, AColumnHalfHiddenByANearerOneIsOneRoundObject) {
  // A 0.3 m column 3 m away whose middle a 6 cm leg 1.5 m away hides: each side shows ~7 beams
  // from the leg's shadow to its silhouette, an edge chord over less than 45 deg of arc with a
  // bulge of 1-2 noise sigmas -- in one breakpoint group each, often kept as a "face". Tested
  // together across the leg (JoinRoundObjectsAcrossOccluders) they are one column.
  const Disc column{{3.0, 0.0}, 0.3};
  const Disc leg{{1.5, 0.0}, 0.06};
  const auto on_column = [&](const LineSegment& s) {
    return (s.start - column.centre).norm() < column.radius_m + 0.05 &&
           (s.end - column.centre).norm() < column.radius_m + 0.05;
  };
  SplitAndMergeOptions apart;
  apart.round_objects.join_across_occluders = false;
  int kept_apart = 0, kept_joined = 0, circles_on_column = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const ScanPoints scan = ScanScene({kRoom}, {column, leg}, 0.01, 20.0, seed);
    for (const LineSegment& s : SplitAndMergeExtractor(apart).Extract(scan))
      kept_apart += on_column(s);
    const ExtractedFeatures joined = SplitAndMergeExtractor().ExtractFeatures(scan);
    for (const LineSegment& s : joined.lines) kept_joined += on_column(s);
    for (const CircleFeature& c : joined.circles) {
      circles_on_column +=
          (c.centre - column.centre).norm() < 0.1 && std::abs(c.radius_m - column.radius_m) < 0.1;
    }
  }
  EXPECT_GE(kept_apart, 10) << "each side alone is often a line";
  EXPECT_LE(kept_joined, kept_apart / 2) << "apart " << kept_apart;
  EXPECT_GE(circles_on_column, 30) << "the column is reported as a circle across the leg";
}

TEST(RoundObjectFilterTest, CollinearWallPiecesBehindALegStayLines) {
  // The wall behind a leg in two pieces: no circle joins them, both stay exact lines.
  const Disc leg{{1.5, 0.0}, 0.06};
  const std::vector<LineSegment> lines =
      SplitAndMergeExtractor().Extract(ScanScene({kRoom}, {leg}));
  int on_far_wall = 0;
  for (const LineSegment& s : lines) {
    on_far_wall += std::abs(s.start.x() - 3.5) < 1e-6 && std::abs(s.end.x() - 3.5) < 1e-6;
  }
  EXPECT_EQ(on_far_wall, 2);
}

TEST(RoundObjectFilterTest, BadOptionsAreRejectedByField) {
  const auto message = [](const RoundObjectOptions& o) {
    try {
      o.Validate();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message({.max_round_radius_m = 0.0}).rfind("max_round_radius_m:", 0), 0u);
  EXPECT_EQ(message({.min_round_points = 2}).rfind("min_round_points:", 0), 0u);
  EXPECT_EQ(message({.min_round_arc_deg = -1.0}).rfind("min_round_arc_deg:", 0), 0u);
}

// A round object whose near side alone lies inside a range cut (round_past_range_cut.h).

constexpr double kCutM = 4.0;
// A room whose walls all lie beyond the cut: only what stands inside 4 m gives lines.
const std::vector<Eigen::Vector2d> kRoomBeyondTheCut{
    {-6.0, -6.0}, {6.0, -6.0}, {6.0, 6.0}, {-6.0, 6.0}};

std::vector<LineSegment> LinesWithCutRule(const ScanPoints& scan, bool past_cut) {
  SplitAndMergeOptions options;
  options.round_objects.round_past_range_cut = past_cut;
  return SplitAndMergeExtractor(options).Extract(scan);
}

TEST(RoundPastRangeCutTest, AColumnsCapAtTheCutIsNoLine) {
  // A 0.2 m column whose near side lies 3.96 m away: a 4 m cut keeps a 4-6 point cap, flat
  // within the 1 cm noise, framed by missing beams -- a line in a third of the scans. Past the cut
  // its flanks curve away to 4.16 m and more, then the wall behind at 6 m: one round object.
  const testing::Disc column{{4.16, 0.0}, 0.2};
  int before = 0, after = 0, returns_past_cut = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const ScanPoints scan =
        testing::ScanScene({kRoomBeyondTheCut}, {column}, 0.01, 20.0, seed, kCutM);
    returns_past_cut += !scan.beyond_cut_range_m.empty();
    before += LinesNear(LinesWithCutRule(scan, false), column.centre, column.radius_m + 0.05);
    after += LinesNear(LinesWithCutRule(scan, true), column.centre, column.radius_m + 0.05);
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
    const ScanPoints scan =
        testing::ScanScene({kRoomBeyondTheCut, wall, box}, {}, 0.01, 20.0, seed, kCutM);
    const std::vector<LineSegment> with = LinesWithCutRule(scan, true),
                                   without = LinesWithCutRule(scan, false);
    ASSERT_EQ(with.size(), without.size()) << seed;
    for (std::size_t k = 0; k < with.size(); ++k) {
      EXPECT_EQ(with[k].start, without[k].start) << seed;
      EXPECT_EQ(with[k].end, without[k].end) << seed;
    }
    wall_lines += LinesNear(with, {3.97, 0.0}, 0.05);
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
    const ScanPoints scan =
        testing::ScanScene({kRoomBeyondTheCut, wall}, {}, 0.01, 20.0, seed, kCutM);
    with_rule += static_cast<int>(LinesWithCutRule(scan, true).size());
    without_rule += static_cast<int>(LinesWithCutRule(scan, false).size());
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
