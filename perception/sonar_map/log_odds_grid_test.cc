#include "perception/sonar_map/log_odds_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace plywood::perception {
namespace {

// Seed 001: P = 1 - (1 + prod p/(1-p))^-1 with prior 0.5.
TEST(CombineReadingsTest, ProductFormulaExact) {
  // 0.8 twice: prod = 4 * 4 = 16, P = 16/17.
  EXPECT_NEAR(CombineReadings({0.8, 0.8}), 16.0 / 17.0, 1e-15);
  // 0.8 then 0.2 cancel; 0.5 says nothing.
  EXPECT_NEAR(CombineReadings({0.8, 0.2}), 0.5, 1e-15);
  EXPECT_NEAR(CombineReadings({0.5, 0.5, 0.5}), 0.5, 1e-15);
  // 0.9, 0.6, 0.3: prod = 9 * 1.5 * 3/7 = 40.5/7, P = 40.5 / 47.5.
  EXPECT_NEAR(CombineReadings({0.9, 0.6, 0.3}), 40.5 / 47.5, 1e-14);
  EXPECT_NEAR(CombineReadings({}), 0.5, 0.0);
}

TEST(CombineReadingsTest, ClampsReadingsAndSum) {
  LogOddsOptions o;
  o.p_min = 0.1;
  EXPECT_NEAR(CombineReadings({1.0}, o), 0.9, 1e-15);  // a certain reading counts as 0.9
  o.log_odds_limit = std::log(4.0);                    // the sum saturates at P = 0.8
  EXPECT_NEAR(CombineReadings({0.9, 0.9, 0.9}, o), 0.8, 1e-15);
  o.p_min = 0.6;
  EXPECT_THROW(CombineReadings({0.5}, o), std::invalid_argument);
}

TEST(LogOddsGridTest, AddMatchesCombine) {
  LogOddsGridOptions o;
  o.width = 4;
  o.height = 3;
  LogOddsGrid grid(o);
  for (double p : {0.7, 0.9, 0.4}) grid.Add(2, 1, p);
  EXPECT_NEAR(grid.Probability(2, 1), CombineReadings({0.7, 0.9, 0.4}), 1e-15);
  EXPECT_EQ(grid.Probability(0, 0), 0.5);
  EXPECT_EQ(grid.CellAt(o.origin_xy + Eigen::Vector2d(0.12, 0.06)), Eigen::Vector2i(2, 1));
  EXPECT_EQ(grid.CellAt(o.origin_xy - Eigen::Vector2d(0.01, 0.0)), Eigen::Vector2i(-1, -1));
}

TEST(LogOddsGridTest, ACellOutsideTheGridOrAReadingThatIsNoProbabilityIsRefused) {
  // Add(4, 0) wrote past the row into cell (0, 1), Add(0, 3) past the end of the vector, and a
  // NaN reading made its cell NaN for good (the clamp keeps a NaN).
  LogOddsGridOptions o;
  o.width = 4;
  o.height = 3;
  LogOddsGrid grid(o);
  const auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no throw");
  };
  EXPECT_EQ(message([&] { grid.Add(4, 0, 0.9); }), "ix, iy: cell (4, 0) is outside the 4 x 3 grid");
  EXPECT_EQ(message([&] { grid.Add(0, 3, 0.9); }), "ix, iy: cell (0, 3) is outside the 4 x 3 grid");
  EXPECT_EQ(message([&] { grid.Add(-1, 0, 0.9); }),
            "ix, iy: cell (-1, 0) is outside the 4 x 3 grid");
  EXPECT_EQ(message([&] { grid.Probability(0, -1); }),
            "ix, iy: cell (0, -1) is outside the 4 x 3 grid");
  EXPECT_EQ(message([&] { grid.LogOdds(7, 7); }), "ix, iy: cell (7, 7) is outside the 4 x 3 grid");
  EXPECT_EQ(message([&] { grid.OccupiedVotes(4, 2); }),
            "ix, iy: cell (4, 2) is outside the 4 x 3 grid");
  EXPECT_EQ(message([&] { grid.Add(1, 1, std::nan("")); }),
            "p: must be a probability in [0, 1], got nan");
  EXPECT_EQ(message([&] { grid.Add(1, 1, 1.5); }), "p: must be a probability in [0, 1], got 1.5");
  // Nothing was written: every cell still holds the prior.
  for (double l : grid.log_odds()) EXPECT_EQ(l, 0.0);
  grid.Add(1, 1, 1.0);  // certainty is allowed; the clamp makes it 1 - p_min
  EXPECT_NEAR(grid.Probability(1, 1), 1.0 - o.log_odds.p_min, 1e-15);
}

TEST(LogOddsGridTest, OccupiedVotesCountTheReadingsAboveOneHalf) {
  // The log-odds saturate (a cell painted by two readings and one heard a hundred times both read
  // P ~ 1); the count of readings that called the cell occupied does not.
  LogOddsGridOptions o;
  o.width = 4;
  o.height = 3;
  LogOddsGrid grid(o);
  for (double p : {0.7, 0.9, 0.4, 0.5, 0.98}) grid.Add(2, 1, p);
  EXPECT_EQ(grid.OccupiedVotes(2, 1), 3);
  for (int k = 0; k < 100; ++k) grid.Add(1, 1, 0.98);
  for (int k = 0; k < 2; ++k) grid.Add(0, 1, 0.98);
  EXPECT_GT(grid.Probability(0, 1), 0.99);
  EXPECT_EQ(grid.OccupiedVotes(1, 1), 100);
  EXPECT_EQ(grid.OccupiedVotes(0, 1), 2);
  EXPECT_EQ(grid.OccupiedVotes(0, 0), 0);
}

// A model that says "occupied" ahead of the robot and "free" behind it.
class AheadModel : public SonarCellModel {
 public:
  double Probability(const msgs::RangeRing&, const Eigen::Vector2d& p_R) const override {
    return p_R.x() > 0.0 ? 0.8 : 0.2;
  }
};

TEST(LogOddsGridTest, LocalGridIsPlacedAtTheOdometryPose) {
  LogOddsGridOptions o;  // 5 cm cells over [-4, 4]^2
  LogOddsGrid grid(o);
  const msgs::RangeRing ring;
  grid.Integrate(AheadModel(), ring, {1.0, 1.0, M_PI / 2});  // facing +y
  // Ahead (+y) is occupied, behind free; beyond the 0.7 m half-width untouched.
  const auto at = [&](double x, double y) {
    const Eigen::Vector2i c = grid.CellAt({x, y});
    return grid.Probability(c.x(), c.y());
  };
  EXPECT_NEAR(at(1.0 + 0.025, 1.5 + 0.025), 0.8, 1e-12);
  EXPECT_NEAR(at(1.0 + 0.025, 0.5 + 0.025), 0.2, 1e-12);
  EXPECT_EQ(at(1.0, 1.8), 0.5);
  EXPECT_EQ(at(1.8, 1.0), 0.5);
}

// What a real robot's odometry can hand it (docs/errors.md, the s64 fifty-third pass).
TEST(LogOddsGridTest, APoseThatIsNotFiniteIsRefusedAndOneFarOffTheGridWritesNothing) {
  LogOddsGridOptions o;  // 5 cm cells over [-4, 4]^2
  LogOddsGrid grid(o);
  const msgs::RangeRing ring;
  try {
    grid.Integrate(AheadModel(), ring, {std::nan(""), 0.0, 0.0});
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "X_WR: must be finite, got (nan, 0, 0)");
  }
  EXPECT_THROW(grid.Integrate(AheadModel(), ring, {0.0, 0.0, INFINITY}), std::invalid_argument);
  // Far off (was: the cell bounds cast to int overflowed, UBSan's float-cast-overflow), and just
  // past the edge, where the local square still overlaps the grid.
  for (const double x : {1e10, -1e300}) grid.Integrate(AheadModel(), ring, {x, 0.0, 0.0});
  for (int iy = 0; iy < grid.height(); ++iy)
    for (int ix = 0; ix < grid.width(); ++ix) ASSERT_EQ(grid.LogOdds(ix, iy), 0.0);
  grid.Integrate(AheadModel(), ring, {4.3, 0.0, 0.0});
  EXPECT_NEAR(grid.Probability(grid.width() - 1, grid.height() / 2), 0.2, 1e-12);  // behind it
}

TEST(LogOddsGridTest, AGeometryThatPlacesNoCellIsRefusedByField) {
  const auto expect_refused = [](const LogOddsGridOptions& o, const std::string& message) {
    try {
      LogOddsGrid grid(o);
      ADD_FAILURE() << "no exception, expected " << message;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  };
  LogOddsGridOptions o;
  o.resolution_m = INFINITY;  // was: every point in cell (0, 0)
  expect_refused(o, "resolution_m: must be a finite number > 0, got inf");
  o = {};
  o.origin_xy = {std::nan(""), 0.0};  // was: no point in the grid
  expect_refused(o, "origin_xy: must be finite, got (nan, 0)");
  o = {};
  o.local_cell_m = INFINITY;  // was: every ring wrote every cell
  expect_refused(o, "local_cell_m: must be a finite number > 0, got inf");
}

}  // namespace
}  // namespace plywood::perception
