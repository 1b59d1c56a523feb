#include "perception/lines/chords_of_known_round_objects.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "msgs/shortest_number.h"
#include "perception/lines/round_objects_of_quiet_scan.h"
#include "perception/lines/scan_scene_test_support.h"
#include "perception/lines/split_and_merge_extractor.h"

namespace plywood::perception {
namespace {

using testing::Disc;
using testing::ScanScene;

constexpr double kPi = std::numbers::pi;
constexpr int kScans = 10;  // seed 000's scan pairs per spot

const std::vector<Eigen::Vector2d> kRoom{{-2.5, -2.0}, {3.5, -2.0}, {3.5, 3.0}, {-2.5, 3.0}};

// The per-beam median of scans taken from one spot (every beam returns in these scenes).
ScanPoints MedianScan(const std::vector<ScanPoints>& scans) {
  std::map<int, std::vector<double>> ranges;
  std::map<int, double> bearings;
  for (const ScanPoints& scan : scans) {
    for (std::size_t i = 0; i < scan.size(); ++i) {
      ranges[scan.beam_index[i]].push_back(scan.range_m[i]);
      bearings[scan.beam_index[i]] = scan.bearing_rad[i];
    }
  }
  ScanPoints median;
  for (auto& [beam, r] : ranges) {
    std::sort(r.begin(), r.end());
    const std::size_t k = r.size();
    median.Add(k % 2 ? r[k / 2] : 0.5 * (r[k / 2 - 1] + r[k / 2]), bearings[beam], beam);
  }
  median.angle_increment_rad = scans.front().angle_increment_rad;
  median.closed = true;
  return median;
}

// The round objects of the median of the spot's scans, split_and_merge's noise set to the
// median's (1.25 sigma / sqrt(10)).
std::vector<CircleFeature> RoundObjectsOfMedian(const std::vector<ScanPoints>& scans) {
  SplitAndMergeOptions quiet;
  quiet.breakpoints.sigma_m = 0.01 * 1.2533 / std::sqrt(static_cast<double>(kScans));
  return RoundObjectsOfQuietScan(MedianScan(scans), quiet);
}

std::vector<ScanPoints> ScansOf(const std::vector<std::vector<Eigen::Vector2d>>& polygons,
                                const std::vector<Disc>& discs) {
  std::vector<ScanPoints> scans;
  for (unsigned seed = 1; seed <= kScans; ++seed)
    scans.push_back(ScanScene(polygons, discs, 0.01, 20.0, seed));
  return scans;
}

int LinesNear(const std::vector<LineSegment>& lines, const Eigen::Vector2d& p, double radius_m) {
  int count = 0;
  for (const LineSegment& s : lines) count += s.SegmentDistance(p) < radius_m;
  return count;
}

// A square box of side `side_m` centred at `centre`, turned by `turn_rad`.
std::vector<Eigen::Vector2d> Box(const Eigen::Vector2d& centre, double side_m, double turn_rad) {
  std::vector<Eigen::Vector2d> corners;
  for (int k = 0; k < 4; ++k) {
    const double a = turn_rad + kPi / 4.0 + k * kPi / 2.0;
    corners.push_back(centre + side_m / std::sqrt(2.0) * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return corners;
}

TEST(ChordsOfKnownRoundObjectsTest, ThinColumnsChordsGoWhenTheSpotsMedianShowsThem) {
  // Thin columns (r 4-8 cm, 1.5-3 m away): in one noisy scan their 4-7 point chords bulge by 1-2
  // noise sigmas, so split_and_merge keeps some as lines; the median of the spot's 10 scans shows
  // each column round, and the chords on its rim go from every scan.
  const std::vector<Disc> columns{{{1.5, 0.8}, 0.04},
                                  {{-1.2, 2.0}, 0.06},
                                  {{2.6, -1.0}, 0.08},
                                  {{-2.0, -1.2}, 0.05},
                                  {{2.8, 0.9}, 0.075}};
  const std::vector<ScanPoints> scans = ScansOf({kRoom}, columns);
  const std::vector<CircleFeature> known = RoundObjectsOfMedian(scans);
  int chords_before = 0, chords_after = 0, walls_before = 0, walls_after = 0;
  for (const ScanPoints& scan : scans) {
    std::vector<LineSegment> lines = SplitAndMergeExtractor().Extract(scan);
    for (const Disc& c : columns) chords_before += LinesNear(lines, c.centre, c.radius_m + 0.03);
    walls_before += static_cast<int>(lines.size());
    RemoveChordsOfKnownRoundObjects(scan, known, 0.01, {}, &lines);
    for (const Disc& c : columns) chords_after += LinesNear(lines, c.centre, c.radius_m + 0.03);
    walls_after += static_cast<int>(lines.size());
  }
  walls_before -= chords_before;
  walls_after -= chords_after;
  EXPECT_GE(chords_before, 5) << "the scans alone leave chords of the thin columns";
  EXPECT_EQ(chords_after, 0);
  EXPECT_EQ(walls_after, walls_before) << "every wall line stays";
}

TEST(ChordsOfKnownRoundObjectsTest, SmallBoxFacesStayLines) {
  // 0.12-0.17 m boxes 2.5-3.5 m away, seen face-on or with a neighbouring face at grazing
  // incidence (stop 42: the column's shape in one scan). The median shows them flat, so no known
  // round object lies on them and every scan keeps exactly its lines.
  const std::vector<std::vector<Eigen::Vector2d>> scene{
      kRoom, Box({2.9, 0.4}, 0.15, 0.0), Box({-1.0, 2.3}, 0.12, 0.3), Box({2.7, -1.4}, 0.17, -0.2),
      Box({-2.0, -1.0}, 0.15, 0.1)};
  const std::vector<ScanPoints> scans = ScansOf(scene, {});
  const std::vector<CircleFeature> known = RoundObjectsOfMedian(scans);
  for (const ScanPoints& scan : scans) {
    std::vector<LineSegment> lines = SplitAndMergeExtractor().Extract(scan);
    const std::size_t before = lines.size();
    EXPECT_EQ(RemoveChordsOfKnownRoundObjects(scan, known, 0.01, {}, &lines), 0);
    EXPECT_EQ(lines.size(), before);
  }
}

TEST(ChordsOfKnownRoundObjectsTest, ALineOnACirclesRimGoesAndOneOffItStays) {
  // Noise-free: a 6-point chord of a 0.1 m circle goes; the same points shifted 5 cm outwards
  // (a flat face in front of it) and a line longer than the diameter stay.
  ScanPoints scan;
  const Eigen::Vector2d centre(2.0, 0.0);
  for (int k = 0; k < 6; ++k) {
    const double a = kPi + (-30.0 + 12.0 * k) * kPi / 180.0;
    const Eigen::Vector2d p = centre + 0.1 * Eigen::Vector2d(std::cos(a), std::sin(a));
    scan.Add(p.norm(), std::atan2(p.y(), p.x()), k);
  }
  CircleFeature circle;
  circle.centre = centre;
  circle.radius_m = 0.1;
  const std::vector<CircleFeature> known{circle};
  LineSegment chord;
  chord.start = scan.points.front();
  chord.end = scan.points.back();
  chord.first_index = 0;
  chord.last_index = 5;
  std::vector<LineSegment> lines{chord};
  EXPECT_EQ(RemoveChordsOfKnownRoundObjects(scan, known, 0.01, {}, &lines), 1);
  EXPECT_TRUE(lines.empty());

  CircleFeature behind = circle;
  behind.centre.x() += 0.05;
  lines = {chord};
  EXPECT_EQ(
      RemoveChordsOfKnownRoundObjects(scan, std::vector<CircleFeature>{behind}, 0.01, {}, &lines),
      0);
  CircleFeature tiny = circle;
  tiny.radius_m = 0.02;
  lines = {chord};
  EXPECT_EQ(
      RemoveChordsOfKnownRoundObjects(scan, std::vector<CircleFeature>{tiny}, 0.01, {}, &lines), 0);
  // The same six points, all on the rim, but the line's ends reach 0.1 m past them: 0.3 m, longer
  // than the diameter + 3 cm, so it is more than a chord (s63 review: `tiny` above is off the rim
  // too, so it left the length test untested).
  LineSegment longer = chord;
  const Eigen::Vector2d along = (chord.end - chord.start).normalized();
  longer.start -= 0.1 * along;
  longer.end += 0.1 * along;
  lines = {longer};
  EXPECT_EQ(RemoveChordsOfKnownRoundObjects(scan, known, 0.01, {}, &lines), 0);
}

// A lab's own list of round objects, or options out of range (docs/errors.md, the s64 fifty-third
// pass): each is refused by name, the lines untouched.
TEST(ChordsOfKnownRoundObjectsTest, ACircleOrOptionNoTestCanUseIsRefusedByName) {
  ScanPoints scan;
  const Eigen::Vector2d centre(2.0, 0.0);
  for (int k = 0; k < 6; ++k) {
    const double a = kPi + (-30.0 + 12.0 * k) * kPi / 180.0;
    const Eigen::Vector2d p = centre + 0.1 * Eigen::Vector2d(std::cos(a), std::sin(a));
    scan.Add(p.norm(), std::atan2(p.y(), p.x()), k);
  }
  LineSegment chord;
  chord.start = scan.points.front();
  chord.end = scan.points.back();
  chord.first_index = 0;
  chord.last_index = 5;
  CircleFeature good;
  good.centre = {5.0, 5.0};  // far from the line: it stays
  good.radius_m = 0.1;
  const auto expect_refused = [&](const std::vector<CircleFeature>& known, double noise_sigma_m,
                                  const KnownRoundObjectOptions& options,
                                  const std::string& message) {
    std::vector<LineSegment> lines{chord};
    try {
      RemoveChordsOfKnownRoundObjects(scan, known, noise_sigma_m, options, &lines);
      ADD_FAILURE() << "no exception, expected " << message;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
    EXPECT_EQ(lines.size(), 1u);
  };
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (const double radius : {0.0, -0.1, kNan, kInf}) {
    CircleFeature bad = good;
    bad.radius_m = radius;
    expect_refused({good, bad}, 0.01, {},
                   "known_round_objects[1].radius_m: must be a finite number > 0, got " +
                       msgs::ShortestNumber(radius));
  }
  CircleFeature nowhere = good;
  nowhere.centre = {kNan, 0.0};
  expect_refused({nowhere}, 0.01, {},
                 "known_round_objects[0].centre: must be finite, got (nan, 0)");
  expect_refused({good}, kNan, {}, "noise_sigma_m: must be a finite number > 0, got nan");
  expect_refused({good}, 0.0, {}, "noise_sigma_m: must be a finite number > 0, got 0");
  KnownRoundObjectOptions options;
  options.rim_sigmas = kInf;
  expect_refused({good}, 0.01, options, "rim_sigmas: must be a finite number > 0, got inf");
  // A fraction of 0 removed every line short enough, on no rim at all (was: the chord went).
  options = {};
  options.min_on_rim_fraction = 0.0;
  expect_refused({good}, 0.01, options, "min_on_rim_fraction: must be in (0, 1], got 0");
  options.min_on_rim_fraction = kNan;
  expect_refused({good}, 0.01, options, "min_on_rim_fraction: must be in (0, 1], got nan");
  // A circle with its centre at the sensor is a circle like any other.
  CircleFeature at_sensor = good;
  at_sensor.centre = {0.0, 0.0};
  std::vector<LineSegment> lines{chord};
  EXPECT_EQ(RemoveChordsOfKnownRoundObjects(scan, std::vector<CircleFeature>{at_sensor}, 0.01, {},
                                            &lines),
            0);
}

}  // namespace
}  // namespace plywood::perception
