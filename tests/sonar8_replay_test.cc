// Replays the real 8-sonar log (../shared/data/sonar8) through seed 001's grid integration with the
// classical cone model, writes a PNG, and checks that the walls the robot drove along come out as
// long straight occupied runs where the echoes put them (the log has no ground-truth map).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "perception/logs/sonar8_log.h"
#include "perception/sonar_map/log_odds_grid.h"
#include "perception/sonar_map/sonar_cell_model.h"
#include "plywood_paths.h"
#include "render/png_image.h"

namespace plywood {
namespace {

const std::filesystem::path kData =
    std::filesystem::path(PLYWOOD_SOURCE_ROOT) / ".." / "shared" / "data" / "sonar8";

perception::LogOddsGrid Replay(const std::vector<perception::Sonar8Record>& log) {
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (const auto& r : log) {
    x0 = std::min(x0, r.X_WR.x_m), x1 = std::max(x1, r.X_WR.x_m);
    y0 = std::min(y0, r.X_WR.y_m), y1 = std::max(y1, r.X_WR.y_m);
  }
  // 5 cm cells; each transducer paints only its own sector: half-angle 7.5 deg, half the 15 deg
  // between this log's front transducers (the 15 deg default smeared every echo over +-1.3 m at 5
  // m, and its free sweeps wiped the walls the side transducers heard). A weaker free update
  // (0.4) for the same reason.
  constexpr double kRes = 0.05;
  perception::LogOddsGridOptions o;
  o.resolution_m = kRes;
  o.origin_xy = {x0 - 5.5, y0 - 5.5};
  o.width = static_cast<int>((x1 - x0 + 11) / kRes);
  o.height = static_cast<int>((y1 - y0 + 11) / kRes);
  o.local_cells = static_cast<int>(11.0 / kRes);  // these sonars reach 5 m: a local grid of +-5.5 m
  o.local_cell_m = kRes;
  perception::LogOddsGrid grid(o);
  perception::ClassicalSonarOptions cone;
  cone.beam_half_angle_deg = 7.5;
  cone.arc_half_width_m = 0.1;
  cone.p_free = 0.4;
  const perception::ClassicalSonarModel model(cone);
  for (const auto& r : log) grid.Integrate(model, r.ring, r.X_WR);
  return grid;
}

TEST(Sonar8ReplayTest, WallsComeOutAsStraightOccupiedRuns) {
  if (!std::filesystem::exists(kData / "measurement.txt")) {
    GTEST_SKIP() << "no real sonar log at " << kData << " (../shared is absent)";
  }
  const auto log = perception::LoadSonar8Log(kData);
  ASSERT_EQ(log.size(), 413u);
  const perception::LogOddsGrid grid = Replay(log);

  render::RgbImage image(grid.width(), grid.height());
  int occupied = 0;
  for (int iy = 0; iy < grid.height(); ++iy)
    for (int ix = 0; ix < grid.width(); ++ix) {
      const auto g = static_cast<std::uint8_t>(255.0 * (1.0 - grid.Probability(ix, iy)));
      std::uint8_t* p = image.At(ix, grid.height() - 1 - iy);
      p[0] = p[1] = p[2] = g;
      occupied += grid.Probability(ix, iy) > 0.7;
    }
  const auto out = std::filesystem::path(PLYWOOD_BINARY_DIR) / "test_tmp" / "sonar8_grid.png";
  std::filesystem::create_directories(out.parent_path());
  render::WritePng(image, out);

  // Longest straight run of occupied cells along a row or a column: walls 2 m or more long that
  // the robot drove beside must show up as runs of at least 2 m with at most 1-cell gaps.
  auto longest = [&](bool rows) {
    int best = 0;
    const int outer = rows ? grid.height() : grid.width();
    const int inner = rows ? grid.width() : grid.height();
    for (int a = 0; a < outer; ++a) {
      int run = 0, gap = 0;
      for (int b = 0; b < inner; ++b) {
        const bool occ = rows ? grid.Probability(b, a) > 0.7 : grid.Probability(a, b) > 0.7;
        if (occ) {
          run += 1 + gap;
          gap = 0;
        } else if (run > 0 && gap < 1) {
          ++gap;
        } else {
          run = 0;
          gap = 0;
        }
        best = std::max(best, run);
      }
    }
    return best;
  };
  const int row_run = longest(true), col_run = longest(false);
  RecordProperty("occupied_cells", occupied);
  RecordProperty("longest_row_run", row_run);
  RecordProperty("longest_column_run", col_run);
  std::printf("occupied cells %d, longest x run %d cells, longest y run %d cells, picture %s\n",
              occupied, row_run, col_run, out.c_str());
  // The first leg runs along +x (x 0 to 8.6 m, y 0 to -0.2 m) between two corridor walls, whose
  // echoes lie about 1.19 m to the left and 0.9 m to the right (with door openings).
  // The share of columns (x 1 to 8 m) holding an occupied cell between y0 and y1.
  auto band = [&](double y0, double y1) {
    const double res = grid.resolution_m();
    const int columns = static_cast<int>(std::lround(7.0 / res)) + 1;  // x from 1 to 8 m
    const int rows = static_cast<int>(std::lround((y1 - y0) / res)) + 1;
    int hits = 0;
    for (int i = 0; i < columns; ++i) {
      bool hit = false;
      for (int j = 0; j < rows && !hit; ++j) {
        const Eigen::Vector2i c = grid.CellAt({1.0 + i * res, y0 + j * res});
        hit = c.x() >= 0 && grid.Probability(c.x(), c.y()) > 0.7;
      }
      hits += hit;
    }
    return static_cast<double>(hits) / columns;
  };
  const double left = band(1.05, 1.35), right = band(-1.05, -0.75);
  std::printf(
      "columns of the first leg with an occupied cell in the wall band: left %.3f, right %.3f\n",
      left, right);
  RecordProperty("left_wall_fraction", std::to_string(left));
  RecordProperty("right_wall_fraction", std::to_string(right));
  // Measured 0.631 and 0.759 (the 15 deg cone at 10 cm: 0.394 and 0.479).
  EXPECT_GE(left, 0.5);
  EXPECT_GE(right, 0.6);
  EXPECT_GE(std::max(row_run, col_run) * grid.resolution_m(), 2.0);
  // Walls are thin: occupied cells are a small part of what the sonars swept.
  EXPECT_LT(occupied, grid.width() * grid.height() / 5);
}

TEST(Sonar8LogTest, MalformedLineGivesItsNumber) {
  const auto dir = std::filesystem::path(PLYWOOD_BINARY_DIR) / "test_tmp" / "sonar8_bad";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "measurement.txt") << "1 5110 5110 2320 2360 5110 5110 2160 1190\n"
                                         << "2 5110 5110 2320 x 5110 5110 2160 1190\n";
  std::ofstream(dir / "poses.txt") << "1 0 0 0\n2 0 0 0\n";
  try {
    perception::LoadSonar8Log(dir);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("measurement.txt: line 2: 'x' is not a number"),
              std::string::npos)
        << e.what();
  }
  std::ofstream(dir / "measurement.txt") << "1 5110 5110 2320 2360 5110 5110 2160\n";
  EXPECT_THROW(perception::LoadSonar8Log(dir), std::runtime_error);
}

// audit s41: a negative range was read as "no echo", which the cone model takes as free space out
// to the 5 m maximum: the grid was painted free where nothing was measured, without a word. Lines
// are named as they stand in the file (blank lines counted), in poses.txt too.
TEST(Sonar8LogTest, ANegativeRangeIsRefusedNamingItsLineAndTransducer) {
  const auto dir = std::filesystem::path(PLYWOOD_BINARY_DIR) / "test_tmp" / "sonar8_negative";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "measurement.txt") << "1 5110 5110 2320 2360 5110 5110 2160 1190\n\n"
                                         << "2 5110 5110 -300 2360 5110 5110 2160 1190\n";
  std::ofstream(dir / "poses.txt") << "1 0 0 0\n2 0 0 0\n";
  try {
    perception::LoadSonar8Log(dir);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "measurement.txt").string() +
                                         ": line 3: r3: negative range -300 mm"),
              std::string::npos)
        << e.what();
  }
  std::ofstream(dir / "measurement.txt") << "1 5110 5110 2320 2360 5110 5110 2160 1190\n"
                                         << "2 5110 5110 2320 2360 5110 5110 2160 1190\n";
  std::ofstream(dir / "poses.txt") << "1 0 0 0\n\n3 0 0 0\n";
  try {
    perception::LoadSonar8Log(dir);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "poses.txt").string() +
                                         ": line 3: timestamp differs from line 2 of "
                                         "measurement.txt"),
              std::string::npos)
        << e.what();
  }
  // -0 is no negative range: a reading below the usable 170 mm, no echo.
  std::ofstream(dir / "measurement.txt") << "1 -0 5110 2320 2360 5110 5110 2160 1190\n";
  std::ofstream(dir / "poses.txt") << "1 0 0 0\n";
  EXPECT_FALSE(perception::LoadSonar8Log(dir).front().ring.readings[0].echo);
}

// audit s40: measurement.txt and poses.txt as folders (a folder opens as a stream that reads
// nothing), or as two empty files, loaded as a log of no rings without a word: the grid was
// integrated from nothing.
TEST(Sonar8LogTest, FoldersOrEmptyFilesAreRefusedNamingTheFile) {
  const auto dir = std::filesystem::path(PLYWOOD_BINARY_DIR) / "test_tmp" / "sonar8_empty";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "measurement.txt");
  std::filesystem::create_directories(dir / "poses.txt");
  const auto expect_error = [&](const std::string& text) {
    try {
      perception::LoadSonar8Log(dir);
      ADD_FAILURE() << "no error, expected: " << text;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  expect_error((dir / "measurement.txt").string() + ": not a regular file (a folder or a device?)");
  std::filesystem::remove_all(dir / "measurement.txt");
  std::filesystem::remove_all(dir / "poses.txt");
  std::ofstream(dir / "measurement.txt") << "";
  std::ofstream(dir / "poses.txt") << "\n";
  expect_error((dir / "measurement.txt").string() + ": no measurement line");
}

}  // namespace
}  // namespace plywood
