#include "eval/geometric_map/joined_faces.h"

#include <gtest/gtest.h>

namespace plywood::eval {
namespace {

// The face of a box seen from +y (counter-clockwise around the box: from larger x to smaller).
sim::WallSegment TopFace(double x0, double x1, double y) {
  sim::WallSegment s;
  s.a = {x1, y};
  s.b = {x0, y};
  return s;
}

// Two cabinets 5 cm apart against a wall: one surface to a segmentation that breaks at 15 cm,
// spanning both; 30 cm apart they stay two (one with a 31 cm limit).
TEST(JoinedFacesTest, CollinearFacesJoinAcrossGapsUpToTheLimit) {
  const std::vector<sim::WallSegment> faces = {TopFace(0.0, 1.0, 0.5), TopFace(1.05, 2.05, 0.5),
                                               TopFace(2.35, 3.0, 0.5)};
  const std::vector<JoinedFace> joined = JoinCollinearFaces(faces, 0.15);
  ASSERT_EQ(joined.size(), 2u);
  EXPECT_EQ(joined[0].members, (std::vector<int>{0, 1}));
  EXPECT_TRUE(joined[0].a.isApprox(Eigen::Vector2d(2.05, 0.5)));
  EXPECT_TRUE(joined[0].b.isApprox(Eigen::Vector2d(0.0, 0.5)));
  EXPECT_EQ(joined[1].members, (std::vector<int>{2}));
  EXPECT_EQ(JoinCollinearFaces(faces, 0.31).size(), 1u);
}

// The two faces of an 18 mm partition face opposite ways; a face 2 mm behind another, or turned by
// 0.1 deg, is not on its line: none of them join.
TEST(JoinedFacesTest, OppositeOffsetOrTurnedFacesStaySeparate) {
  sim::WallSegment back;  // the partition's other face, counter-clockwise: from smaller x
  back.a = {1.0, 0.482};
  back.b = {2.0, 0.482};
  sim::WallSegment turned = TopFace(1.0, 2.0, 0.5);
  turned.b.y() += 1.0 * std::tan(0.1 * 3.14159265358979 / 180.0);
  const std::vector<sim::WallSegment> faces = {TopFace(0.0, 1.0, 0.5), back,
                                               TopFace(1.0, 2.0, 0.502), turned};
  EXPECT_EQ(JoinCollinearFaces(faces, 0.15).size(), 4u);
}

// The overlap along the face's line, whichever way the segment runs and off the line or not: a
// segment from x = 0.2 to 1.5 covers 0.8 m of a face from x = 0 to 1; one past its end covers none.
TEST(JoinedFacesTest, CoveredLengthIsTheOverlapAlongTheFace) {
  const sim::WallSegment face = TopFace(0.0, 1.0, 0.5);
  EXPECT_NEAR(CoveredLengthM(face, {0.2, 0.51}, {1.5, 0.49}), 0.8, 1e-12);
  EXPECT_NEAR(CoveredLengthM(face, {1.5, 0.49}, {0.2, 0.51}), 0.8, 1e-12);
  EXPECT_NEAR(CoveredLengthM(face, {-1.0, 0.5}, {3.0, 0.5}), 1.0, 1e-12);
  EXPECT_NEAR(CoveredLengthM(face, {0.3, 0.5}, {0.4, 0.5}), 0.1, 1e-12);
  EXPECT_EQ(CoveredLengthM(face, {1.05, 0.5}, {2.0, 0.5}), 0.0);
  // The 18 mm end of a partition on the line of a wall's face, under a segment along the wall.
  EXPECT_NEAR(CoveredLengthM(TopFace(1.0, 1.018, 0.5), {0.0, 0.5}, {1.1, 0.5}), 0.018, 1e-12);
}

}  // namespace
}  // namespace plywood::eval
