#include "eval/bench/bench_experiment.h"

#include <gtest/gtest.h>

#include <cstdlib>

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
  ASSERT_EQ(setenv("TMPDIR", testing::MakeTempDir("bench_experiment").c_str(), 1), 0);
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
}

}  // namespace
}  // namespace plywood::eval
