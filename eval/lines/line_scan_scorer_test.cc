// Line scoring on simulated scans: the `lines:` section, the back-to-back rig, and issue 4's
// acceptance on worlds that are not in the repo (written here, several with walls that are not
// axis-aligned), with realistic LMS 200 noise (experiments/seed000_rooms.yaml's laser).

#include "eval/lines/line_scan_scorer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "eval/lines/seed000_rooms.h"
#include "sim/config/config_error.h"
#include "sim/config/experiment_config.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::eval {
namespace {

using Vertices = std::vector<Eigen::Vector2d>;

// A wall box per edge of each counter-clockwise polygon, its inner face exactly on the edge;
// `gaps` removes edges (doorways).
std::string PolygonWorld(const std::vector<Vertices>& rooms, const std::string& extra = "") {
  std::ostringstream xml;
  xml << "<mujoco model=\"test_room\"><worldbody>\n"
      << "<geom name=\"floor\" type=\"plane\" size=\"10 10 0.05\"/>\n";
  int k = 0;
  for (const Vertices& v : rooms) {
    for (std::size_t i = 0; i + 1 < v.size() + (v.size() > 2 ? 1 : 0); ++i) {
      const Eigen::Vector2d a = v[i], b = v[(i + 1) % v.size()];
      const Eigen::Vector2d d = (b - a).normalized();
      const Eigen::Vector2d outward(d.y(), -d.x());  // right of a -> b: outside a CCW polygon
      const Eigen::Vector2d c = 0.5 * (a + b) + 0.009 * outward;
      const double yaw_deg = std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
      xml << "<geom name=\"wall_" << k++ << "\" type=\"box\" pos=\"" << c.x() << " " << c.y()
          << " 0.5\" size=\"" << 0.5 * (b - a).norm() + 0.009 << " 0.009 0.5\" euler=\"0 0 "
          << yaw_deg << "\"/>\n";
    }
  }
  xml << extra << "</worldbody></mujoco>\n";
  return xml.str();
}

Vertices Rotated(Vertices v, double deg) {
  const double c = std::cos(deg * std::numbers::pi / 180),
               s = std::sin(deg * std::numbers::pi / 180);
  for (auto& p : v) p = Eigen::Vector2d(c * p.x() - s * p.y(), s * p.x() + c * p.y());
  return v;
}

sim::ExperimentConfig RigConfig(const std::filesystem::path& world) {
  return sim::LoadExperimentConfig(testing::SourceRoot() / "experiments/seed000_rooms.yaml",
                                   {"world=" + world.string()});
}

Seed000RoomResult RunWorld(const std::string& name, const std::string& xml, int scans) {
  const auto dir = testing::MakeTempDir("line_scan_scorer_test");
  const auto world = testing::WriteFile(dir / (name + ".xml"), xml);
  const sim::ExperimentConfig config = RigConfig(world);
  const auto rooms = RoomsToRun(config, ReadSeed000RoomsOptions(config));
  EXPECT_EQ(rooms.size(), 1u);  // a user world runs alone
  return RunSeed000Room(config, rooms.front(), scans);
}

const ExtractorScore& Find(const Seed000RoomResult& r, const std::string& name) {
  for (const auto& s : r.scores)
    if (s.name == name) return s;
  throw std::invalid_argument(name);
}

TEST(LineScanScorerTest, NoiseFreeSquareGivesItsFourWallsExactly) {
  const auto dir = testing::MakeTempDir("line_scan_scorer_test");
  const auto world = testing::WriteFile(
      dir / "square.xml", PolygonWorld({{{-1.5, -1.2}, {2.0, -1.2}, {2.0, 1.6}, {-1.5, 1.6}}}));
  sim::ExperimentConfig config = RigConfig(world);
  config.sensors.laser->noise_free = true;
  const auto rooms = RoomsToRun(config, ReadSeed000RoomsOptions(config));
  const Seed000RoomResult r = RunSeed000Room(config, rooms.front(), 1);
  ASSERT_EQ(r.scans.size(), 1u);
  EXPECT_EQ(r.PointsPerScan(), 722.0);
  EXPECT_TRUE(r.scans[0].points.closed);
  EXPECT_EQ(r.WallsVisible(), 4.0);  // the four inner faces; the 18 mm ends are not seen
  const ExtractorScore& sm = Find(r, "split_and_merge");
  EXPECT_EQ(sm.score.extracted, 4);
  EXPECT_EQ(sm.score.Recall(), 1.0);
  EXPECT_EQ(sm.score.Precision(), 1.0);
  // Not zero: the idle robot settles on its wheels by a fraction of a millimetre between the two
  // runs, and the pair is combined about the front sensor's origin.
  EXPECT_LT(sm.score.SigmaRM(), 1e-4);
  EXPECT_LT(sm.score.SigmaAlphaDeg(), 0.01);
  EXPECT_NEAR(sm.score.PointsPerLine(), 722.0 / 4.0, 1e-9);
}

// Issue 4 acceptance: split_and_merge recall and precision >= 0.95 with realistic noise on worlds
// not in the repo: an irregular pentagon, a rotated rectangle with a rotated box in it, and a
// hexagon with a doorway and a wall behind it.
TEST(LineScanScorerTest, SplitAndMergeMeetsAcceptanceOnUnseenWorlds) {
  const std::vector<std::pair<std::string, std::string>> worlds{
      {"pentagon",
       PolygonWorld({{{-1.6, -1.0}, {1.4, -1.6}, {2.3, 0.7}, {0.2, 2.1}, {-2.0, 1.0}}})},
      {"rotated_rectangle",
       PolygonWorld({Rotated({{-1.7, -1.3}, {2.1, -1.3}, {2.1, 1.5}, {-1.7, 1.5}}, 37.0)},
                    "<geom name=\"box\" type=\"box\" pos=\"-0.9 0.9 0.4\" size=\"0.3 0.2 0.4\" "
                    "euler=\"0 0 -25\"/>\n")},
      {"hexagon_doorway",
       // Six walls of a hexagon of radius 2.4 m, the east one cut by a 0.9 m doorway, and a panel
       // outside it that the lasers see through the door.
       [] {
         Vertices hex;
         for (int i = 0; i < 6; ++i) {
           const double a = (i * 60.0 + 10.0) * std::numbers::pi / 180.0;
           hex.emplace_back(2.4 * std::cos(a), 2.4 * std::sin(a));
         }
         std::vector<Vertices> walls;
         for (int i = 0; i < 6; ++i) {
           const Eigen::Vector2d a = hex[i], b = hex[(i + 1) % 6];
           if (i != 5) {
             walls.push_back({a, b});
             continue;
           }
           const Eigen::Vector2d m = 0.5 * (a + b), d = (b - a).normalized();
           walls.push_back({a, m - 0.45 * d});
           walls.push_back({m + 0.45 * d, b});
         }
         walls.push_back({{3.6, 1.0}, {3.6, -1.2}});
         return PolygonWorld(walls);
       }()},
      {"rotated_room_with_columns",
       // Round columns are cut into chords that match no wall unless the extractor sees they are
       // round (perception/lines/round_object_filter.h); a rotated box's corner must survive.
       PolygonWorld({Rotated({{-2.4, -1.8}, {2.6, -1.8}, {2.6, 2.0}, {-2.4, 2.0}}, -14.0)},
                    "<geom name=\"column_0\" type=\"cylinder\" pos=\"1.1 -0.5 0.5\" "
                    "size=\"0.15 0.5\"/>\n"
                    "<geom name=\"column_1\" type=\"cylinder\" pos=\"-0.8 1.2 0.5\" "
                    "size=\"0.2 0.5\"/>\n"
                    "<geom name=\"box\" type=\"box\" pos=\"-1.0 -0.9 0.4\" size=\"0.3 0.25 0.4\" "
                    "euler=\"0 0 33\"/>\n")},
  };
  for (const auto& [name, xml] : worlds) {
    const Seed000RoomResult r = RunWorld(name, xml, 5);
    for (const auto& s : r.scores) {
      std::printf(
          "%-18s %-16s recall %.3f precision %.3f sigma_r %.4f m sigma_alpha %.3f deg "
          "(%.1f walls visible)\n",
          name.c_str(), s.name.c_str(), s.score.Recall(), s.score.Precision(), s.score.SigmaRM(),
          s.score.SigmaAlphaDeg(), r.WallsVisible());
    }
    const ExtractorScore& sm = Find(r, "split_and_merge");
    EXPECT_GE(sm.score.Recall(), 0.95) << name;
    EXPECT_GE(sm.score.Precision(), 0.95) << name;
    EXPECT_GE(r.WallsVisible(), 4.0) << name;
  }
}

// seed000_room_1's world text, and the same with its south wall's box replaced by `geoms` (and
// `appended` before </worldbody>, so every other face keeps its walls.csv row).
struct Room1Texts {
  std::string one_box;
  std::string rewritten;
};
Room1Texts Room1WithSouthWallAs(const std::string& geoms, const std::string& appended = "") {
  std::ifstream in(testing::SourceRoot() / "worlds/seed000_room_1.xml");
  std::stringstream text;
  text << in.rdbuf();
  Room1Texts texts{text.str(), text.str()};
  const std::string wall_0 =
      "<geom name=\"wall_0\" class=\"wall\" pos=\"0.3 -1.109 0.5\" size=\"1.618 0.009 0.5\"/>";
  const std::size_t at = texts.rewritten.find(wall_0);
  EXPECT_NE(at, std::string::npos);
  if (at == std::string::npos) return texts;
  texts.rewritten.replace(at, wall_0.size(), geoms);
  texts.rewritten.replace(texts.rewritten.find("</worldbody>"), 0, appended);
  return texts;
}

// seed000_room_1 with its south wall written as two 1.618 m boxes meeting at x = 0.3 (the second
// half last, so every other face keeps its walls.csv row) is the same room to every scorer: from
// the very same scans, 4 walls visible and every extractor's recall 1, and each line matches the
// same walls.csv row (the south wall's first half's inner face names the joined surface). Scored
// face by face it was 5 walls and recall 0.8: a line along the wall matched one half.
TEST(LineScanScorerTest, AWallWrittenAsTwoBoxesEndToEndScoresAsOneWall) {
  const auto [one_box, two_boxes] = Room1WithSouthWallAs(
      "<geom name=\"wall_0a\" class=\"wall\" pos=\"-0.509 -1.109 0.5\" size=\"0.809 0.009 0.5\"/>",
      "<geom name=\"wall_0b\" class=\"wall\" pos=\"1.109 -1.109 0.5\" size=\"0.809 0.009 "
      "0.5\"/>\n");
  const Seed000RoomResult one = RunWorld("one_box", one_box, 2);
  const Seed000RoomResult two = RunWorld("two_boxes", two_boxes, 2);
  ASSERT_EQ(one.scans.size(), 2u);
  ASSERT_EQ(two.scans.size(), 2u);
  for (std::size_t s = 0; s < 2; ++s) {
    EXPECT_EQ(one.scans[s].points.points, two.scans[s].points.points) << "scan " << s;
  }
  EXPECT_EQ(two.rig.walls.segments.size(), 20u);
  EXPECT_EQ(one.WallsVisible(), 4.0);
  EXPECT_EQ(two.WallsVisible(), 4.0);
  ASSERT_EQ(two.scores.size(), one.scores.size());
  for (std::size_t e = 0; e < one.scores.size(); ++e) {
    const ExtractorScore& a = one.scores[e];
    const ExtractorScore& b = two.scores[e];
    EXPECT_EQ(a.score.Recall(), 1.0) << a.name;
    EXPECT_EQ(b.score.Recall(), 1.0) << b.name;
    EXPECT_EQ(b.score.extracted, a.score.extracted) << b.name;
    EXPECT_EQ(b.score.extracted_matched, a.score.extracted_matched) << b.name;
    ASSERT_EQ(b.scans.size(), a.scans.size());
    for (std::size_t s = 0; s < a.scans.size(); ++s) {
      EXPECT_EQ(b.scans[s].matched_truth, a.scans[s].matched_truth) << b.name << " scan " << s;
    }
  }
}

// The same wall of three panels written by hand to the millimetre (audit s45): a third of 3.236 m
// is 1.0787 m, written `size="0.539"` with centres rounded to the millimetre, so 1 mm seams part
// the panels. The scanner sees the one wall it sees in the one-box room (its rays through a seam,
// if any, are stray points): 4 walls visible, every extractor's recall 1 and its precision the
// one-box room's. Scored as three walls it was 6 visible, recall 0.5 and precision 0.75 for four
// of the five extractors: a line along the wall overlapped each panel by a third and matched none.
TEST(LineScanScorerTest, AWallOfPanelsWrittenToTheMillimetreScoresAsOneWall) {
  const auto [one_box, panels] = Room1WithSouthWallAs(
      "<geom name=\"wall_0a\" class=\"wall\" pos=\"-0.779 -1.109 0.5\" size=\"0.539 0.009 0.5\"/>"
      "<geom name=\"wall_0b\" class=\"wall\" pos=\"0.3 -1.109 0.5\" size=\"0.539 0.009 0.5\"/>"
      "<geom name=\"wall_0c\" class=\"wall\" pos=\"1.379 -1.109 0.5\" size=\"0.539 0.009 0.5\"/>");
  const Seed000RoomResult one = RunWorld("one_box", one_box, 2);
  const Seed000RoomResult three = RunWorld("panels", panels, 2);
  EXPECT_EQ(three.rig.walls.segments.size(), 24u);
  EXPECT_EQ(one.WallsVisible(), 4.0);
  EXPECT_EQ(three.WallsVisible(), 4.0);
  ASSERT_EQ(three.scores.size(), one.scores.size());
  for (std::size_t e = 0; e < one.scores.size(); ++e) {
    const ExtractorScore& a = one.scores[e];
    const ExtractorScore& b = three.scores[e];
    EXPECT_EQ(b.score.Recall(), 1.0) << b.name;
    EXPECT_EQ(b.score.Precision(), a.score.Precision()) << b.name;
  }
}

TEST(LineScanScorerTest, LinesSectionRoundTripsAndRejectsBadInput) {
  const std::string yaml =
      "world: worlds/seed000_room_1.xml\n"
      "sensors: {laser: {}}\n"
      "lines: {extractors: [ransac, split_and_merge], range_cut_m: 3.5,\n"
      "        split_and_merge: {split_threshold_m: 0.05, fit: modal, breakpoints: {max_m: 0.4}},\n"
      "        ransac: {seed: 9}}\n";
  const sim::ExperimentConfig config =
      sim::ParseExperimentConfig(yaml, "t.yaml", testing::SourceRoot());
  EXPECT_TRUE(config.lines.given);
  EXPECT_EQ(config.lines.extractors, (std::vector<std::string>{"ransac", "split_and_merge"}));
  EXPECT_EQ(config.lines.range_cut_m, 3.5);
  EXPECT_EQ(config.lines.options.split_and_merge.split_threshold_m, 0.05);
  EXPECT_EQ(config.lines.options.split_and_merge.breakpoints.max_m, 0.4);
  EXPECT_EQ(config.lines.options.ransac.seed, 9u);
  const sim::ExperimentConfig again = sim::ParseExperimentConfig(
      sim::ExperimentConfigToYaml(config), "again.yaml", testing::SourceRoot());
  EXPECT_EQ(sim::ExperimentConfigToYaml(again), sim::ExperimentConfigToYaml(config));
  EXPECT_EQ(again.lines.options.split_and_merge.fit, perception::LineFitMethod::kModal);

  const sim::ExperimentConfig plain = sim::ParseExperimentConfig(
      "world: worlds/seed000_room_1.xml\n", "p.yaml", testing::SourceRoot());
  EXPECT_FALSE(plain.lines.given);
  EXPECT_EQ(sim::ExperimentConfigToYaml(plain).find("lines:"), std::string::npos);

  const auto error = [&](const std::string& lines) {
    try {
      sim::ParseExperimentConfig("world: worlds/seed000_room_1.xml\nlines: " + lines + "\n",
                                 "b.yaml", testing::SourceRoot());
    } catch (const sim::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("{extractors: [split_and_merge, lsd]}").find("lines.extractors"),
            std::string::npos);
  EXPECT_NE(error("{extractors: [hough, hough]}").find("twice"), std::string::npos);
  EXPECT_NE(error("{split_and_merge: {split_threshold_m: -1}}").find("split_threshold_m"),
            std::string::npos);
  EXPECT_NE(error("{ransac: {iteration: 5}}").find("iteration"), std::string::npos);
  EXPECT_NE(error("{range_cut_m: 0}").find("range_cut_m"), std::string::npos);
}

// The post-run scorer sees every scan of a moving run and writes the documented keys.
TEST(LineScanScorerTest, PostRunScorerWritesMetricsForEveryExtractor) {
  const std::string yaml =
      "world: worlds/seed000_room_1.xml\n"
      "seed: 3\nduration_s: 2\n"
      "robot: {spawn: {x_m: 0, y_m: 0, theta_deg: 0}}\n"
      "controller: {type: wheel_script, segments: [[2, 2, 3]]}\n"
      "sensors: {laser: {rate_hz: 5}}\n"
      "lines: {extractors: [split_and_merge, incremental]}\n";
  sim::ExperimentRunner runner(sim::ParseExperimentConfig(yaml, "r.yaml", testing::SourceRoot()));
  runner.Run();
  const auto scores = AddLineMetrics(runner);
  ASSERT_EQ(scores.size(), 2u);
  const sim::Metrics& m = runner.record().metrics;
  EXPECT_EQ(m.Number("lines.scans"), static_cast<double>(runner.record().laser.size()));
  for (const std::string name : {"split_and_merge", "incremental"}) {
    EXPECT_GE(m.Number("lines." + name + ".recall"), 0.9) << name;
    EXPECT_GE(m.Number("lines." + name + ".precision"), 0.9) << name;
    EXPECT_GT(m.Number("lines." + name + ".points_per_line"), 20.0) << name;
    EXPECT_LT(m.Number("lines." + name + ".sigma_r_m"), 0.02) << name;
  }
  EXPECT_NE(LineTimingJson(scores).find("\"split_and_merge\": {\"us_per_scan\""),
            std::string::npos);
}

}  // namespace
}  // namespace plywood::eval
