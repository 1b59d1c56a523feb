// UMBmark end to end in the simulator (issue 3's acceptance): with E_d = 1.005 and E_b = 1.03
// injected into the simulated robot, the shipped experiment recovers both and the correction
// shrinks E_max,syst at least tenfold. Also: seed 001's turn calibration sees the same track error.

#include "eval/odometry/umbmark_experiment.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "plywood_paths.h"
#include "sim/config/config_error.h"

namespace plywood::eval {
namespace {

sim::ExperimentConfig Shipped(std::vector<std::string> overrides) {
  overrides.push_back("robot.deviation.wheel_diameter_ratio=1.005");
  overrides.push_back("robot.deviation.track_ratio=1.03");
  return sim::LoadExperimentConfig(std::string(PLYWOOD_SOURCE_ROOT) + "/experiments/umbmark.yaml",
                                   overrides);
}

TEST(UmbmarkExperimentTest, RecoversInjectedErrorsAndCorrectsThem) {
  // Two squares each way keep the test short; each run is deterministic up to encoder slip.
  const sim::ExperimentConfig config = Shipped({"sensors.encoders.slip_sigma=0.001"});
  UmbmarkOptions options = ReadUmbmarkOptions(config);
  options.runs_per_direction = 2;
  const UmbmarkOutcome outcome = RunUmbmark(config, options);
  const robot::UmbmarkResult& before = outcome.before.result;
  const robot::UmbmarkResult& after = outcome.after.result;
  std::printf(
      "E_d %.5f, E_b %.5f, E_max,syst %.4f m -> %.4f m (%.1fx); turns %d, mean error %.3f deg\n",
      before.ed, before.eb, before.e_max_syst_m, after.e_max_syst_m,
      before.e_max_syst_m / after.e_max_syst_m, outcome.before.turn_calibration.turns,
      outcome.before.turn_calibration.mean_error_deg);
  EXPECT_NEAR(before.ed, 1.005, 0.001);
  EXPECT_NEAR(before.eb, 1.03, 0.005);
  EXPECT_LE(after.e_max_syst_m, before.e_max_syst_m / 10.0);
  EXPECT_EQ(outcome.metrics.Number("umbmark.ed"), before.ed);
  EXPECT_EQ(outcome.metrics.Number("umbmark.e_max_syst_after_m"), after.e_max_syst_m);
  // 4 spot turns per square; a 3 % wider track under-turns each 90 deg by about 2.6 deg.
  EXPECT_EQ(outcome.before.turn_calibration.turns, 16);
  EXPECT_NEAR(outcome.before.turn_calibration.mean_error_deg, 90.0 / 1.03 - 90.0, 0.5);
}

TEST(UmbmarkExperimentTest, RejectsGroundTruthSteering) {
  const sim::ExperimentConfig config = Shipped({"controller.steer_by=ground_truth"});
  EXPECT_THROW(RunUmbmark(config, ReadUmbmarkOptions(config)), sim::ConfigError);
}

}  // namespace
}  // namespace plywood::eval
