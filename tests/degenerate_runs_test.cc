// Runs that are valid but degenerate (a robot that never moves, a range cut below every wall, a
// search over less than a centimetre of travel): every figure they print or write is right, or
// null, or the run is refused naming its field; never nan, nor a figure computed over nothing
// (docs/errors.md, the s63 forty-eighth pass).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::MakeTempDir;
using testing::RunPlywood;
using testing::Slurp;
using testing::WriteFile;

// A robot that stands half a second in the hall, its encoders on: nothing moves, nothing is seen.
constexpr const char* kStandingExperiment =
    "name: standing\n"
    "duration_s: 0.5\n"
    "world: worlds/hall.xml\n"
    "robot: {model: p3dx, spawn: {x_m: 0, y_m: 0, theta_deg: 0}}\n"
    "sensors: {encoders: {}}\n"
    "output: {snapshot: false}\n";

fs::path Dir() {
  return MakeTempDir(std::string("degenerate_runs_") +
                     ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

// One line on stderr, exit 2, naming each of `must_contain`; nothing on stdout (no figure was
// printed before the refusal) and no results.
void ExpectRefusedBeforeAnyFigure(const CliResult& result, const fs::path& out,
                                  const std::vector<std::string>& must_contain) {
  EXPECT_EQ(result.exit_code, 2) << result.err;
  ASSERT_FALSE(result.err.empty());
  EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << "not one line: " << result.err;
  EXPECT_EQ(result.err.rfind("plywood: ", 0), 0u) << result.err;
  for (const std::string& text : must_contain) {
    EXPECT_NE(result.err.find(text), std::string::npos) << "'" << text << "' in: " << result.err;
  }
  EXPECT_EQ(result.out, "") << "figures printed before the refusal";
  EXPECT_FALSE(fs::exists(out / "metrics.json"));
}

// The printed summary of a robot that stands: metrics.json's drift_percent is null, and the
// summary says so (main printed "drift nan %").
TEST(DegenerateRunsTest, AStandingRobotsSummaryPrintsItsDriftAsNullNotNan) {
  const fs::path dir = Dir();
  const fs::path file = WriteFile(dir / "experiment.yaml", kStandingExperiment);
  const CliResult run =
      RunPlywood("run " + file.string() + " --out " + (dir / "out").string(), dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(Slurp(dir / "out" / "metrics.json").find("\"drift_percent\": null"), std::string::npos);
  EXPECT_NE(run.out.find("drift null (travelled < 1 cm)"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("nan"), std::string::npos) << run.out;
}

// A seed 000 room whose range cut lies below every wall: recall 0 / 0. Beside a room that has
// walls in view, main wrote recall 1 and precision 1 for it (metrics.json, rooms.csv), exit 0.
TEST(DegenerateRunsTest, ASeed000RoomWithNoWallWithinItsCutIsRefusedBeforeAnyFigure) {
  const fs::path dir = Dir();
  const std::string experiment =
      (testing::SourceRoot() / "experiments/seed000_rooms.yaml").string();
  const std::string common =
      " --set seed000_rooms.scans=1 --set 'lines.extractors=[split_and_merge]'";
  const CliResult two = RunPlywood(
      "run " + experiment + " --out " + (dir / "two").string() + common +
          " --set 'seed000_rooms.rooms=[{world: worlds/seed000_room_1.xml, range_cut_m: 4}, "
          "{world: worlds/seed000_room_2.xml, range_cut_m: 0.3}]'",
      dir);
  ExpectRefusedBeforeAnyFigure(two, dir / "two",
                               {experiment, "seed000_rooms.rooms[1].range_cut_m",
                                "seed000_room_2.xml", "0.3 m", "recall is undefined"});
  // The room alone: main refused, but only after printing its row (recall 1.000, reduction nanx).
  const CliResult alone = RunPlywood(
      "run " + experiment + " --out " + (dir / "alone").string() + common +
          " --set world=worlds/seed000_room_2.xml"
          " --set 'seed000_rooms.rooms=[{world: worlds/seed000_room_2.xml, range_cut_m: 0.3}]'",
      dir);
  ExpectRefusedBeforeAnyFigure(alone, dir / "alone",
                               {experiment, "seed000_rooms.rooms[0].range_cut_m", "0.3 m"});
}

// A rooms list given with --set that holds not the world: main ran the world alone at the
// top-level cut (seed000_room_1 at 4 m, exit 0), the list silently unused.
TEST(DegenerateRunsTest, ASeed000RoomsListWithoutTheWorldIsRefused) {
  const fs::path dir = Dir();
  const std::string experiment =
      (testing::SourceRoot() / "experiments/seed000_rooms.yaml").string();
  const CliResult run = RunPlywood(
      "run " + experiment + " --out " + (dir / "out").string() +
          " --set seed000_rooms.scans=1 --set 'lines.extractors=[split_and_merge]'"
          " --set 'seed000_rooms.rooms=[{world: worlds/seed000_room_2.xml, range_cut_m: 2}]'",
      dir);
  ExpectRefusedBeforeAnyFigure(
      run, dir / "out",
      {experiment + ": seed000_rooms.rooms: ", "changes nothing", "seed000_room_1.xml"});
  // The list with the world runs it, at the listed cut.
  const CliResult listed = RunPlywood(
      "run " + experiment + " --quiet --out " + (dir / "listed").string() +
          " --set seed000_rooms.scans=1 --set 'lines.extractors=[split_and_merge]'"
          " --set 'seed000_rooms.rooms=[{world: worlds/seed000_room_1.xml, range_cut_m: 3}]'",
      dir);
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  EXPECT_NE(Slurp(dir / "listed" / "rooms.csv").find("\nseed000_room_1,3,"), std::string::npos);
}

// A weighted-gain search over a run that travels less than 1 cm: main's line named neither the
// file nor a field ("plywood: run: distance_m: drift is undefined ...").
TEST(DegenerateRunsTest, AWeightedGainSearchOverLessThanACentimetreNamesTheExperiment) {
  const fs::path dir = Dir();
  const std::string experiment =
      (testing::SourceRoot() / "experiments/weighted_gain_calibration.yaml").string();
  const CliResult run = RunPlywood(
      "run " + experiment + " --out " + (dir / "out").string() + " --set duration_s=0.2", dir);
  ExpectRefusedBeforeAnyFigure(
      run, dir / "out",
      {experiment + ": weighted_gain_search: ", "less than 1 cm", "duration_s = 0.2 s"});
}

// An extractor that finds no line: its sigmas, points per line and reduction are null in
// metrics.json; the printed tables said "nan" (main), now "null".
TEST(DegenerateRunsTest, TablesOfAnExtractorThatFindsNoLinePrintNullNotNan) {
  const fs::path dir = Dir();
  const std::string experiment =
      (testing::SourceRoot() / "experiments/seed000_rooms.yaml").string();
  const CliResult rooms = RunPlywood(
      "run " + experiment + " --out " + (dir / "rooms").string() +
          " --set seed000_rooms.scans=1 --set 'lines.extractors=[split_and_merge, ransac]'"
          " --set lines.ransac.min_inliers=500 --set lines.ransac.min_points=500",
      dir);
  ASSERT_EQ(rooms.exit_code, 0) << rooms.err;
  EXPECT_NE(Slurp(dir / "rooms" / "metrics.json").find("\"sigma_r_m\": null"), std::string::npos);
  EXPECT_NE(rooms.out.find("ransac              0.00      null   0.000"), std::string::npos)
      << rooms.out;
  EXPECT_NE(rooms.out.find("ransac             0.000   1.000      null        null      null"),
            std::string::npos)
      << rooms.out;
  EXPECT_EQ(rooms.out.find("nan"), std::string::npos) << rooms.out;

  // One step of a standing robot in the hall: one laser scan, ransac asked for more inliers than
  // any wall gives it.
  const fs::path file =
      WriteFile(dir / "experiment.yaml",
                "name: one_scan\n"
                "duration_s: 0.01\n"
                "world: worlds/hall.xml\n"
                "robot: {model: p3dx, spawn: {x_m: 0, y_m: 0, theta_deg: 0}}\n"
                "sensors: {laser: {rate_hz: 10}}\n"
                "lines: {extractors: [ransac], ransac: {min_inliers: 300, min_points: 300}}\n"
                "output: {snapshot: false}\n");
  const CliResult run =
      RunPlywood("run " + file.string() + " --out " + (dir / "run").string(), dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("sigma_r null, sigma_alpha null, points/line null"), std::string::npos)
      << run.out;
  EXPECT_EQ(run.out.find("nan"), std::string::npos) << run.out;

  // The run's log of one scan replayed with the same extractor options.
  const CliResult replay = RunPlywood("replay " + (dir / "run" / "laser.log").string() +
                                          " --extractor ransac --set ransac.min_inliers=300"
                                          " --set ransac.min_points=300 --out " +
                                          (dir / "replay").string(),
                                      dir);
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  EXPECT_NE(replay.out.find("rms distance           null (no ray explained)"), std::string::npos)
      << replay.out;
  EXPECT_NE(replay.out.find("rays per line          null (no line found)"), std::string::npos)
      << replay.out;
  EXPECT_EQ(replay.out.find("nan"), std::string::npos) << replay.out;
}

// Seed 003's map over 3 s of the office with a scoring gate no segment passes, and no small object
// in view: main wrote endpoint_error_m and orientation_error_deg 0 (no segment matched) and
// cluster_recall 1 (0 objects of 0), and printed "endpoint error 0.000 m".
TEST(DegenerateRunsTest, AGeometricMapsFiguresOfNothingAreNull) {
  const fs::path dir = Dir();
  const std::string experiment =
      (testing::SourceRoot() / "experiments/seed003_office.yaml").string();
  const CliResult run =
      RunPlywood("run " + experiment + " --out " + (dir / "out").string() +
                     " --set duration_s=3 --set geometric_map.scoring.max_endpoint_distance_m=1e-6",
                 dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string metrics = Slurp(dir / "out" / "metrics.json");
  for (const char* key :
       {"\"cluster_recall\": null", "\"endpoint_error_m\": null", "\"orientation_error_deg\": null",
        "\"small_objects_observed\": 0", "\"precision\": 0", "\"segments\": 4"}) {
    EXPECT_NE(metrics.find(key), std::string::npos) << key << " in " << metrics;
  }
  EXPECT_NE(run.out.find("recall 0.000, precision 0.000, endpoint error null, 4 segments"),
            std::string::npos)
      << run.out;
}

// A sweep of one cell whose one run stood: its drift_percent is null. Main printed "n 0" with no
// word why, and plotted an empty box on axes round 0.
TEST(DegenerateRunsTest, ASweepOfOneStandingRunSaysItsMetricHasNoValue) {
  const fs::path dir = Dir();
  WriteFile(dir / "standing.yaml", kStandingExperiment);
  const fs::path sweep = WriteFile(dir / "one.yaml",
                                   "experiment: standing.yaml\n"
                                   "seeds: [1]\n"
                                   "metrics: [odometry.encoder.drift_percent, truth.distance_m]\n");
  const CliResult run =
      RunPlywood("sweep " + sweep.string() + " --jobs 1 --out " + (dir / "sweep").string(), dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("all runs: n 0 (no value in its run: null or absent in metrics.json"),
            std::string::npos)
      << run.out;
  EXPECT_FALSE(fs::exists(dir / "sweep" / "plots" / "odometry.encoder.drift_percent.png"));
}

}  // namespace
}  // namespace plywood
