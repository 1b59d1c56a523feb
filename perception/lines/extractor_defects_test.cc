// Issue 13's extractor defects, one test per cause, each on a hand-made scan where the extractors
// failed before the fix.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "perception/lines/line_extractor_factory.h"
#include "perception/lines/line_scoring.h"
#include "perception/lines/scan_scene_test_support.h"

namespace plywood::perception {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(ExtractorDefectsTest, AnOpeningOfAnyWidthBreaksEveryExtractor) {
  // Two collinear wall pieces x = 2 with a 0.2 m opening between them (|y| < 0.1) and nothing
  // seen beyond it: 11 beams without a return. The breakpoint distance (capped at 0.5 m), the
  // polar-neighbour chain (0.3 m) and the RANSAC/Hough gap cut (0.3 m) all bridged it.
  ScanPoints scan;
  scan.angle_increment_rad = kPi / 360.0;
  for (int i = 0; i <= 180; ++i) {
    const double a = -kPi / 4.0 + i * scan.angle_increment_rad;
    const double y = 2.0 * std::tan(a);
    if (std::abs(y) < 0.1) continue;
    scan.Add(2.0 / std::cos(a), a, i);
  }
  // A single dropout in a wall (one beam) is not an opening.
  ScanPoints with_dropout;
  with_dropout.angle_increment_rad = scan.angle_increment_rad;
  for (std::size_t k = 0; k < scan.size(); ++k)
    if (k != 20) with_dropout.Add(scan.range_m[k], scan.bearing_rad[k], scan.beam_index[k]);
  for (const std::string& name : LineExtractorNames()) {
    const auto extractor = MakeLineExtractor(name);
    const std::vector<LineSegment> lines = extractor->Extract(scan);
    EXPECT_EQ(lines.size(), 2u) << name;
    for (const LineSegment& s : lines) {
      EXPECT_GT(std::min(std::abs(s.start.y()), std::abs(s.end.y())), 0.09) << name;
      EXPECT_EQ(std::signbit(s.start.y()), std::signbit(s.end.y())) << name << " bridged";
    }
    EXPECT_EQ(extractor->Extract(with_dropout).size(), 2u) << name;
  }
  // Without the break rule the opening is bridged: one line through empty space.
  LineExtractorOptions bridging;
  bridging.split_and_merge.breakpoints.max_missing_beams = 1000;
  bridging.incremental.breakpoints.max_missing_beams = 1000;
  bridging.polar_neighbour.max_missing_beams = 1000;
  bridging.ransac.breakpoints.max_missing_beams = 1000;
  bridging.hough.breakpoints.max_missing_beams = 1000;
  for (const std::string& name : LineExtractorNames()) {
    EXPECT_EQ(MakeLineExtractor(name, bridging)->Extract(scan).size(), 1u) << name;
  }
}

const std::vector<Eigen::Vector2d> kRoom{{-2.5, -2.0}, {3.5, -2.0}, {3.5, 3.0}, {-2.5, 3.0}};

int LinesNear(const std::vector<LineSegment>& lines, const Eigen::Vector2d& p, double radius_m) {
  int count = 0;
  for (const LineSegment& s : lines) count += s.SegmentDistance(p) < radius_m;
  return count;
}

TEST(ExtractorDefectsTest, RansacAndHoughLeaveColumnsOut) {
  // Two columns (1 cm noise): RANSAC and Hough had no round-object handling and took their chords
  // as lines; they now share split_and_merge's round-object stage (RoundObjectPoints).
  const testing::Disc near_column{{1.3, 0.2}, 0.2}, far_column{{-1.0, 2.2}, 0.25};
  const ScanPoints scan = testing::ScanScene({kRoom}, {near_column, far_column}, 0.01);
  for (const char* name : {"ransac", "hough", "split_and_merge", "incremental"}) {
    const std::vector<LineSegment> lines = MakeLineExtractor(name)->Extract(scan);
    EXPECT_EQ(LinesNear(lines, near_column.centre, near_column.radius_m + 0.05), 0) << name;
    EXPECT_EQ(LinesNear(lines, far_column.centre, far_column.radius_m + 0.05), 0) << name;
    // The walls are all there.
    std::vector<TruthSegment> walls;
    for (std::size_t k = 0; k < kRoom.size(); ++k)
      walls.push_back({kRoom[k], kRoom[(k + 1) % kRoom.size()], 100});
    EXPECT_EQ(ScoreScan(lines, walls, static_cast<long>(scan.size())).Recall(), 1.0) << name;
  }
  // Without the stage both columns give chords.
  LineExtractorOptions keep_round;
  keep_round.ransac.round_objects.reject_round_objects = false;
  keep_round.hough.round_objects.reject_round_objects = false;
  for (const char* name : {"ransac", "hough"}) {
    const std::vector<LineSegment> lines = MakeLineExtractor(name, keep_round)->Extract(scan);
    EXPECT_GE(LinesNear(lines, near_column.centre, near_column.radius_m + 0.05) +
                  LinesNear(lines, far_column.centre, far_column.radius_m + 0.05),
              1)
        << name;
  }
}

TEST(ExtractorDefectsTest, RansacAndHoughKeepFragmentsToOneSurface) {
  // A free-standing panel along y = 1 (x in [-2, 0]) and, on its infinite line, two 0.1 m posts
  // at x = 1 and 1.25: each post's left face crosses the line, 3-4 of its points lie within the
  // 3 cm inlier band, and together (0.25 m apart along the line) they made a 6-8 point fragment
  // "wall" from post to post. Runs are now cut where neighbours along the line are not neighbours
  // in the scan.
  const auto square = [](const Eigen::Vector2d& c) {
    return std::vector<Eigen::Vector2d>{
        c + Eigen::Vector2d(-0.05, -0.05), c + Eigen::Vector2d(0.05, -0.05),
        c + Eigen::Vector2d(0.05, 0.05), c + Eigen::Vector2d(-0.05, 0.05)};
  };
  const std::vector<std::vector<Eigen::Vector2d>> scene{
      kRoom, testing::Panel({-2.0, 1.0}, {0.0, 1.0}), square({1.0, 1.0}), square({1.25, 1.0})};
  std::vector<TruthSegment> truth;
  for (const auto& polygon : scene)
    for (std::size_t k = 0; k < polygon.size(); ++k)
      truth.push_back({polygon[k], polygon[(k + 1) % polygon.size()], 100});
  const ScanPoints scan = testing::ScanScene(scene, {});
  for (const char* name : {"ransac", "hough"}) {
    const std::vector<LineSegment> lines = MakeLineExtractor(name)->Extract(scan);
    for (const LineSegment& s : lines) {
      EXPECT_GE(MatchSegment(s, truth, {}), 0)
          << name << ": " << s.start.transpose() << " -> " << s.end.transpose();
    }
  }
}

TEST(ExtractorDefectsTest, AShortFaceAtACornerKeepsItsOwnPoints) {
  // Issue 13's corner contamination: a 0.3 m box face seen at 74 deg incidence 1.5 m away (about
  // 6 points) meets a long face it sees nearly head-on. A distance gate (incremental's 4 cm) left
  // 2-4 points of the long face on the short one, which turned by degrees and missed its face.
  const double incidence = 74.0 * kPi / 180.0;
  const Eigen::Vector2d n(-std::cos(incidence), std::sin(incidence));  // towards the sensor
  const Eigen::Vector2d u(n.y(), -n.x()), c(1.5, 0.0);
  const Eigen::Vector2d a = c - 0.15 * u, b = c + 0.15 * u;
  const std::vector<Eigen::Vector2d> box{a, b, b - 1.0 * n, a - 1.0 * n};
  const TruthSegment short_face{a, b, 6};
  for (const char* name : {"incremental", "split_and_merge"}) {
    int found = 0;
    for (unsigned seed = 1; seed <= 10; ++seed) {
      const ScanPoints scan = testing::ScanScene({kRoom, box}, {}, 0.01, 20.0, seed);
      for (const LineSegment& s : MakeLineExtractor(name)->Extract(scan)) {
        const std::vector<TruthSegment> one{short_face};
        if (MatchSegment(s, one, {}) == 0) {
          ++found;
          break;
        }
      }
    }
    EXPECT_GE(found, 8) << name;
  }
}

TEST(ExtractorDefectsTest, AColumnSeenWholeIsRoundEvenWhenItsFittedArcIsShort) {
  // A free-standing column of r = 0.1 m 2 m away (its own breakpoint group, about 12 points in two
  // chords, 1 cm noise): the noise inflates the fitted circle (R 0.12-0.14 m), whose centre moves
  // back, so the sampled arc on it falls under 100 deg and the two chords stayed as lines. A
  // multi-line group that one circle explains with every point on it is a round object seen
  // whole, whatever its fitted arc. A small box seen corner-on beside it (two 0.15 m faces, a
  // circle fits it only with points trimmed) keeps its faces. (incremental still keeps 4 chords in
  // 20 scans here: its lines do not cover the group the same way; not fixed yet.)
  const testing::Disc column{{0.0, 2.0}, 0.1};
  const Eigen::Vector2d box_centre(2.0, 0.3);
  std::vector<Eigen::Vector2d> box;
  for (int k = 0; k < 4; ++k) {
    const double a = k * kPi / 2.0 + std::atan2(box_centre.y(), box_centre.x());
    box.push_back(box_centre + 0.106 * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  std::vector<TruthSegment> box_faces;
  for (std::size_t k = 0; k < box.size(); ++k) box_faces.push_back({box[k], box[(k + 1) % 4], 6});
  const std::vector<Eigen::Vector2d> room{{-3.5, -3.0}, {3.5, -3.0}, {3.5, 3.5}, {-3.5, 3.5}};
  // Box faces found in 20 scans before the change (split_and_merge 30, RANSAC 15): none lost.
  for (const auto& [name, box_faces_before] :
       std::vector<std::pair<const char*, int>>{{"split_and_merge", 30}, {"ransac", 15}}) {
    int column_lines = 0, box_faces_found = 0;
    for (unsigned seed = 1; seed <= 20; ++seed) {
      const ScanPoints scan = testing::ScanScene({room, box}, {column}, 0.01, 20.0, seed);
      const std::vector<LineSegment> lines = MakeLineExtractor(name)->Extract(scan);
      column_lines += LinesNear(lines, column.centre, column.radius_m + 0.05);
      for (const LineSegment& s : lines) box_faces_found += MatchSegment(s, box_faces, {}) >= 0;
    }
    EXPECT_EQ(column_lines, 0) << name;  // 5 of 20 scans kept a chord before
    EXPECT_GE(box_faces_found, box_faces_before) << name;
  }
}

TEST(ExtractorDefectsTest, ATableLegJustInFrontOfAWallTurnsFewerLines) {
  // Tables against two walls (the generator's office tables: legs of r = 25 mm whose surface
  // stands 35 mm in front of the wall) seen 2.5-3.5 m away: a leg gives 2-3 returns 4-10 cm nearer
  // than the wall, inside the breakpoint distance, so they stay in the wall's group. The end-point
  // fit split the wall at a leg point, which then ended a piece whose chord it turned: 4-10 point
  // "walls" at 20-55 deg to the real one (office, generator seed 53: 106 of split_and_merge's 148
  // false lines). A run too few for a line of its own, standing beyond the threshold in front of
  // the chord with two points on each side near it, is left out instead. 20 noisy scans: 30 false
  // lines before, 8 now -- those left are legs whose edge return lies within the threshold of the
  // wall (it breaks the run; counting such returns in the run cost a column's arc elsewhere,
  // docs/lines.md round 12). Every wall is still found in every scan.
  const std::vector<Eigen::Vector2d> room{{-3.0, -2.5}, {2.5, -2.5}, {2.5, 3.0}, {-3.0, 3.0}};
  const double leg_centre_from_wall = 0.025 + 0.035;
  std::vector<testing::Disc> legs;
  for (const double x : {-1.9, -1.2, 0.4, 1.1})
    legs.push_back({{x, 3.0 - leg_centre_from_wall}, 0.025});
  for (const double y : {-1.3, -0.6, 0.9, 1.6})
    legs.push_back({{2.5 - leg_centre_from_wall, y}, 0.025});
  std::vector<TruthSegment> walls;
  for (std::size_t k = 0; k < room.size(); ++k) walls.push_back({room[k], room[(k + 1) % 4], 100});
  int false_lines = 0;
  int walls_found = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const ScanPoints scan = testing::ScanScene({room}, legs, 0.01, 20.0, seed);
    std::vector<char> found(walls.size(), 0);
    for (const LineSegment& s : MakeLineExtractor("split_and_merge")->Extract(scan)) {
      const int match = MatchSegment(s, walls, {});
      if (match < 0) ++false_lines;
      if (match >= 0) found[match] = 1;
    }
    for (char f : found) walls_found += f;
  }
  EXPECT_LE(false_lines, 10);
  EXPECT_EQ(walls_found, 80);
}

}  // namespace
}  // namespace plywood::perception
