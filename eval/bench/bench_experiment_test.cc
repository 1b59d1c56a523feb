#include "eval/bench/bench_experiment.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::eval {
namespace {

// s62: the bench's last line set the default run's simulated time to its duration_s (120 s), but
// the office tour's waypoint controller finishes at 73.66 s, so the line said "120.0 s simulated"
// and overstated the run's real-time factor by 1.6x. It is the time the run simulated.
TEST(BenchExperimentTest, TheDefaultRunsSimulatedTimeIsTheTimeItRan) {
  // RunBench writes its tiled world and the default run under the temp directory: a private one,
  // so that a `plywood bench` running beside the tests is not touched.
  const std::filesystem::path scratch = testing::MakeTempDir("bench_experiment");
  ASSERT_EQ(setenv("TMPDIR", scratch.c_str(), 1), 0);
  // s64: another bench's default run, there under the name every bench used (half written as a
  // bench beside this one writes it; here with a file no run writes): the bench exited 2 ("holds
  // files that are not a Plywood run", or "cannot move the finished run into place").
  const std::filesystem::path other_bench = scratch / "plywood-bench-default-run";
  std::filesystem::create_directories(other_bench);
  std::ofstream(other_bench / "notes.txt") << "another bench's\n";
  BenchOptions options;
  options.seconds = 1.0;
  options.repeats = 1;
  options.min_wall_s = 0.0;
  const BenchFigures figures = RunBench(options);

  const sim::ExperimentConfig config =
      sim::LoadExperimentConfig(testing::SourceRoot() / "experiments" / "default.yaml", {});
  sim::ExperimentRunner runner(config);
  runner.Run();
  ASSERT_LT(runner.cost().simulated_s, config.duration_s) << "the tour no longer ends early";
  EXPECT_EQ(figures.default_run_simulated_s, runner.cost().simulated_s);

  // The other bench's folder as it was; nothing of this bench's but the tiled world left behind.
  EXPECT_TRUE(std::filesystem::exists(other_bench / "notes.txt"));
  std::set<std::string> left;
  for (const auto& entry : std::filesystem::directory_iterator(scratch)) {
    left.insert(entry.path().filename().string());
  }
  EXPECT_EQ(left,
            (std::set<std::string>{"plywood-bench-default-run", "plywood-bench-office-3x3.xml"}));
}

}  // namespace
}  // namespace plywood::eval
