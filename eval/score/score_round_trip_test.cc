// The file scorers against the runner's own figures: a run's own trajectory.<estimator>.tum,
// trajectory.csv and lines.csv score exactly (same doubles) what its metrics.json says; a
// trajectory offset from the truth by a constant scores the closed-form errors; a grid made from
// the truth scores e = 0, an all-free grid the area that is not free.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "eval/protocol.h"
#include "eval/score/csv_table.h"
#include "eval/score/grid_score.h"
#include "eval/score/lines_score.h"
#include "eval/score/trajectory_score.h"
#include "perception/logs/tum_trajectory.h"
#include "render/png_image.h"
#include "sim/config/config_error.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/format_number.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/metrics_json_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::eval {
namespace {

namespace fs = std::filesystem;

// 3 simulated seconds in the office with a turn, three estimators and every line extractor,
// written as `plywood run` writes it. Made once for all tests.
const fs::path& RunDir() {
  static const fs::path dir = [] {
    const fs::path root = testing::MakeTempDir("score_round_trip");
    const fs::path yaml = testing::WriteFile(
        root / "experiment.yaml",
        "name: score_round_trip\n"
        "seed: 3\n"
        "duration_s: 3\n"
        "world: " +
            (testing::SourceRoot() / "worlds" / "office.xml").string() +
            "\n"
            "robot: {model: p3dx, spawn: {x_m: -6.5, y_m: 0.0, theta_deg: 0}}\n"
            "controller: {type: waypoints, speed_m_s: 0.4, waypoints: [[-6.0, 0.0], [-6.0, 1.0]]}\n"
            "sensors:\n"
            "  laser: {rate_hz: 10}\n"
            "  encoders: {slip_sigma: 0.01}\n"
            "  gyro: {noise_sigma_rad_s: 0.002, bias_rad_s: 0.001}\n"
            "odometry: {encoder: {}, gyro: {}, ekf: {}}\n"
            "lines: {}\n"
            "output: {snapshot: false}\n");
    const sim::ExperimentConfig config = sim::LoadExperimentConfig(yaml);
    EXPECT_EQ(RunProtocol({config, root / "run", true, false}), 0);
    return root / "run";
  }();
  return dir;
}

std::map<std::string, std::string> RunMetrics() {
  return testing::FlattenMetricsJson(testing::Slurp(RunDir() / "metrics.json"));
}

// Every figure of `report` has the same text (so the same double) in the run's metrics.json.
void ExpectSameAsRun(const ScoreReport& report, const std::string& prefix) {
  const auto run = RunMetrics();
  const auto scored = testing::FlattenMetricsJson(report.metrics.ToJson());
  int compared = 0;
  for (const auto& [key, text] : scored) {
    if (key.rfind(prefix, 0) != 0) continue;
    ASSERT_TRUE(run.count(key)) << key;
    EXPECT_EQ(text, run.at(key)) << key;
    ++compared;
  }
  EXPECT_GT(compared, 3);
}

TEST(ScoreRoundTripTest, EachEstimatorsTumFileScoresExactlyItsMetrics) {
  for (const std::string name : {"encoder", "gyro", "ekf"}) {
    SCOPED_TRACE(name);
    const ScoreReport report =
        ScoreTrajectoryFile(RunDir(), RunDir() / ("trajectory." + name + ".tum"));
    ExpectSameAsRun(report, "odometry." + name + ".");
    EXPECT_EQ(testing::FlattenMetricsJson(report.metrics.ToJson()).at("truth.distance_m"),
              RunMetrics().at("truth.distance_m"));
  }
  // The run turned, so headings were really compared.
  EXPECT_NE(RunMetrics().at("odometry.gyro.heading_error_deg"), "0");
}

TEST(ScoreRoundTripTest, PlywoodCsvLayoutScoresEveryEstimatorExactly) {
  const ScoreReport report = ScoreTrajectoryFile(RunDir(), RunDir() / "trajectory.csv");
  ExpectSameAsRun(report, "odometry.");
  EXPECT_EQ(report.metrics.values().count("odometry.truth.ate_rms_m"), 0u);  // truth is skipped
  EXPECT_EQ(report.metrics.values().size(), 1u + 3u * 4u);
}

TEST(ScoreRoundTripTest, ConstantOffsetFromTheTruthScoresTheClosedFormErrors) {
  const auto truth = perception::ReadTumTrajectory(RunDir() / "trajectory.truth.tum");
  // 0.05 m and 2.865 deg: within what a start may miss the spawn by (0.1 m and 10 deg; farther, it
  // is refused: ScoreCliTest.AnEstimateThatDoesNotStartAtTheSpawnIsRefused).
  const double dx = 0.03, dy = -0.04, dtheta = 0.05;
  std::ostringstream text;
  for (const auto& p : truth) {
    perception::WriteTumPose(
        text, p.time_s,
        {p.pose.x_m + dx, p.pose.y_m + dy, msgs::WrapAngle(p.pose.theta_rad + dtheta)});
  }
  const fs::path file =
      testing::WriteFile(testing::MakeTempDir("score_offset") / "offset.tum", text.str());
  const ScoreReport report = ScoreTrajectoryFile(RunDir(), file);
  const sim::Metrics& m = report.metrics;
  const double distance = m.Number("truth.distance_m");
  EXPECT_GT(distance, 0.3);
  EXPECT_NEAR(m.Number("odometry.offset.ate_rms_m"), 0.05, 1e-12);
  EXPECT_NEAR(m.Number("odometry.offset.final_error_m"), 0.05, 1e-12);
  EXPECT_NEAR(m.Number("odometry.offset.drift_percent"), 100.0 * 0.05 / distance, 1e-10);
  EXPECT_NEAR(m.Number("odometry.offset.heading_error_deg"), dtheta * 180 / std::numbers::pi,
              1e-10);
}

TEST(ScoreRoundTripTest, PosesBetweenStampsAreInterpolatedAlongTheShorterArc) {
  // A file at 1 Hz along x = t with the heading passing through pi; the run samples at 0.25 s.
  NamedTrajectory estimate{"e", {}};
  for (int k = 0; k <= 2; ++k) {
    estimate.poses.push_back({double(k), {double(k), 0.0, k == 1 ? -3.0 : 3.0}, std::size_t(k)});
  }
  const std::vector<double> times = {0.0, 0.5, 1.0, 1.25, 2.0005};
  const auto poses = PosesAtTimes(estimate, times, "e.tum", 1e-3);
  EXPECT_EQ(poses[0], estimate.poses[0].pose);
  EXPECT_NEAR(poses[1].x_m, 0.5, 1e-15);
  EXPECT_NEAR(std::abs(poses[1].theta_rad), std::numbers::pi, 1e-12);  // not 0: shorter arc
  EXPECT_EQ(poses[2], estimate.poses[1].pose);
  EXPECT_NEAR(poses[3].theta_rad, msgs::WrapAngle(-3.0 - 0.25 * (2 * std::numbers::pi - 6.0)),
              1e-12);
  EXPECT_EQ(poses[4], estimate.poses[2].pose);  // within the tolerance after the last pose
  EXPECT_THROW(PosesAtTimes(estimate, {0.0, 2.5}, "e.tum", 1e-3), sim::ConfigError);
  EXPECT_THROW(PosesAtTimes(estimate, {-0.5, 2.0}, "e.tum", 1e-3), sim::ConfigError);
  EXPECT_THROW(PosesAtTimes(estimate, {0.5, 1.5}, "e.tum", 1e-3), sim::ConfigError);
}

TEST(ScoreRoundTripTest, OwnLinesCsvScoresExactlyItsMetrics) {
  const ScoreReport report = ScoreLinesFile(RunDir(), RunDir() / "lines.csv");
  ExpectSameAsRun(report, "lines.");
  EXPECT_EQ(report.metrics.values().size(), 1u + 5u * 6u);  // lines.scans + 5 extractors
  // The run really found and matched lines.
  EXPECT_NE(RunMetrics().at("lines.split_and_merge.recall"), "0");
}

TEST(ScoreRoundTripTest, EndpointsAloneGiveTheSameRecallAndPrecision) {
  // Only scan, extractor, the endpoints and the points used (the match rule's direction tolerance
  // depends on them): the line through the endpoints replaces the fitted normal form.
  const CsvTable full = ReadCsv(RunDir() / "lines.csv");
  const int points = full.Column("points");
  ASSERT_GE(points, 0);
  std::string text = "scan,extractor,x1_m,y1_m,x2_m,y2_m,points\n";
  for (const CsvRow& row : full.rows) {
    for (int c = 0; c < 6; ++c) text += row.fields[c] + ",";
    text += row.fields[points] + "\n";
  }
  const fs::path file =
      testing::WriteFile(testing::MakeTempDir("score_endpoints") / "endpoints.csv", text);
  const auto scored = testing::FlattenMetricsJson(ScoreLinesFile(RunDir(), file).metrics.ToJson());
  const auto run = RunMetrics();
  for (const std::string name :
       {"polar_neighbour", "split_and_merge", "incremental", "ransac", "hough"}) {
    SCOPED_TRACE(name);
    const std::string key = "lines." + name + ".";
    EXPECT_EQ(scored.at(key + "recall"), run.at(key + "recall"));
    EXPECT_EQ(scored.at(key + "precision"), run.at(key + "precision"));
    EXPECT_NEAR(std::stod(scored.at(key + "sigma_r_m")), std::stod(run.at(key + "sigma_r_m")),
                1e-9);
  }
}

// audit s48: a lines file written in the world frame (as mapping programs write segments: the
// run's own segments moved by each scan's true sensor pose) scored recall 0.02 and precision 0.04
// against walls it had found, exit 0. A segment ends near a return of its scan, which tells.
TEST(ScoreRoundTripTest, ALinesFileInTheWorldFrameIsRefused) {
  const CsvTable lines = ReadCsv(RunDir() / "lines.csv");
  const CsvTable scans = ReadCsv(RunDir() / "laser_scans.csv");
  std::string text = "scan,extractor,x1_m,y1_m,x2_m,y2_m\n";
  for (const CsvRow& row : lines.rows) {
    const long scan = lines.Integer(row, lines.Column("scan"), "scan");
    const CsvRow& pose = scans.rows.at(static_cast<std::size_t>(scan));
    const double x = scans.Number(pose, scans.Column("sensor_x_m"), "x");
    const double y = scans.Number(pose, scans.Column("sensor_y_m"), "y");
    const double theta = scans.Number(pose, scans.Column("sensor_theta_rad"), "theta");
    text += std::to_string(scan) + "," + row.fields[lines.Column("extractor")];
    for (const char* end : {"1", "2"}) {
      const double px = lines.Number(row, lines.Column(std::string("x") + end + "_m"), "x");
      const double py = lines.Number(row, lines.Column(std::string("y") + end + "_m"), "y");
      text += "," + sim::FormatNumber(x + std::cos(theta) * px - std::sin(theta) * py) + "," +
              sim::FormatNumber(y + std::sin(theta) * px + std::cos(theta) * py);
    }
    text += "\n";
  }
  const fs::path file =
      testing::WriteFile(testing::MakeTempDir("score_world_frame") / "w.csv", text);
  try {
    ScoreLinesFile(RunDir(), file);
    ADD_FAILURE() << "a world-frame lines file was scored";
  } catch (const sim::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file.string() + ":2: x1_m, y1_m: the end ("), std::string::npos) << what;
    EXPECT_NE(what.find(" m from every return of scan 0, more than 0.5 m: segments are in their "
                        "scan's sensor frame (laser_scans.csv), not the world's"),
              std::string::npos)
        << what;
  }
  // The run's own file, whose ends lie on its scans' returns, still scores (the tests above).
  // s54: an end 1e300 m out read "lies null m from every return" (the squared norm overflowed).
  const fs::path far = testing::WriteFile(testing::MakeTempDir("score_far_end") / "far.csv",
                                          "scan,extractor,x1_m,y1_m,x2_m,y2_m\n"
                                          "0,mine,-1e300,0,1,0\n");
  try {
    ScoreLinesFile(RunDir(), far);
    ADD_FAILURE() << "an end 1e300 m out was scored";
  } catch (const sim::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(far.string() + ":2: x1_m, y1_m: the end (-1e+300, 0) lies 1e+300 m from "
                                       "every return of scan 0"),
              std::string::npos)
        << what;
  }
}

// audit s48: a lines file appended to itself scored each segment twice, exit 0: the same recall
// and precision but lines_per_scan doubled and points_per_line halved.
TEST(ScoreRoundTripTest, ALinesFileWrittenTwiceIsRefused) {
  const std::string own = testing::Slurp(RunDir() / "lines.csv");
  const std::size_t rows = static_cast<std::size_t>(std::count(own.begin(), own.end(), '\n')) - 1;
  ASSERT_GT(rows, 0u);
  const fs::path file = testing::WriteFile(testing::MakeTempDir("score_twice") / "twice.csv",
                                           own + own.substr(own.find('\n') + 1));
  try {
    ScoreLinesFile(RunDir(), file);
    ADD_FAILURE() << "a lines file written twice was scored";
  } catch (const sim::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ":" + std::to_string(rows + 2) +
                                         ": x1_m: repeats line 2 (scan 0, extractor "),
              std::string::npos)
        << e.what();
  }
}

// s61 thirty-sixth pass: the same segment again with its ends swapped (a tool that writes its
// lines from either end) passed the repeat check and was counted twice, exit 0.
TEST(ScoreRoundTripTest, ASegmentRepeatedWithItsEndsSwappedIsRefused) {
  const std::string own = testing::Slurp(RunDir() / "lines.csv");
  const std::size_t rows = static_cast<std::size_t>(std::count(own.begin(), own.end(), '\n')) - 1;
  ASSERT_GT(rows, 0u);
  // The first row, its fields split on commas (no field of the run's own file is quoted).
  const std::size_t begin = own.find('\n') + 1;
  std::vector<std::string> fields;
  std::stringstream first(own.substr(begin, own.find('\n', begin) - begin));
  for (std::string field; std::getline(first, field, ',');) fields.push_back(field);
  ASSERT_GE(fields.size(), 6u);
  std::swap(fields[2], fields[4]);  // x1_m <-> x2_m
  std::swap(fields[3], fields[5]);  // y1_m <-> y2_m
  std::string swapped;
  for (std::size_t i = 0; i < fields.size(); ++i) swapped += (i ? "," : "") + fields[i];
  const fs::path file = testing::WriteFile(testing::MakeTempDir("score_swapped") / "swapped.csv",
                                           own + swapped + "\n");
  try {
    ScoreLinesFile(RunDir(), file);
    ADD_FAILURE() << "a segment given twice, its ends swapped, was scored";
  } catch (const sim::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ":" + std::to_string(rows + 2) +
                                         ": x1_m: repeats line 2 (scan 0, extractor "),
              std::string::npos)
        << e.what();
  }
}

// A grid image of the truth's own cells, sampled at each pixel's centre.
GridImage TruthImage(const OccupancyTruth& truth, const GridPlacement& placement, int width,
                     int height) {
  GridImage image{width, height, std::vector<double>(std::size_t(width) * height)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Eigen::Vector2d centre =
          placement.origin_W +
          placement.resolution_m * Eigen::Vector2d(x + 0.5, height - 1 - y + 0.5);
      const auto cell = truth.raster.CellAt(centre);
      image.brightness[std::size_t(y) * width + x] =
          cell && truth.CellFree(cell->x(), cell->y()) ? 1.0 : 0.0;
    }
  return image;
}

void WritePgm(const GridImage& image, const fs::path& path) {
  std::ofstream out(path, std::ios::binary);
  out << "P5\n# truth\n" << image.width << ' ' << image.height << "\n255\n";
  for (double b : image.brightness) out.put(static_cast<char>(b > 0.5 ? 255 : 0));
}

TEST(ScoreGridTest, TheTruthItselfScoresZeroAndCoarserCopiesStayWithinTheirDiscretisation) {
  const auto truth = LoadRunOccupancyTruth(RunDir());
  // Aligned with the 1 cm truth raster: every cell is its own pixel.
  GridPlacement fine{0.01, truth->raster.origin_xy, 0.5};
  const GridImage exact = TruthImage(*truth, fine, truth->raster.width, truth->raster.height);
  EXPECT_EQ(ScoreGridImage(*truth, exact, fine, "exact").error_cells, 0.0);

  // 5 cm pixels: a truth cell is misread only when its centre and its pixel's centre (at most
  // R / sqrt(2) apart) straddle the boundary, so within R / sqrt(2) + one cell of it. Bound:
  // band area 2 (R / sqrt(2) + 0.01) L over the free area, L the boundary length in the box.
  double boundary_m = 0.0;
  for (int iy = truth->y0; iy <= truth->y1; ++iy)
    for (int ix = truth->x0; ix <= truth->x1; ++ix) {
      if (ix < truth->x1)
        boundary_m += 0.01 * (truth->CellFree(ix, iy) != truth->CellFree(ix + 1, iy));
      if (iy < truth->y1)
        boundary_m += 0.01 * (truth->CellFree(ix, iy) != truth->CellFree(ix, iy + 1));
    }
  const double r = 0.05;
  GridPlacement coarse{r, truth->raster.origin_xy - Eigen::Vector2d(0.013, 0.027), 0.5};
  const int w = int(std::ceil(truth->raster.width * 0.01 / r)) + 2;
  const int h = int(std::ceil(truth->raster.height * 0.01 / r)) + 2;
  const OccupancyError e = ScoreGridImage(*truth, TruthImage(*truth, coarse, w, h), coarse, "c");
  const double bound = 2.0 * (r / std::sqrt(2.0) + 0.01) * boundary_m / e.AreaTotalM2();
  EXPECT_GT(e.Error(), 0.0);
  EXPECT_LT(e.Error(), bound);
  EXPECT_LT(bound, 0.5);  // the bound says something

  // Through the files: the same figures from a PGM and from a PNG.
  const fs::path dir = testing::MakeTempDir("score_grid");
  WritePgm(exact, dir / "truth.pgm");
  const ScoreReport from_pgm = ScoreGridFile(RunDir(), dir / "truth.pgm", fine);
  EXPECT_EQ(from_pgm.metrics.Number("occupancy.grid_error"), 0.0);
  render::RgbImage rgb(exact.width, exact.height);
  for (std::size_t i = 0; i < exact.brightness.size(); ++i) {
    for (int c = 0; c < 3; ++c) rgb.pixels[3 * i + c] = exact.brightness[i] > 0.5 ? 255 : 0;
  }
  render::WritePng(rgb, dir / "truth.png");
  EXPECT_EQ(ScoreGridFile(RunDir(), dir / "truth.png", fine).metrics.Number("occupancy.grid_error"),
            0.0);
}

// s38: `--resolution 1e300` put the whole world in one pixel and scored e 0. A map must put at
// least kMinPixelsAcross pixels across the scored area's shorter side.
TEST(ScoreGridTest, AGridOfFewerThanTenPixelsAcrossTheScoredAreaIsRefused) {
  const auto truth = LoadRunOccupancyTruth(RunDir());
  const Eigen::Vector2d low = truth->raster.CellCentre(truth->x0, truth->y0);
  const Eigen::Vector2d high = truth->raster.CellCentre(truth->x1, truth->y1);
  const Eigen::Vector2d extent = (high - low).array() + 0.01;
  const auto copy_at = [&](double r) {
    GridPlacement placement{r, low - Eigen::Vector2d(0.005 + r, 0.005 + r), 0.5};
    const int w = int(std::ceil(extent.x() / r)) + 2, h = int(std::ceil(extent.y() / r)) + 2;
    return ScoreGridImage(*truth, TruthImage(*truth, placement, w, h), placement, "copy");
  };
  // Ten pixels across: scored, and within the discretisation a truth copy allows.
  const OccupancyError ten = copy_at(extent.minCoeff() / kMinPixelsAcross);
  EXPECT_GT(ten.Error(), 0.0);
  EXPECT_LT(ten.Error(), 1.0);
  // Fewer (9.5, one, and 1e300 m per pixel, which scored e 0): refused, naming the flag.
  for (const double r : {extent.minCoeff() / 9.5, extent.minCoeff(), 1e300}) {
    SCOPED_TRACE(r);
    std::string refusal = "scored";
    try {
      copy_at(r);
    } catch (const std::invalid_argument& e) {
      refusal = e.what();
    }
    EXPECT_EQ(refusal.rfind("--resolution: ", 0), 0u) << refusal;
    EXPECT_NE(refusal.find("at least 10 are needed"), std::string::npos) << refusal;
  }
}

TEST(ScoreGridTest, AnAllFreeGridScoresTheAreaThatIsNotFree) {
  const auto truth = LoadRunOccupancyTruth(RunDir());
  double box = 0.0, free = 0.0;
  for (int iy = truth->y0; iy <= truth->y1; ++iy)
    for (int ix = truth->x0; ix <= truth->x1; ++ix) box += 1, free += truth->CellFree(ix, iy);
  ASSERT_GT(box, free);
  GridPlacement placement{0.1, truth->raster.origin_xy, 0.5};
  const int w = int(std::ceil(truth->raster.width * 0.01 / 0.1)) + 1;
  const int h = int(std::ceil(truth->raster.height * 0.01 / 0.1)) + 1;
  GridImage white{w, h, std::vector<double>(std::size_t(w) * h, 1.0)};
  EXPECT_EQ(ScoreGridImage(*truth, white, placement, "white").Error(), (box - free) / free);
  // Unknown grey (0.5 < threshold... 1 - 0.6 = 0.4 <= 0.5) is free too; black is all wrong.
  GridImage grey{w, h, std::vector<double>(std::size_t(w) * h, 0.6)};
  EXPECT_EQ(ScoreGridImage(*truth, grey, placement, "grey").Error(), (box - free) / free);
  GridImage black{w, h, std::vector<double>(std::size_t(w) * h, 0.0)};
  EXPECT_EQ(ScoreGridImage(*truth, black, placement, "black").Error(), 1.0);
}

}  // namespace
}  // namespace plywood::eval
