#include "tests/support/sonar_map_test_support.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::testing {
namespace {

void Run(const std::string& experiment, const std::filesystem::path& out,
         const std::string& extra_args, SonarMapScore* score) {
  const auto result = RunPlywood("run " + (SourceRoot() / "experiments" / experiment).string() +
                                     " --quiet --out " + out.string() + " " + extra_args,
                                 out.parent_path());
  ASSERT_EQ(result.exit_code, 0) << experiment << " " << extra_args << ": " << result.err;
  const YAML::Node metrics = YAML::LoadFile((out / "metrics.json").string());
  score->error = metrics["occupancy"]["error"].as<double>();
  score->grid_error = metrics["occupancy"]["grid_error"].as<double>();
  score->contacts = metrics["sensors"]["bumpers"]["contact_samples"].as<double>();
  score->end_reason = metrics["exploration"]["end_reason"].as<std::string>();
}

}  // namespace

SonarMapScore RunSonarMap(const std::string& experiment, const std::filesystem::path& out,
                          const std::string& extra_args) {
  SonarMapScore score;
  Run(experiment, out, extra_args, &score);  // ASSERT needs a void function
  return score;
}

}  // namespace plywood::testing
