// RunContent (no window needed): what the overlays are given matches what the run's own outputs
// are built from.

#include "viewer/run_content.h"

#include <gtest/gtest.h>

#include "eval/geometric_map/geometric_map_run.h"
#include "perception/sonar_map/sonar_explorer.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/run_observer.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::viewer {
namespace {

using testing::SourceRoot;

// Updates a RunContent after every step and at the end, as the live viewer does.
class ContentWatcher : public sim::RunObserver {
 public:
  bool AfterStep(const sim::ExperimentRunner& runner) override {
    if (!content_) content_.emplace(runner);
    latest_ = content_->Update(runner);
    return true;
  }
  void RunFinished(const sim::ExperimentRunner& runner) override {
    latest_ = content_->Update(runner);
  }
  const FrameContent& latest() const { return latest_; }

 private:
  std::optional<RunContent> content_;
  FrameContent latest_;
};

TEST(RunContentTest, SeedThreesMapGrowsLiveIntoTheMapTheRunWritesAfterwards) {
  const sim::ExperimentConfig config = sim::LoadExperimentConfig(
      SourceRoot() / "experiments/seed003_office.yaml", {"duration_s=30"});
  sim::ExperimentRunner runner(config);
  ContentWatcher watcher;
  runner.SetObserver(&watcher);
  runner.Run();
  ASSERT_TRUE(watcher.latest().geometric_map);
  const GeometricMapView& live = *watcher.latest().geometric_map;

  const eval::GeometricMapRun after =
      eval::BuildGeometricMap(runner.record(), config.geometric_map);
  std::vector<GeometricMapView::Segment> expected;
  for (const perception::MapSegment& s : after.map.segments()) {
    if (s.pseudo || after.map.Confirmed(s))
      expected.push_back({s.line.start, s.line.end, s.pseudo});
  }
  ASSERT_GT(expected.size(), 5u) << "30 s of the office must map some walls";
  ASSERT_EQ(live.segments.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(live.segments[i].pseudo, expected[i].pseudo) << i;
    EXPECT_LT((live.segments[i].a_W - expected[i].a_W).norm(), 1e-9) << i;
    EXPECT_LT((live.segments[i].b_W - expected[i].b_W).norm(), 1e-9) << i;
  }
  EXPECT_EQ(live.clusters.size(), after.map.clusters().size());
  EXPECT_FALSE(watcher.latest().grid) << "no sonar explorer, no occupancy grid";
}

TEST(RunContentTest, SeedOnesGridIsTheExplorersGridCellForCell) {
  const sim::ExperimentConfig config = sim::LoadExperimentConfig(
      SourceRoot() / "experiments/seed001_room_1.yaml", {"duration_s=10"});
  sim::ExperimentRunner runner(config);
  ContentWatcher watcher;
  runner.SetObserver(&watcher);
  runner.Run();
  // The grid is refreshed once per simulated second; compare it with a fresh content's at the end.
  RunContent fresh(runner);
  const FrameContent& now = fresh.Update(runner);
  ASSERT_TRUE(now.grid);
  const auto* explorer = dynamic_cast<const perception::SonarExplorer*>(runner.controller());
  ASSERT_NE(explorer, nullptr);
  const perception::LogOddsGrid& grid = explorer->grid();
  ASSERT_EQ(now.grid->width, grid.width());
  ASSERT_EQ(now.grid->height, grid.height());
  long known = 0;
  for (int iy = 0; iy < grid.height(); ++iy) {
    for (int ix = 0; ix < grid.width(); ++ix) {
      const float p = now.grid->occupied_p[static_cast<std::size_t>(iy) * grid.width() + ix];
      ASSERT_NEAR(p, grid.Probability(ix, iy), 1e-6);
      known += std::abs(p - 0.5f) > 0.1f;
    }
  }
  EXPECT_GT(known, 100) << "10 s of sonar must have mapped some cells";
  const Eigen::Vector2d c = grid.CellCentre(3, 4);
  EXPECT_LT((now.grid->cell_00_centre_W + now.grid->cell_m * Eigen::Vector2d(3, 4) - c).norm(),
            1e-12);
}

}  // namespace
}  // namespace plywood::viewer
