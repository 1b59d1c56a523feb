#include "perception/geometric_map/range_fusion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "perception/geometric_map/geometric_mapper.h"
#include "tests/support/synthetic_scan.h"

namespace plywood::perception {
namespace {

// The IR sees a wall at x = 2 (1.8 m from a transducer at (0.2, 0) facing +x); beam 100 points
// along +x (beams from -180 deg in 1.8 deg steps).
class RangeFusionTest : public ::testing::Test {
 protected:
  msgs::LaserScan ir = test::SyntheticScan({{{2.0, -5.0}, {2.0, 5.0}}}, {}, 200, 3.0);
  msgs::RangeRing Sonar(double range_m) const {
    msgs::RangeRing ring;
    ring.readings.push_back({{0.2, 0.0, 0.0}, range_m, true});
    return ring;
  }
  std::vector<RangePoint> IrOnly() const {
    FusionOptions o;
    o.source = RangeSource::kIrOnly;
    return FuseRanges(ir, nullptr, o);
  }
  static void ExpectSame(const std::vector<RangePoint>& a, const std::vector<RangePoint>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].beam, b[i].beam);
      EXPECT_EQ(a[i].p_R, b[i].p_R);
      EXPECT_FALSE(a[i].from_sonar);
    }
  }
};

TEST_F(RangeFusionTest, SonarFartherThanIrIsIgnored) {
  const msgs::RangeRing sonar = Sonar(2.5);  // e.g. a multipath echo
  ExpectSame(FuseRanges(ir, &sonar, {}), IrOnly());
}

TEST_F(RangeFusionTest, SonarWithinTauKeepsTheIr) {
  const msgs::RangeRing sonar = Sonar(1.85);  // 5 cm beyond the IR's 1.8 m, tau 0.1 m
  ExpectSame(FuseRanges(ir, &sonar, {}), IrOnly());
}

TEST_F(RangeFusionTest, SonarNearerReplacesTheIrAroundItsAxis) {
  const msgs::RangeRing sonar = Sonar(1.0);  // a glass panel at x = 1.2 the IR looked through
  const std::vector<RangePoint> fused = FuseRanges(ir, &sonar, {});
  const std::vector<RangePoint> ir_only = IrOnly();
  ASSERT_EQ(fused.size(), ir_only.size());
  int replaced = 0;
  for (std::size_t i = 0; i < fused.size(); ++i) {
    const int beam = fused[i].beam;
    if (beam == 100) {
      EXPECT_TRUE(fused[i].from_sonar);
      EXPECT_NEAR(fused[i].p_R.x(), 1.2, 1e-12);
      EXPECT_NEAR(fused[i].p_R.y(), 0.0, 1e-12);
    }
    if (fused[i].from_sonar) {
      ++replaced;
      EXPECT_NEAR(fused[i].p_R.x(), 1.2, 1e-12);  // on the surface square to the axis
      // Within 10 deg (fill_half_angle_deg) of the axis seen from the transducer.
      EXPECT_LE(std::abs(fused[i].p_R.y()), std::tan(10.0 * std::numbers::pi / 180.0) + 1e-12);
    } else {
      EXPECT_EQ(fused[i].p_R, ir_only[i].p_R);
    }
  }
  // Beams at 0, +-1.8, ..., +-7.2 deg (their points 1.0 m from the transducer subtend less).
  EXPECT_EQ(replaced, 9);
}

TEST_F(RangeFusionTest, SingleSourceModes) {
  const msgs::RangeRing sonar = Sonar(1.0);
  FusionOptions ir_only;
  ir_only.source = RangeSource::kIrOnly;
  ExpectSame(FuseRanges(ir, &sonar, ir_only), IrOnly());
  FusionOptions sonar_only;
  sonar_only.source = RangeSource::kSonarOnly;
  const std::vector<RangePoint> points = FuseRanges(ir, &sonar, sonar_only);
  ASSERT_EQ(points.size(), 9u);
  for (const RangePoint& p : points) EXPECT_TRUE(p.from_sonar);
  // A sonar echo 1.8 m out (the wall itself) gives the wall's points in sonar-only mode.
  const msgs::RangeRing wall_echo = Sonar(1.8);
  const std::vector<RangePoint> wall = FuseRanges(ir, &wall_echo, sonar_only);
  ASSERT_EQ(wall.size(), 11u);  // beams within 9 deg: 1.8 tan(10 deg) at 2 m
  for (const RangePoint& p : wall) EXPECT_NEAR(p.p_R.x(), 2.0, 1e-12);
}

TEST_F(RangeFusionTest, TauNaNNamesTheField) {
  FusionOptions o;
  o.tau_m = std::nan("");
  try {
    o.Validate();
    FAIL() << "NaN tau accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("tau_m:", 0), 0u) << e.what();
  }
}

TEST_F(RangeFusionTest, AScanWhoseAnglesCannotPlaceItsBeamsIsRefusedByField) {
  // angle_increment_rad 0: every IR beam on one ray, the wall a spray of points along it; a NaN
  // angle: every point NaN, and the geometric map's lines with them.
  msgs::LaserScan bad = ir;
  bad.angle_increment_rad = 0.0;
  EXPECT_THROW(
      {
        try {
          FuseRanges(bad, nullptr, {});
        } catch (const std::invalid_argument& e) {
          EXPECT_STREQ(e.what(), "angle_increment_rad: must be finite and non-zero, got 0");
          throw;
        }
      },
      std::invalid_argument);
  bad = ir;
  bad.angle_min_rad = std::nan("");
  EXPECT_THROW(FuseRanges(bad, nullptr, {}), std::invalid_argument);
}

TEST_F(RangeFusionTest, TheMapperRefusesAPoseThatIsNotFinite) {
  // A NaN odometry pose put NaN segments into the map for good (every later scan merged with them).
  GeometricMapper mapper(GeometricMapOptions{});
  try {
    mapper.AddScan(ir, nullptr, {std::nan(""), 0.0, 0.0});
    ADD_FAILURE() << "no throw; segments " << mapper.map().segments().size();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "X_OR: must be finite, got (nan, 0, 0)");
  }
  EXPECT_TRUE(mapper.map().segments().empty());
  mapper.AddScan(ir, nullptr, {0.0, 0.0, 0.0});
  // A NaN heading once the map has a reference crashed the pose correction (a segfault).
  EXPECT_THROW(mapper.AddScan(ir, nullptr, {0.0, 0.0, std::nan("")}), std::invalid_argument);
  EXPECT_FALSE(mapper.map().segments().empty());
  for (const MapSegment& s : mapper.map().segments()) {
    EXPECT_TRUE(s.line.start.allFinite() && s.line.end.allFinite());
  }
}

}  // namespace
}  // namespace plywood::perception
