#include "perception/geometric_map/piece_curvature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "perception/geometric_map/map_aggregation.h"
#include "perception/geometric_map/scan_segmentation.h"

namespace plywood::perception {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kBeamStep = 1.8 * kDeg;  // the IR head's step
constexpr double kIrSigma = 0.005;        // the IR head's range noise

// Points on v = u^2 / (2 R) (v away from the observer at (0, -1)): curvature 1 / R exactly.
TEST(PieceCurvatureTest, ParabolaGivesItsCurvatureTowardsTheObserver) {
  const double radius = 0.4;
  std::vector<Eigen::Vector2d> points;
  std::vector<int> indices;
  for (int k = -10; k <= 10; ++k) {
    const double u = 0.01 * k;
    points.emplace_back(u, u * u / (2.0 * radius));
    indices.push_back(k + 10);
  }
  const PieceCurvature towards =
      FitPieceCurvature(points, indices, {-0.1, 0.0}, {0.1, 0.0}, {0.0, -1.0}, kIrSigma);
  EXPECT_NEAR(towards.curvature_per_m, 1.0 / radius, 1e-9);
  EXPECT_GT(towards.sigma_per_m, 0.0);
  // Seen from the other side the same points are concave: the sign turns.
  const PieceCurvature away =
      FitPieceCurvature(points, indices, {-0.1, 0.0}, {0.1, 0.0}, {0.0, 1.0}, kIrSigma);
  EXPECT_NEAR(away.curvature_per_m, -1.0 / radius, 1e-9);
  EXPECT_FALSE(RoundPieceOptions{}.IsRound(away));
}

TEST(PieceCurvatureTest, CombinedIsTheInverseVarianceMean) {
  const PieceCurvature c = PieceCurvature{4.0, 2.0}.Combined({1.0, 1.0});
  EXPECT_NEAR(c.curvature_per_m, (4.0 / 4.0 + 1.0) / (1.0 / 4.0 + 1.0), 1e-12);
  EXPECT_NEAR(c.sigma_per_m, 1.0 / std::sqrt(1.25), 1e-12);
  // An unknown curvature (pseudo segments) adds nothing.
  const PieceCurvature same = c.Combined({});
  EXPECT_EQ(same.curvature_per_m, c.curvature_per_m);
  EXPECT_EQ(same.sigma_per_m, c.sigma_per_m);
}

// One scan from the origin, beams every 1.8 deg, with the IR's Gaussian range noise; `range` gives
// a beam's true range from its direction (negative: no return).
template <typename Range>
std::vector<RangePoint> NoisyScan(std::mt19937* rng, const Range& range) {
  std::normal_distribution<double> noise(0.0, kIrSigma);
  std::vector<RangePoint> points;
  for (int i = 0; i < 200; ++i) {
    const double angle = i * kBeamStep - std::numbers::pi;
    const Eigen::Vector2d d(std::cos(angle), std::sin(angle));
    const double r = range(d);
    if (r < 0.0 || r > 3.0) continue;
    points.push_back({(r + noise(*rng)) * d, i, false});
  }
  return points;
}

std::vector<RangePoint> ColumnScan(std::mt19937* rng, const Eigen::Vector2d& centre,
                                   double radius) {
  return NoisyScan(rng, [&](const Eigen::Vector2d& d) {
    const double along = d.dot(centre);
    const double disc = along * along - centre.squaredNorm() + radius * radius;
    return disc >= 0.0 ? along - std::sqrt(disc) : -1.0;
  });
}

std::vector<RangePoint> SegmentScan(std::mt19937* rng, const Eigen::Vector2d& a,
                                    const Eigen::Vector2d& b) {
  return NoisyScan(rng, [&](const Eigen::Vector2d& d) {
    const Eigen::Vector2d ab = b - a;
    const double den = d.x() * ab.y() - d.y() * ab.x();
    if (std::abs(den) < 1e-12) return -1.0;
    const double t = (a.x() * ab.y() - a.y() * ab.x()) / den;
    const double u = (a.x() * d.y() - a.y() * d.x()) / den;
    return u >= 0.0 && u <= 1.0 ? t : -1.0;
  });
}

// A column (r = 0.15 m) 0.5-0.8 m away: 12-19 beams, the end-point fit cuts the arc into one or two
// chords of 0.12-0.2 m, each within the 2 cm inlier distance of its line; their curvature (1/0.15
// = 6.7 /m) is 5-10 standard errors above zero. Before the curvature test, 0.15 m and 0.2 m chords
// became wall segments in most scans.
TEST(PieceCurvatureTest, ColumnArcIsAClusterNotASegment) {
  std::mt19937 rng(3);
  int without_test = 0;
  for (double distance : {0.5, 0.6, 0.7, 0.8}) {
    for (int seed = 0; seed < 100; ++seed) {
      const std::vector<RangePoint> points = ColumnScan(&rng, {distance, 0.3}, 0.15);
      const ScanFeatures f = ExtractScanFeatures(points, 0, {}, {});
      EXPECT_TRUE(f.segments.empty()) << distance << " m, seed " << seed;
      ASSERT_EQ(f.clusters.size(), 1u) << distance << " m, seed " << seed;
      EXPECT_LE(f.clusters[0].box.sizes().maxCoeff(), 0.3 + 4 * kIrSigma);
      SegmentationOptions no_test;
      no_test.round_objects.max_object_radius_m = 0.0;
      without_test += !ExtractScanFeatures(points, 0, {}, no_test).segments.empty();
    }
  }
  EXPECT_GT(without_test, 200);  // the scenes do make chords the line fit accepts
}

// A straight 0.3 m box face 0.5-1 m away and a 4 m wall 1 m away, with the same noise: the round
// tests change nothing, every line stays and no piece becomes a cluster (the face's fitted
// curvature has a standard error of ~0.5 /m from the noise alone, a radius <= 0.3 m needs >= 3.3
// /m). The face gives one segment in at least 95 % of the scans (the modal fit loses a few at 0.5
// m, where its point pairs are 5 cm apart and their directions spread over many 2 deg bins, and the
// face is then a cluster with or without the round tests).
TEST(PieceCurvatureTest, StraightFaceAndLongWallStaySegments) {
  std::mt19937 rng(4);
  SegmentationOptions no_test;
  no_test.round_objects.max_object_radius_m = 0.0;
  int faces = 0, face_scans = 0;
  for (int seed = 0; seed < 100; ++seed) {
    for (double distance : {0.5, 0.75, 1.0}) {
      const std::vector<RangePoint> points = SegmentScan(&rng, {distance, 0.15}, {distance, -0.15});
      const ScanFeatures face = ExtractScanFeatures(points, 0, {}, {});
      const ScanFeatures face_no_test = ExtractScanFeatures(points, 0, {}, no_test);
      EXPECT_EQ(face.segments.size(), face_no_test.segments.size())
          << distance << " m, seed " << seed;
      EXPECT_EQ(face.clusters.size(), face_no_test.clusters.size());
      EXPECT_LE(face.segments.size(), 1u);
      for (const MapSegment& s : face.segments) {
        EXPECT_LT(std::abs(s.curvature.curvature_per_m), 4.0 * s.curvature.sigma_per_m);
      }
      faces += static_cast<int>(face.segments.size());
      ++face_scans;
    }
    const std::vector<RangePoint> points = SegmentScan(&rng, {1.0, -2.0}, {1.0, 2.0});
    const ScanFeatures wall = ExtractScanFeatures(points, 0, {}, {});
    ASSERT_FALSE(wall.segments.empty()) << "seed " << seed;
    EXPECT_EQ(wall.segments.size(), ExtractScanFeatures(points, 0, {}, no_test).segments.size());
    EXPECT_TRUE(wall.clusters.empty()) << "seed " << seed;
    for (const MapSegment& s : wall.segments) {
      EXPECT_FALSE(RoundPieceOptions{}.IsRound(s.curvature)) << "seed " << seed;
    }
  }
  EXPECT_GE(faces, 0.95 * face_scans);
}

// Three chords of one column seen from nearby poses, each bending 2 standard errors (not round
// alone): merged, the curvature is 2 sqrt(3) = 3.5 standard errors, so the segment is not
// confirmed; three straight chords are.
TEST(PieceCurvatureTest, FaintCurvatureOfMergedChordsKeepsTheSegmentUnconfirmed) {
  for (const double curvature : {6.0, 0.0}) {
    GeometricMap map;
    for (int k = 0; k < 3; ++k) {
      MapSegment s;
      s.line.start = {0.0, 0.01 * k};
      s.line.end = {0.14, 0.01 * k};
      s.line.num_points = s.inliers = 10;
      s.curvature = {curvature, 3.0};
      EXPECT_FALSE(RoundPieceOptions{}.IsRound(s.curvature));
      map.AddSegment(s);
    }
    ASSERT_EQ(map.segments().size(), 1u);
    EXPECT_EQ(map.segments()[0].observations, 3);
    EXPECT_NEAR(map.segments()[0].curvature.sigma_per_m, 3.0 / std::sqrt(3.0), 1e-12);
    EXPECT_EQ(map.Confirmed(map.segments()[0]), curvature == 0.0);
  }
}

TEST(PieceCurvatureTest, NegativeRadiusNamesTheField) {
  RoundPieceOptions o;
  o.max_object_radius_m = -1.0;
  try {
    o.Validate();
    FAIL() << "negative radius accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("max_object_radius_m:", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace plywood::perception
