#include "perception/sonar_map/contact_clearance.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "perception/sonar_map/frontier_planner.h"

namespace plywood::perception {
namespace {

// A 40 x 40 raster of 5 cm cells. The sonar heard a face along column 9 (cells x <= 9); a box
// whose south-west corner lies at cell (22, 20) was never heard, and the space from column 22 east
// is unknown, so paths stay in columns 10-21. A bump panel touched the box's corner: the contact
// point is cell (22, 20). The passage between the face and the corner is 13 cells (0.65 m) wide,
// as in generated world 46 of seed 22 (0.61 m between two box corners; the robot is 0.41 m wide).
constexpr int kW = 40, kH = 40;
constexpr int kFaceX = 9, kCornerX = 22, kCornerY = 20;
// The squeeze tier's clearance (0.30 m) and the body's corridor (0.25 m), in cells.
constexpr double kSqueezeCells = 6.0, kBodyCells = 5.0;

std::size_t Index(int ix, int iy) { return static_cast<std::size_t>(iy) * kW + ix; }

std::vector<char> HeardFace() {
  std::vector<char> heard(static_cast<std::size_t>(kW) * kH, 0);
  for (int iy = 0; iy < kH; ++iy)
    for (int ix = 0; ix <= kFaceX; ++ix) heard[Index(ix, iy)] = 1;
  return heard;
}

std::vector<char> Single(int ix, int iy) {
  std::vector<char> mask(static_cast<std::size_t>(kW) * kH, 0);
  mask[Index(ix, iy)] = 1;
  return mask;
}

// The cells from the passage's south end to its north end over cells not blocked, west of the
// unknown columns; empty when there is no way through.
std::vector<Eigen::Vector2i> WayThrough(const std::vector<char>& blocked) {
  std::vector<char> traversable(blocked.size(), 0), goal(blocked.size(), 0);
  for (int iy = 0; iy < kH; ++iy)
    for (int ix = 0; ix < kCornerX; ++ix) {
      traversable[Index(ix, iy)] = !blocked[Index(ix, iy)];
      goal[Index(ix, iy)] = traversable[Index(ix, iy)] && iy == kH - 1;
    }
  const Eigen::Vector2i start(16, 0);
  if (!traversable[Index(start.x(), start.y())]) return {};
  return ShortestCellPath(traversable, goal, kW, kH, start);
}

TEST(ContactClearanceTest, AContactAtAnUnheardCornerBlockingLikeAHeardCellClosesThePassage) {
  const std::vector<char> blocked =
      BlockedCells(HeardFace(), Single(kCornerX, kCornerY), kW, kH, kSqueezeCells, 0.0);
  EXPECT_TRUE(WayThrough(blocked).empty());
}

TEST(ContactClearanceTest, AContactKeptAtTheBodysClearanceLeavesThePassageOpen) {
  const std::vector<char> blocked =
      BlockedCells(HeardFace(), Single(kCornerX, kCornerY), kW, kH, kSqueezeCells, kBodyCells);
  const std::vector<Eigen::Vector2i> way = WayThrough(blocked);
  ASSERT_FALSE(way.empty());
  EXPECT_EQ(way.back().y(), kH - 1);
  // Every cell of the way keeps the body's clearance from the contact and the tier's from the face.
  for (const Eigen::Vector2i& c : way) {
    EXPECT_GT(std::hypot(c.x() - kCornerX, c.y() - kCornerY), kBodyCells) << c.transpose();
    EXPECT_GT(c.x() - kFaceX, kSqueezeCells) << c.transpose();
  }
}

TEST(ContactClearanceTest, TheCornerHeardBySonarKeepsTheTiersClearance) {
  // The same corner as a heard cell (its face may lie anywhere in the cell and the beam): closed.
  std::vector<char> heard = HeardFace();
  heard[Index(kCornerX, kCornerY)] = 1;
  const std::vector<char> none(heard.size(), 0);
  EXPECT_TRUE(WayThrough(BlockedCells(heard, none, kW, kH, kSqueezeCells, kBodyCells)).empty());
}

TEST(ContactClearanceTest, ATierClearanceBelowTheContactClearanceIsKept) {
  // min(tier, contact): a 4-cell tier keeps 4 cells from the contact, not 5.
  const std::vector<char> none(static_cast<std::size_t>(kW) * kH, 0);
  const std::vector<char> blocked =
      BlockedCells(none, Single(kCornerX, kCornerY), kW, kH, 4.0, kBodyCells);
  EXPECT_TRUE(blocked[Index(kCornerX - 4, kCornerY)]);
  EXPECT_FALSE(blocked[Index(kCornerX - 5, kCornerY)]);
  // And at the body's clearance, 5 cells are blocked, 6 are not.
  const std::vector<char> wide =
      BlockedCells(none, Single(kCornerX, kCornerY), kW, kH, kSqueezeCells, kBodyCells);
  EXPECT_TRUE(wide[Index(kCornerX - 5, kCornerY)]);
  EXPECT_FALSE(wide[Index(kCornerX - 6, kCornerY)]);
}

}  // namespace
}  // namespace plywood::perception
