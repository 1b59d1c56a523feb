#include "perception/sonar_map/beam_free_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace plywood::perception {
namespace {

constexpr double kPi = 3.14159265358979323846;

// 5 cm cells from (0, 0), 4 x 4 m.
LogOddsGridOptions Geometry() {
  LogOddsGridOptions g;
  g.resolution_m = 0.05;
  g.origin_xy = {0.0, 0.0};
  g.width = g.height = 80;
  return g;
}

msgs::RangeRing Ring(double bearing_rad, double range_m, bool echo = true) {
  msgs::RangeRing ring;
  msgs::RangeReading r;
  r.X_RS = {0.0, 0.0, bearing_rad};
  r.range_m = range_m;
  r.echo = echo;
  ring.readings.push_back(r);
  return ring;
}

TEST(BeamFreeGridTest, AnAxisAlongXPassesEveryCellUpToTheEchoLessTheMargin) {
  BeamFreeGrid grid(Geometry(), {});
  // From (1.02, 1.02) along +x, echo at 1.0 m: free up to x = 1.97 (stop_short_m 0.05).
  grid.Integrate(Ring(0.0, 1.0), {1.02, 1.02, 0.0});
  for (int ix = 0; ix < 80; ++ix) {
    SCOPED_TRACE(ix);
    const bool on_axis = ix >= 20 && ix <= 39;  // cells [1.00, 1.05] .. [1.95, 2.00]
    EXPECT_EQ(grid.Passes(ix, 20), on_axis ? 1 : 0);
    EXPECT_EQ(grid.Passes(ix, 19), 0);
    EXPECT_EQ(grid.Passes(ix, 21), 0);
  }
  // A second reading adds a second pass; the echo's own cell never gets one.
  grid.Integrate(Ring(0.0, 1.0), {1.02, 1.02, 0.0});
  EXPECT_EQ(grid.Passes(30, 20), 2);
  EXPECT_EQ(grid.Passes(40, 20), 0);
}

TEST(BeamFreeGridTest, TheTransducersMountingAndTheRobotsHeadingPlaceTheAxis) {
  BeamFreeGrid grid(Geometry(), {});
  msgs::RangeRing ring = Ring(0.5 * kPi, 0.5);
  ring.readings[0].X_RS.x_m = 0.2;  // 0.2 m ahead of the centre, looking left
  // Robot at (2.02, 1.02) heading +y: the transducer sits at (2.02, 1.22) and looks along -x.
  grid.Integrate(ring, {2.02, 1.02, 0.5 * kPi});
  EXPECT_EQ(grid.Passes(40, 24), 1);  // at the transducer
  EXPECT_EQ(grid.Passes(31, 24), 1);  // x 1.57: 0.45 m along
  EXPECT_EQ(grid.Passes(30, 24), 0);  // beyond 0.45 m
  EXPECT_EQ(grid.Passes(41, 24), 0);  // behind it
}

TEST(BeamFreeGridTest, ObliqueAxesMissesAndFarEchoesSayNothing) {
  BeamFreeOptions options;
  options.max_range_m = 3.0;
  BeamFreeGrid grid(Geometry(), options);
  // 45 deg: an oblique axis passes convex corners it never hears.
  grid.Integrate(Ring(0.25 * kPi, 1.0), {1.02, 1.02, 0.0});
  // A specular miss.
  grid.Integrate(Ring(0.0, 1.0, false), {1.02, 1.02, 0.0});
  // Beyond max_range_m.
  grid.Integrate(Ring(0.0, 3.5), {0.02, 1.02, 0.0});
  for (int iy = 0; iy < 80; ++iy)
    for (int ix = 0; ix < 80; ++ix) ASSERT_EQ(grid.Passes(ix, iy), 0) << ix << " " << iy;
  // 8 deg off the x axis is within the 10 deg tolerance, and so is 98 deg.
  grid.Integrate(Ring(8.0 * kPi / 180.0, 1.0), {1.02, 1.02, 0.0});
  grid.Integrate(Ring(0.5 * kPi, 1.0), {1.02, 1.02, 8.0 * kPi / 180.0});
  EXPECT_EQ(grid.Passes(21, 20), 1);
  EXPECT_EQ(grid.Passes(20, 21), 1);
}

TEST(BeamFreeGridTest, EchoesPlaceTheFaceAtTheRangeAlongTheGridAxis) {
  BeamFreeGrid grid(Geometry(), {});
  // 8 deg off +x from (1.02, 1.22), echo at 1.0 m: an axis that near the face's normal hears the
  // face's perpendicular foot, so the face is at x = 2.02 (not 1.02 + cos 8 deg), heard at the
  // transducer's y.
  grid.Integrate(Ring(8.0 * kPi / 180.0, 1.0), {1.02, 1.22, 0.0});
  // -y from (2.52, 3.02), 0.4 m.
  grid.Integrate(Ring(-0.5 * kPi, 0.4), {2.52, 3.02, 0.0});
  ASSERT_EQ(grid.face_echoes().size(), 2u);
  EXPECT_EQ(grid.face_echoes()[0].direction, BeamFreeGrid::kEast);
  EXPECT_NEAR(grid.face_echoes()[0].face, 2.02, 1e-12);
  EXPECT_NEAR(grid.face_echoes()[0].lateral, 1.22, 1e-12);
  EXPECT_EQ(grid.face_echoes()[1].direction, BeamFreeGrid::kSouth);
  EXPECT_NEAR(grid.face_echoes()[1].face, 2.62, 1e-12);
  EXPECT_NEAR(grid.face_echoes()[1].lateral, 2.52, 1e-12);
}

TEST(BeamFreeGridTest, AnObliqueTransducerPlacesTheFaceItsRayNearestTheNormalHeard) {
  BeamFreeOptions options;
  options.oblique_face_max_rad = 35.0 * kPi / 180.0;
  BeamFreeGrid grid(Geometry(), options);
  // 25 deg off +x from (1.02, 1.22), echo at 1.0 m: the cone's edge ray, 10 deg off the x axis
  // towards +y, is the one nearest a face perpendicular to x, so the face lies at x = 1.02 +
  // cos 10 deg and that ray meets it at y = 1.22 + sin 10 deg.
  grid.Integrate(Ring(0.0, 1.0), {1.02, 1.22, 25.0 * kPi / 180.0});
  // 12 deg off -y from (2.52, 3.02), 0.4 m: the normal itself is inside the 15 deg cone.
  grid.Integrate(Ring(0.0, 0.4), {2.52, 3.02, -0.5 * kPi + 12.0 * kPi / 180.0});
  // 40 deg off: no plywood face echoes that obliquely (the edge ray meets it at 25 deg).
  grid.Integrate(Ring(0.0, 1.0), {1.02, 1.22, 40.0 * kPi / 180.0});
  ASSERT_EQ(grid.oblique_face_echoes().size(), 2u);
  const BeamFreeGrid::ObliqueFaceEcho& east = grid.oblique_face_echoes()[0];
  EXPECT_EQ(east.echo.direction, BeamFreeGrid::kEast);
  EXPECT_NEAR(east.echo.face, 1.02 + std::cos(10.0 * kPi / 180.0), 1e-12);
  EXPECT_NEAR(east.echo.lateral, 1.22 + std::sin(10.0 * kPi / 180.0), 1e-12);
  EXPECT_NEAR(east.from_face, 1.02, 1e-12);
  EXPECT_NEAR(east.from_lateral, 1.22, 1e-12);
  const BeamFreeGrid::ObliqueFaceEcho& south = grid.oblique_face_echoes()[1];
  EXPECT_EQ(south.echo.direction, BeamFreeGrid::kSouth);
  EXPECT_NEAR(south.echo.face, 2.62, 1e-12);
  EXPECT_NEAR(south.echo.lateral, 2.52, 1e-12);
  // They place no axis face and pass no cell: an oblique axis passes corners it never hears.
  EXPECT_TRUE(grid.face_echoes().empty());
  for (int iy = 0; iy < 80; ++iy)
    for (int ix = 0; ix < 80; ++ix) ASSERT_EQ(grid.Passes(ix, iy), 0) << ix << " " << iy;
  // By default up to 30 deg off: 25 deg is kept, 32 deg is not (its cone's edge ray meets a wall
  // at 17 deg, too near the 20 deg incidence limit for the heading's error).
  BeamFreeGrid plain(Geometry(), {});
  plain.Integrate(Ring(0.0, 1.0), {1.02, 1.22, 25.0 * kPi / 180.0});
  plain.Integrate(Ring(0.0, 1.0), {1.02, 1.22, 32.0 * kPi / 180.0});
  ASSERT_EQ(plain.oblique_face_echoes().size(), 1u);
  EXPECT_NEAR(plain.oblique_face_echoes()[0].echo.face, 1.02 + std::cos(10.0 * kPi / 180.0), 1e-12);
}

TEST(BeamFreeGridTest, AReadingAtTheBlankingRangeFreesNothingAndPlacesNoFace) {
  BeamFreeGrid grid(Geometry(), {});
  // The receiver's blanking time: a face 0.05-0.15 m away is reported at range_min_m, so the
  // axis is not known free up to 0.10 m, nor the face to be at 0.15 m.
  msgs::RangeRing ring = Ring(0.0, 0.15);
  ring.range_min_m = 0.15;
  grid.Integrate(ring, {1.02, 1.02, 0.0});
  EXPECT_EQ(grid.Passes(20, 20), 0);
  EXPECT_EQ(grid.Passes(21, 20), 0);
  EXPECT_EQ(grid.Echoes(23, 20, BeamFreeGrid::kEast), 0);
  EXPECT_TRUE(grid.face_echoes().empty());
  // Just beyond it the reading counts.
  ring.readings[0].range_m = 0.16;
  grid.Integrate(ring, {1.02, 1.02, 0.0});
  EXPECT_EQ(grid.Passes(20, 20), 1);
  EXPECT_EQ(grid.face_echoes().size(), 1u);
}

TEST(BeamFreeGridTest, OutsideTheGridIsNoPassAndBadOptionsThrow) {
  BeamFreeGrid grid(Geometry(), {});
  grid.Integrate(Ring(kPi, 2.0), {0.52, 1.02, 0.0});  // runs off the grid's west edge
  EXPECT_EQ(grid.Passes(0, 20), 1);
  EXPECT_EQ(grid.Passes(-1, 20), 0);
  BeamFreeOptions bad;
  bad.axis_tolerance_rad = 1.0;
  EXPECT_THROW(BeamFreeGrid(Geometry(), bad), std::invalid_argument);
  bad = {};
  bad.stop_short_m = -0.1;
  EXPECT_THROW(BeamFreeGrid(Geometry(), bad), std::invalid_argument);
  bad = {};
  bad.oblique_face_max_rad = 1.0;
  EXPECT_THROW(BeamFreeGrid(Geometry(), bad), std::invalid_argument);
  bad = {};
  bad.half_angle_rad = -0.1;
  EXPECT_THROW(BeamFreeGrid(Geometry(), bad), std::invalid_argument);
}

// What a real driver can hand it (docs/errors.md, the s64 fifty-third pass).
TEST(BeamFreeGridTest, AnEchoWithoutAUsableRangeOrAPoseThatIsNotFiniteWritesNothing) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  BeamFreeGrid grid(Geometry(), {});
  // On a grid axis (was: floor(NaN / step) cast to int, UBSan's float-cast-overflow) and 25 deg
  // off one (was: an oblique face at NaN).
  for (const double range : {kNan, std::numeric_limits<double>::infinity(), 0.0, -0.3}) {
    SCOPED_TRACE(range);
    grid.Integrate(Ring(0.0, range), {1.02, 1.02, 0.0});
    grid.Integrate(Ring(0.0, range), {1.02, 1.22, 25.0 * kPi / 180.0});
  }
  EXPECT_TRUE(grid.face_echoes().empty());
  EXPECT_TRUE(grid.oblique_face_echoes().empty());
  for (const msgs::Pose2D& pose :
       {msgs::Pose2D{kNan, 1.0, 0.0}, msgs::Pose2D{1.0, 1.0, kNan},
        msgs::Pose2D{1.0, -std::numeric_limits<double>::infinity(), 0.0}}) {
    try {
      grid.Integrate(Ring(0.0, 1.0), pose);
      ADD_FAILURE() << "no exception";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("X_WR: must be finite, got (", 0), 0u) << e.what();
    }
  }
  EXPECT_TRUE(grid.face_echoes().empty());
  for (int iy = 0; iy < 80; ++iy)
    for (int ix = 0; ix < 80; ++ix) ASSERT_EQ(grid.Passes(ix, iy), 0) << ix << " " << iy;
}

}  // namespace
}  // namespace plywood::perception
