// Mixed pixels at the ends of a breakpoint group (mixed_pixel_ends.h), on hand-made noise-free
// scans.

#include "perception/lines/mixed_pixel_ends.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "perception/lines/incremental_extractor.h"
#include "perception/lines/split_and_merge_extractor.h"

namespace plywood::perception {
namespace {

constexpr double kStep = std::numbers::pi / 360.0;  // 0.5 deg, the LMS 200's

// A wall x = 3 m seen over +-20 deg, and in front of it on beams 40-42 a thin flat face 1 m away
// (a table leg); beam 43 straddles the leg's edge and reports a range between the two (1.15 m).
ScanPoints LegWithMixedPixel(bool mixed_pixel) {
  ScanPoints scan;
  scan.angle_increment_rad = kStep;
  for (int i = 0; i <= 80; ++i) {
    const double bearing = -20.0 * std::numbers::pi / 180.0 + i * kStep;
    double range = 3.0 / std::cos(bearing);
    if (i >= 40 && i <= 42) range = 1.0;
    if (i == 43 && mixed_pixel) range = 1.15;
    scan.Add(range, bearing, i);
  }
  return scan;
}

int LinesCloserThan(const std::vector<LineSegment>& lines, double range_m) {
  int count = 0;
  for (const LineSegment& s : lines) count += std::min(s.start.norm(), s.end.norm()) < range_m;
  return count;
}

TEST(MixedPixelEndsTest, ALegAndItsMixedPixelGiveNoLineAlongTheBeam) {
  // The three leg points and the mixed pixel form one breakpoint group (the 0.15 m jump is inside
  // the 0.2 m breakpoint floor) that fits a 4-point line 0.15 m long pointing at the sensor; the
  // split threshold (4 cm) does not cut it. Without the mixed pixel the leg's 3 points make no
  // line (4 points needed), and with it they must not either.
  const SplitAndMergeExtractor extractor;
  const std::vector<LineSegment> with = extractor.Extract(LegWithMixedPixel(true));
  EXPECT_EQ(LinesCloserThan(with, 2.0), 0);
  EXPECT_EQ(LinesCloserThan(extractor.Extract(LegWithMixedPixel(false)), 2.0), 0);
  // The wall behind is still found on both sides of the leg.
  EXPECT_EQ(with.size(), 2u);
}

TEST(MixedPixelEndsTest, TheIncrementalExtractorEndsAWallAtItsLastTrueReturn) {
  // A wall x = 2 m on beams 0-20 with +-1 cm range noise (alternating), then beam 21 straddling
  // its edge: a mixed pixel 3.8 cm behind it -- inside the incremental extractor's 4 cm line
  // tolerance and the robust refit's 3 MAD-sigma band, but 3.8 noise sigmas off the wall's line --
  // then an opening (no return on beams 22-30) and a far wall 5 m away. The incremental extractor's
  // group ends at that opening and the same stage as split_and_merge's (TrimGroupMixedPixelEnds)
  // drops the mixed pixel: the wall ends at beam 20 (y = 2 tan 10 deg = 0.353 m), not at the
  // mixed pixel's 0.377 m.
  ScanPoints scan;
  scan.angle_increment_rad = kStep;
  for (int i = 0; i <= 20; ++i) {
    scan.Add((2.0 + (i % 2 == 0 ? 0.01 : -0.01)) / std::cos(i * kStep), i * kStep, i);
  }
  scan.Add(2.038 / std::cos(21 * kStep), 21 * kStep, 21);
  for (int i = 31; i <= 50; ++i) scan.Add(5.0 / std::cos(i * kStep), i * kStep, i);
  const std::vector<LineSegment> lines = IncrementalExtractor().Extract(scan);
  int walls = 0;
  for (const LineSegment& s : lines) {
    if (std::max(s.start.x(), s.end.x()) > 3.0) continue;  // the far wall
    ++walls;
    EXPECT_LT(std::max(s.start.y(), s.end.y()), 0.365);
  }
  EXPECT_EQ(walls, 1);
}

TEST(MixedPixelEndsTest, TrimsOnlyAnEndPointBetweenTheTwoSurfaces) {
  // A wall x = 2 m on beams 0-20, then an opening (no return on beams 21-30) and a far wall.
  ScanPoints scan;
  scan.angle_increment_rad = kStep;
  for (int i = 0; i <= 20; ++i) scan.Add(2.0 / std::cos(i * kStep), i * kStep, i);
  scan.Add(2.3 / std::cos(21 * kStep), 21 * kStep, 21);  // a mixed pixel 0.3 m behind the wall
  for (int i = 31; i <= 50; ++i) scan.Add(5.0 / std::cos(i * kStep), i * kStep, i);
  std::vector<int> wall;
  for (int i = 0; i <= 20; ++i) wall.push_back(i);
  const BreakpointOptions breakpoints;
  // The wall's own end points lie on it: nothing is trimmed, at either end.
  std::vector<int> line = wall;
  TrimMixedPixelEnds(scan, breakpoints, true, true, &line);
  EXPECT_EQ(line, wall);
  // With the mixed pixel as its last point (the group's end): trimmed, and only it.
  line = wall;
  line.push_back(21);
  TrimMixedPixelEnds(scan, breakpoints, true, true, &line);
  EXPECT_EQ(line, wall);
  // Not at a group end (a neighbouring line of the same group continues there): left alone.
  line = wall;
  line.push_back(21);
  TrimMixedPixelEnds(scan, breakpoints, true, false, &line);
  EXPECT_EQ(line.size(), wall.size() + 1);
  // A point in front of the wall, away from the surface past the break, is not between the two.
  ScanPoints in_front = scan;
  in_front.range_m[21] = 1.7 / std::cos(21 * kStep);
  in_front.points[21] =
      in_front.range_m[21] * Eigen::Vector2d(std::cos(21 * kStep), std::sin(21 * kStep));
  line = wall;
  line.push_back(21);
  TrimMixedPixelEnds(in_front, breakpoints, true, true, &line);
  EXPECT_EQ(line.size(), wall.size() + 1);
}

TEST(MixedPixelEndsTest, AFaceAtGrazingIncidenceKeepsItsEndPoint) {
  // A face 8 deg off the beam, from 2 m: its ranges grow by 0.13-0.18 m a beam, more than a
  // surface at the breakpoint's 10 deg incidence may (0.15 m at 2.3 m), yet every point lies on
  // it; past its far end the next return is 5 m away.
  ScanPoints scan;
  scan.angle_increment_rad = kStep;
  const double grazing = 8.0 * std::numbers::pi / 180.0;
  for (int i = 0; i <= 3; ++i)
    scan.Add(2.0 * std::sin(grazing) / std::sin(grazing - i * kStep), i * kStep, i);
  scan.Add(5.0, 4 * kStep, 4);
  std::vector<int> line{0, 1, 2, 3};
  TrimMixedPixelEnds(scan, BreakpointOptions{}, true, true, &line);
  EXPECT_EQ(line.size(), 4u);
  // The same end point 4 cm behind the face (4 sigma off its line) is a mixed pixel.
  ScanPoints mixed = scan;
  mixed.range_m[3] += 0.04 / std::sin(grazing - 3 * kStep);
  mixed.points[3] = mixed.range_m[3] * Eigen::Vector2d(std::cos(3 * kStep), std::sin(3 * kStep));
  line = {0, 1, 2, 3};
  TrimMixedPixelEnds(mixed, BreakpointOptions{}, true, true, &line);
  EXPECT_EQ(line.size(), 3u);
}

}  // namespace
}  // namespace plywood::perception
