#include "sim/world/ground_truth_walls.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "sim/world/mujoco_handles.h"
#include "sim/world/scene.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim {
namespace {

using Eigen::Vector2d;

constexpr double kTol = 1e-9;

MjModelPtr Load(const std::string& xml) {
  return LoadModelFromString(xml, (testing::MakeTempDir("ground_truth_walls") / "m.xml").string());
}

int GeomId(const mjModel* m, const std::string& name) {
  const int id = mj_name2id(m, mjOBJ_GEOM, name.c_str());
  EXPECT_GE(id, 0) << name;
  return id;
}

std::vector<WallSegment> FacesOf(const GroundTruthWalls& walls, int geom_id) {
  std::vector<WallSegment> faces;
  for (const WallSegment& s : walls.segments) {
    if (s.geom_id == geom_id) faces.push_back(s);
  }
  return faces;
}

void ExpectNear(const Vector2d& actual, const Vector2d& expected, const std::string& what) {
  EXPECT_NEAR(actual.x(), expected.x(), kTol) << what;
  EXPECT_NEAR(actual.y(), expected.y(), kTol) << what;
}

// Faces must be 0..3, in order, and counter-clockwise from the box's centre: (mid - c) x (b - a)
// > 0 and the outward normal points away from the centre.
void ExpectOutwardFaces(const std::vector<WallSegment>& faces, const Vector2d& centre) {
  ASSERT_EQ(faces.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    const WallSegment& s = faces[k];
    EXPECT_EQ(s.face_index, k);
    const Vector2d mid = (s.a + s.b) / 2.0;
    EXPECT_GT((mid - centre).dot(s.OutwardNormal()), 0.0) << "face " << k;
    const Vector2d d = s.b - s.a, r = mid - centre;
    EXPECT_GT(r.x() * d.y() - r.y() * d.x(), 0.0) << "face " << k << " not counter-clockwise";
  }
}

constexpr char kInlineWorld[] = R"(
<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <geom name="axis_box" type="box" pos="1 2 0.5" size="0.5 0.25 0.5"/>
    <geom name="rotated_box" type="box" pos="-1 0.5 0.3" size="0.4 0.1 0.3" euler="0 0 30"/>
    <geom name="flipped_box" type="box" pos="3 -1 0.5" size="0.2 0.1 0.5" euler="180 0 0"/>
    <geom name="tilted_box" type="box" pos="-3 -3 0.5" size="0.2 0.2 0.2" euler="0 30 0"/>
    <geom name="column" type="cylinder" pos="2 2 0.5" size="0.15 0.5"/>
    <geom name="lying_cylinder" type="cylinder" pos="-2 2 0.1" size="0.1 0.5" euler="90 0 0"/>
    <geom name="ball" type="sphere" pos="0 -3 0.2" size="0.2"/>
    <geom name="egg" type="ellipsoid" pos="-4 0 0.2" size="0.1 0.15 0.2"/>
    <geom name="post" type="capsule" pos="4 -2 0.5" size="0.1 0.3"/>
    <geom name="lying_capsule" type="capsule" pos="-4 -2 0.1" size="0.1 0.3" euler="90 0 0"/>
    <geom name="table_top" type="box" pos="0 -2 0.735" size="0.6 0.3 0.015"/>
    <geom name="static_robot_group" type="box" pos="4 4 0.5" size="0.1 0.1 0.5" group="3"/>
    <body name="shelf" pos="2 0 0" euler="0 0 90">
      <geom name="shelf_box" type="box" pos="1 0 0.5" size="0.3 0.1 0.5"/>
    </body>
    <body name="robot" pos="0 0 0.2">
      <freejoint/>
      <geom name="robot_chassis" type="box" size="0.2 0.2 0.1" group="3"/>
      <geom name="robot_ungrouped" type="box" pos="0 0 0.15" size="0.05 0.05 0.05"/>
    </body>
  </worldbody>
</mujoco>)";

TEST(GroundTruthWallsTest, AxisAlignedBoxFacesAreTheHandComputedCorners) {
  const MjModelPtr m = Load(kInlineWorld);
  const GroundTruthWalls walls = ExtractGroundTruthWalls(m.get());
  const auto faces = FacesOf(walls, GeomId(m.get(), "axis_box"));
  ASSERT_EQ(faces.size(), 4u);
  // Corners (1 +- 0.5, 2 +- 0.25), counter-clockwise from the +x face.
  ExpectNear(faces[0].a, {1.5, 1.75}, "+x a");
  ExpectNear(faces[0].b, {1.5, 2.25}, "+x b");
  ExpectNear(faces[1].a, {1.5, 2.25}, "+y a");
  ExpectNear(faces[1].b, {0.5, 2.25}, "+y b");
  ExpectNear(faces[2].a, {0.5, 2.25}, "-x a");
  ExpectNear(faces[2].b, {0.5, 1.75}, "-x b");
  ExpectNear(faces[3].a, {0.5, 1.75}, "-y a");
  ExpectNear(faces[3].b, {1.5, 1.75}, "-y b");
  ExpectNear(faces[0].OutwardNormal(), {1, 0}, "+x normal");
  ExpectNear(faces[1].OutwardNormal(), {0, 1}, "+y normal");
  ExpectNear(faces[2].OutwardNormal(), {-1, 0}, "-x normal");
  ExpectNear(faces[3].OutwardNormal(), {0, -1}, "-y normal");
  EXPECT_NEAR(faces[0].LengthM(), 0.5, kTol);
  EXPECT_NEAR(faces[1].LengthM(), 1.0, kTol);
}

TEST(GroundTruthWallsTest, RotatedBoxFacesAreTheHandComputedCorners) {
  const MjModelPtr m = Load(kInlineWorld);
  const auto faces = FacesOf(ExtractGroundTruthWalls(m.get()), GeomId(m.get(), "rotated_box"));
  ASSERT_EQ(faces.size(), 4u);
  const double c = std::sqrt(3.0) / 2.0, s = 0.5;  // 30 deg
  const Vector2d centre(-1.0, 0.5);
  const auto corner = [&](double x, double y) {
    return Vector2d(centre.x() + c * x - s * y, centre.y() + s * x + c * y);
  };
  ExpectNear(faces[0].a, corner(0.4, -0.1), "+x a");
  ExpectNear(faces[0].b, corner(0.4, 0.1), "+x b");
  ExpectNear(faces[1].b, corner(-0.4, 0.1), "+y b");
  ExpectNear(faces[2].b, corner(-0.4, -0.1), "-x b");
  ExpectNear(faces[3].b, corner(0.4, -0.1), "-y b");
  ExpectNear(faces[0].OutwardNormal(), {c, s}, "+x normal");
  ExpectOutwardFaces(faces, centre);
}

TEST(GroundTruthWallsTest, StaticChildBodyPosesAreComposed) {
  const MjModelPtr m = Load(kInlineWorld);
  const auto faces = FacesOf(ExtractGroundTruthWalls(m.get()), GeomId(m.get(), "shelf_box"));
  ASSERT_EQ(faces.size(), 4u);
  // Body at (2, 0) turned 90 deg; the geom's local (1, 0) lands at (2, 1), its x axis along +y.
  ExpectNear(faces[0].a, {2.0 + 0.1, 1.0 + 0.3}, "+x a");  // local (0.3, -0.1)
  ExpectNear(faces[0].b, {2.0 - 0.1, 1.0 + 0.3}, "+x b");  // local (0.3, 0.1)
  ExpectOutwardFaces(faces, {2.0, 1.0});
}

TEST(GroundTruthWallsTest, UpsideDownBoxKeepsNormalsOutward) {
  const MjModelPtr m = Load(kInlineWorld);
  const auto faces = FacesOf(ExtractGroundTruthWalls(m.get()), GeomId(m.get(), "flipped_box"));
  ExpectOutwardFaces(faces, {3.0, -1.0});
  // Local +x is still world +x after a roll of 180 deg.
  ExpectNear(faces[0].OutwardNormal(), {1, 0}, "+x normal");
}

// A box is an upright prism whichever of its axes stands upright (audit s45): a wall turned 90 deg
// about x or y (or by a quaternion), with its sizes to match, and a square beam written with
// `fromto` along the floor (MuJoCo 2.2.2 gives a fromto box size[0] on both its other axes), are
// the upright box's footprint: the same four faces, outward, and the same cross-section and
// heights. Each was left out as "a box tilted 90 deg" (refused where a run is scored: a wall the
// truth can hold). A box tilted 30 deg stays unrepresented (kInlineWorld).
TEST(GroundTruthWallsTest, ABoxLyingOnItsSideIsTheUprightPrismItIs) {
  const auto world = [](const std::string& geom) {
    return "<mujoco><worldbody><geom type=\"plane\" size=\"5 5 0.1\"/>" + geom +
           "</worldbody></mujoco>";
  };
  GroundTruthOptions at_laser;
  at_laser.height_m = 0.34;
  const std::string wall = "<geom type=\"box\" pos=\"0.3 -1.109 0.5\" size=\"1.618 0.009 0.5\"/>";
  const std::string beam = "<geom type=\"box\" pos=\"0.3 -1.109 0.34\" size=\"1.618 0.05 0.05\"/>";
  for (
      const auto& [upright, lying] : std::vector<std::pair<std::string, std::string>>{
          {wall,
           "<geom type=\"box\" pos=\"0.3 -1.109 0.5\" size=\"1.618 0.5 0.009\" euler=\"90 0 0\"/>"},
          {wall,
           "<geom type=\"box\" pos=\"0.3 -1.109 0.5\" size=\"0.5 0.009 1.618\" euler=\"0 -90 "
           "0\"/>"},
          {wall,
           "<geom type=\"box\" pos=\"0.3 -1.109 0.5\" size=\"1.618 0.5 0.009\" "
           "quat=\"0 0 0.7071068 0.7071068\"/>"},
          {beam,
           "<geom type=\"box\" fromto=\"-1.318 -1.109 0.34 1.918 -1.109 0.34\" size=\"0.05\"/>"},
          {beam,
           "<geom type=\"box\" fromto=\"1.918 -1.109 0.34 -1.318 -1.109 0.34\" size=\"0.05\"/>"}}) {
    SCOPED_TRACE(lying);
    const MjModelPtr reference = Load(world(upright));
    const GroundTruthWalls expected = ExtractGroundTruthWalls(reference.get(), at_laser);
    ASSERT_EQ(expected.segments.size(), 4u);
    const MjModelPtr m = Load(world(lying));
    const GroundTruthWalls walls = ExtractGroundTruthWalls(m.get(), at_laser);
    EXPECT_TRUE(walls.unrepresented_geom_ids.empty());
    ASSERT_EQ(walls.segments.size(), 4u);
    ExpectOutwardFaces(walls.segments, {0.3, -1.109});
    // The same faces, whichever box axis each comes from.
    for (const WallSegment& face : expected.segments) {
      const bool found =
          std::any_of(walls.segments.begin(), walls.segments.end(), [&](const WallSegment& other) {
            return (other.a - face.a).norm() < 1e-6 && (other.b - face.b).norm() < 1e-6;
          });
      EXPECT_TRUE(found) << face.a.transpose() << " -> " << face.b.transpose();
    }
    const std::vector<UprightGeom> geoms = ExtractUprightGeoms(m.get(), at_laser);
    const std::vector<UprightGeom> upright_geoms = ExtractUprightGeoms(reference.get(), at_laser);
    ASSERT_EQ(geoms.size(), 1u);
    ASSERT_EQ(upright_geoms.size(), 1u);
    EXPECT_NEAR(geoms[0].z_min_m, upright_geoms[0].z_min_m, 1e-9);
    EXPECT_NEAR(geoms[0].z_max_m, upright_geoms[0].z_max_m, 1e-9);
    for (const Vector2d& p : {Vector2d(1.9, -1.101), Vector2d(1.9, -1.099), Vector2d(1.92, -1.11),
                              Vector2d(0.3, -1.06), Vector2d(0.3, -1.16)}) {
      EXPECT_EQ(geoms[0].ContainsXY(p), upright_geoms[0].ContainsXY(p)) << p.transpose();
    }
  }
}

TEST(GroundTruthWallsTest, CylindersBecomeCirclesAndOtherShapesAreReported) {
  const MjModelPtr m = Load(kInlineWorld);
  const GroundTruthWalls walls = ExtractGroundTruthWalls(m.get());
  // The column, the ball and the upright capsule, in geom order; seen from above (no slice) a
  // round shape is its outline.
  ASSERT_EQ(walls.circles.size(), 3u);
  EXPECT_EQ(walls.circles[0].geom_id, GeomId(m.get(), "column"));
  ExpectNear(walls.circles[0].centre, {2, 2}, "column centre");
  EXPECT_DOUBLE_EQ(walls.circles[0].radius_m, 0.15);
  EXPECT_EQ(walls.circles[1].geom_id, GeomId(m.get(), "ball"));
  EXPECT_DOUBLE_EQ(walls.circles[1].radius_m, 0.2);
  EXPECT_EQ(walls.circles[2].geom_id, GeomId(m.get(), "post"));
  ExpectNear(walls.circles[2].centre, {4, -2}, "post centre");
  EXPECT_DOUBLE_EQ(walls.circles[2].radius_m, 0.1);
  std::vector<int> expected = {GeomId(m.get(), "tilted_box"), GeomId(m.get(), "lying_cylinder"),
                               GeomId(m.get(), "egg"), GeomId(m.get(), "lying_capsule")};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(walls.unrepresented_geom_ids, expected);
}

// A slice through a sphere of radius r, dz from its centre, is a disc of radius sqrt(r^2 - dz^2);
// a capsule is a cylinder between two such half-spheres.
TEST(GroundTruthWallsTest, SlicesThroughRoundEndsAreTheirDiscs) {
  const MjModelPtr m = Load(kInlineWorld);
  const auto radius_at = [&](const std::string& name, double height_m) -> std::optional<double> {
    GroundTruthOptions slice;
    slice.height_m = height_m;
    for (const WallCircle& c : ExtractGroundTruthWalls(m.get(), slice).circles) {
      if (c.geom_id == GeomId(m.get(), name)) return c.radius_m;
    }
    return std::nullopt;
  };
  // The ball: centre z 0.2, r 0.2.
  EXPECT_NEAR(*radius_at("ball", 0.2), 0.2, kTol);
  EXPECT_NEAR(*radius_at("ball", 0.34), std::sqrt(0.2 * 0.2 - 0.14 * 0.14), kTol);
  EXPECT_NEAR(*radius_at("ball", 0.05), std::sqrt(0.2 * 0.2 - 0.15 * 0.15), kTol);
  EXPECT_FALSE(radius_at("ball", 0.41).has_value());
  EXPECT_FALSE(radius_at("ball", 0.4).has_value());  // the pole only
  // The post: centre z 0.5, straight part 0.2-0.8, ends to 0.1 and 0.9, r 0.1.
  EXPECT_NEAR(*radius_at("post", 0.34), 0.1, kTol);
  EXPECT_NEAR(*radius_at("post", 0.8), 0.1, kTol);
  EXPECT_NEAR(*radius_at("post", 0.86), std::sqrt(0.1 * 0.1 - 0.06 * 0.06), kTol);
  EXPECT_NEAR(*radius_at("post", 0.15), std::sqrt(0.1 * 0.1 - 0.05 * 0.05), kTol);
  EXPECT_FALSE(radius_at("post", 0.95).has_value());
  // The occupancy prism agrees: a point 0.09 m from the post's axis is inside at 0.34 m, outside
  // where the end's disc is 0.08 m.
  GroundTruthOptions low, end;
  low.height_m = 0.34;
  end.height_m = 0.86;
  for (const auto& [options, inside] : {std::pair{low, true}, std::pair{end, false}}) {
    bool found = false;
    for (const UprightGeom& u : ExtractUprightGeoms(m.get(), options)) {
      if (u.geom_id != GeomId(m.get(), "post")) continue;
      found = true;
      EXPECT_EQ(u.ContainsXY({4.09, -2}), inside);
      EXPECT_NEAR(u.z_min_m, 0.1, kTol);
      EXPECT_NEAR(u.z_max_m, 0.9, kTol);
    }
    EXPECT_TRUE(found);
  }
}

TEST(GroundTruthWallsTest, RobotFloorAndMovingGeomsAreExcluded) {
  const MjModelPtr m = Load(kInlineWorld);
  const GroundTruthWalls walls = ExtractGroundTruthWalls(m.get());
  // axis, rotated, flipped, table top, shelf: five boxes.
  EXPECT_EQ(walls.segments.size(), 5u * 4u);
  for (const std::string name :
       {"floor", "static_robot_group", "robot_chassis", "robot_ungrouped"}) {
    const int id = GeomId(m.get(), name);
    EXPECT_TRUE(FacesOf(walls, id).empty()) << name;
    EXPECT_EQ(
        std::count(walls.unrepresented_geom_ids.begin(), walls.unrepresented_geom_ids.end(), id), 0)
        << name;
  }
  EXPECT_FALSE(IsStaticGeom(m.get(), GeomId(m.get(), "robot_ungrouped")));
  EXPECT_TRUE(IsStaticGeom(m.get(), GeomId(m.get(), "shelf_box")));
  // With no group excluded the static robot-group box is world geometry again.
  GroundTruthOptions all_groups;
  all_groups.excluded_geom_group = -1;
  EXPECT_EQ(
      FacesOf(ExtractGroundTruthWalls(m.get(), all_groups), GeomId(m.get(), "static_robot_group"))
          .size(),
      4u);
}

TEST(GroundTruthWallsTest, HeightFilterDropsGeomsThatDoNotSpanTheHeight) {
  const MjModelPtr m = Load(kInlineWorld);
  const int top = GeomId(m.get(), "table_top");
  const int rotated = GeomId(m.get(), "rotated_box");  // z in [0, 0.6]
  GroundTruthOptions laser;
  laser.height_m = 0.34;
  const GroundTruthWalls low = ExtractGroundTruthWalls(m.get(), laser);
  EXPECT_TRUE(FacesOf(low, top).empty());
  EXPECT_EQ(FacesOf(low, rotated).size(), 4u);
  GroundTruthOptions table_height;
  table_height.height_m = 0.74;
  const GroundTruthWalls high = ExtractGroundTruthWalls(m.get(), table_height);
  EXPECT_EQ(FacesOf(high, top).size(), 4u);
  EXPECT_TRUE(FacesOf(high, rotated).empty());
  GroundTruthOptions above;
  above.height_m = 1.5;
  const GroundTruthWalls none = ExtractGroundTruthWalls(m.get(), above);
  EXPECT_TRUE(none.segments.empty());
  EXPECT_TRUE(none.circles.empty());
}

// Shapes the truth cannot hold are reported only where they reach the slice, by their exact
// vertical extent: a 0.6 m capsule and a flat ellipsoid lying on the floor (tops at 0.1 m) were
// reported at the laser's 0.34 m by their bounding radii (0.35 and 0.5 m), which refused a scored
// run in a world the laser could not see them in.
TEST(GroundTruthWallsTest, ShapesLyingBelowTheSliceAreNotReportedAtIt) {
  const MjModelPtr m = Load(
      "<mujoco><worldbody>"
      "<geom name=\"log\" type=\"capsule\" fromto=\"1 0.2 0.05 1 0.8 0.05\" size=\"0.05\"/>"
      "<geom name=\"mat\" type=\"ellipsoid\" pos=\"2 0 0.05\" size=\"0.5 0.1 0.05\"/>"
      "<geom name=\"beam\" type=\"cylinder\" fromto=\"3 0 0.1 3.6 0 0.1\" size=\"0.1\"/>"
      "<geom name=\"plank\" type=\"box\" pos=\"4 0 0.1\" size=\"0.5 0.1 0.02\" "
      "euler=\"10 0 0\"/>"
      "</worldbody></mujoco>");
  GroundTruthOptions laser;
  laser.height_m = 0.34;
  EXPECT_TRUE(ExtractGroundTruthWalls(m.get(), laser).unrepresented_geom_ids.empty());
  GroundTruthOptions low;
  low.height_m = 0.09;
  EXPECT_EQ(ExtractGroundTruthWalls(m.get(), low).unrepresented_geom_ids.size(), 4u);
  // The extents by hand: the plank (0.5 x 0.1 x 0.02) turned 10 deg about x rises
  // 0.1 sin 10 + 0.02 cos 10 either side of its centre.
  const Eigen::Matrix3d level = Eigen::Matrix3d::Identity();
  EXPECT_NEAR(GeomVerticalHalfExtent(m.get(), GeomId(m.get(), "mat"), level), 0.05, kTol);
  Eigen::Matrix3d about_x;
  const double a = 10.0 * std::numbers::pi / 180.0;
  about_x << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  EXPECT_NEAR(GeomVerticalHalfExtent(m.get(), GeomId(m.get(), "plank"), about_x),
              0.1 * std::sin(a) + 0.02 * std::cos(a), kTol);
  Eigen::Matrix3d lying;  // the axis along x
  lying << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  EXPECT_NEAR(GeomVerticalHalfExtent(m.get(), GeomId(m.get(), "beam"), lying), 0.1, kTol);
  EXPECT_NEAR(GeomVerticalHalfExtent(m.get(), GeomId(m.get(), "log"), lying), 0.05, kTol);
}

TEST(GroundTruthWallsTest, InvalidOptionsNameTheField) {
  const MjModelPtr m = Load(kInlineWorld);
  GroundTruthOptions bad;
  bad.max_tilt_rad = -1.0;
  try {
    ExtractGroundTruthWalls(m.get(), bad);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("max_tilt_rad:", 0), 0u) << e.what();
  }
  bad = {};
  bad.excluded_geom_group = 9;
  EXPECT_THROW(bad.Validate(), std::invalid_argument);
  bad = {};
  bad.height_m = std::nan("");
  EXPECT_THROW(bad.Validate(), std::invalid_argument);
}

struct WorldCounts {
  int segments_at_laser;  // z = 0.34 m
  int circles_at_laser;
  int segments_at_table;  // z = 0.74 m
  int circles_at_table;
};

// Hand-counted from the MJCF files: four faces per box that spans the height.
const std::map<std::string, WorldCounts>& ExpectedCounts() {
  static const std::map<std::string, WorldCounts> counts = {
      {"seed001_room_1", {4 * 4, 0, 4 * 4, 0}},
      {"seed001_room_2", {5 * 4, 0, 4 * 4, 0}},  // the 0.6 m obstacle ends below 0.74
      {"seed001_room_3", {6 * 4, 0, 4 * 4, 0}},
      {"seed001_room_4", {5 * 4, 0, 4 * 4, 0}},
      {"seed000_room_1", {4 * 4, 0, 4 * 4, 0}},
      {"seed000_room_2", {6 * 4, 0, 6 * 4, 0}},
      {"seed000_room_3", {7 * 4, 0, 7 * 4, 0}},  // six walls and the pillar
      {"seed000_room_4", {7 * 4, 0, 7 * 4, 0}},
      {"hall", {4 * 4, 0, 4 * 4, 0}},
      {"rotated_room", {5 * 4, 1, 4 * 4, 1}},
      // 19 walls + 6 wardrobes + 1 cabinet; at the laser 2 columns + 8 tables x 4 legs, at 0.74 m
      // the 8 table tops instead of their legs.
      {"office", {26 * 4, 2 + 32, 34 * 4, 2}},
  };
  return counts;
}

TEST(GroundTruthWallsTest, WorldFilesHaveTheHandCountedFacesAtEachHeight) {
  const std::filesystem::path worlds = testing::SourceRoot() / "worlds";
  for (const auto& [name, expected] : ExpectedCounts()) {
    SCOPED_TRACE(name);
    const MjModelPtr m = LoadModelFromFile((worlds / (name + ".xml")).string());
    GroundTruthOptions laser;
    laser.height_m = 0.34;
    const GroundTruthWalls low = ExtractGroundTruthWalls(m.get(), laser);
    EXPECT_EQ(static_cast<int>(low.segments.size()), expected.segments_at_laser);
    EXPECT_EQ(static_cast<int>(low.circles.size()), expected.circles_at_laser);
    EXPECT_TRUE(low.unrepresented_geom_ids.empty());
    GroundTruthOptions table;
    table.height_m = 0.74;
    const GroundTruthWalls high = ExtractGroundTruthWalls(m.get(), table);
    EXPECT_EQ(static_cast<int>(high.segments.size()), expected.segments_at_table);
    EXPECT_EQ(static_cast<int>(high.circles.size()), expected.circles_at_table);
    // Nothing but the office's 2 m wardrobes reaches above the 1 m walls.
    GroundTruthOptions above_walls;
    above_walls.height_m = 1.5;
    EXPECT_EQ(ExtractGroundTruthWalls(m.get(), above_walls).segments.size(),
              name == "office" ? 6u * 4u : 0u);
  }
}

TEST(GroundTruthWallsTest, Seed001RoomInnerFacesLieOnTheRoomRectangle) {
  const MjModelPtr m =
      LoadModelFromFile((testing::SourceRoot() / "worlds" / "seed001_room_1.xml").string());
  const GroundTruthWalls walls = ExtractGroundTruthWalls(m.get());
  // East wall: its -x face is the room's inner face x = 1.75, running from north to south.
  const auto east = FacesOf(walls, GeomId(m.get(), "wall_1"));
  ASSERT_EQ(east.size(), 4u);
  ExpectNear(east[2].a, {1.75, 1.5}, "east inner a");
  ExpectNear(east[2].b, {1.75, -1.5}, "east inner b");
  // South wall's +y face spans the full inner width and the wall thickness on both ends.
  const auto south = FacesOf(walls, GeomId(m.get(), "wall_0"));
  ASSERT_EQ(south.size(), 4u);
  ExpectNear(south[1].a, {1.768, -1.5}, "south inner a");
  ExpectNear(south[1].b, {-1.768, -1.5}, "south inner b");
}

TEST(GroundTruthWallsTest, RotatedRoomInnerFacesAreTheRotatedRectangle) {
  const MjModelPtr m =
      LoadModelFromFile((testing::SourceRoot() / "worlds" / "rotated_room.xml").string());
  const GroundTruthWalls walls = ExtractGroundTruthWalls(m.get());
  // Each wall's face that looks at the origin lies on a side of the 4 x 3 m rectangle rotated by
  // 20 deg: normal-form distance 2.0 or 1.5, normal angle 20 deg + k * 90 deg. Positions in the
  // file carry 6 decimals.
  int inner_faces = 0;
  for (int w = 0; w < 4; ++w) {
    for (const WallSegment& s : FacesOf(walls, GeomId(m.get(), "wall_" + std::to_string(w)))) {
      // The inner face's outward normal points back at the origin.
      const Vector2d towards_wall = -s.OutwardNormal();
      const double distance = towards_wall.dot(s.a);
      if (s.LengthM() < 1.0 || distance < 0.0) continue;
      ++inner_faces;
      EXPECT_TRUE(std::abs(distance - 2.0) < 1e-5 || std::abs(distance - 1.5) < 1e-5) << distance;
      const double angle_deg =
          std::atan2(towards_wall.y(), towards_wall.x()) * 180.0 / std::numbers::pi;
      const double off_grid = std::remainder(angle_deg - 20.0, 90.0);
      EXPECT_NEAR(off_grid, 0.0, 1e-9) << angle_deg;
    }
  }
  EXPECT_EQ(inner_faces, 4);
}

TEST(GroundTruthWallsTest, WorldWithRobotGivesTheWorldsSegments) {
  const std::filesystem::path root = testing::SourceRoot();
  const MjModelPtr world = LoadModelFromFile((root / "worlds" / "seed001_room_4.xml").string());
  SceneOptions options;
  options.world_mjcf = root / "worlds" / "seed001_room_4.xml";
  options.robot_mjcf = root / "models" / "p3dx.xml";
  options.spawn = {-1.0, 0.0, 0.0};
  const Scene scene(options);
  GroundTruthOptions laser;
  laser.height_m = 0.34;
  const GroundTruthWalls alone = ExtractGroundTruthWalls(world.get(), laser);
  const GroundTruthWalls composed = ExtractGroundTruthWalls(scene.model(), laser);
  ASSERT_EQ(composed.segments.size(), alone.segments.size());
  EXPECT_TRUE(composed.unrepresented_geom_ids.empty());
  for (size_t i = 0; i < alone.segments.size(); ++i) {
    ExpectNear(composed.segments[i].a, alone.segments[i].a, "a");
    ExpectNear(composed.segments[i].b, alone.segments[i].b, "b");
    EXPECT_FALSE(scene.IsRobotGeom(composed.segments[i].geom_id));
  }
}

}  // namespace
}  // namespace plywood::sim
