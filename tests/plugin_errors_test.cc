// Bad plug-in input ends `plywood run` with one line naming the experiment file and the field,
// and exit code 2: a missing file, a file that is not a shared library, a library without the
// entry point or built for another Plywood, an unknown algorithm name (the message lists the
// built-in and the registered ones), and an option a plug-in's factory does not read or rejects.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::MakeTempDir;
using testing::RunPlywood;
using testing::SourceRoot;
using testing::WriteFile;

class PluginErrorsTest : public ::testing::Test {
 protected:
  // Runs the example experiment with `overrides` (each a --set) and expects exit code 2 with one
  // line that starts with "plywood: <experiment>: " and contains every string in `must_contain`.
  void ExpectOneLineError(const std::vector<std::string>& overrides,
                          const std::vector<std::string>& must_contain) {
    const fs::path dir =
        MakeTempDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    const fs::path experiment = SourceRoot() / "examples/out_of_tree/experiment.yaml";
    std::string args = "run " + experiment.string() + " --quiet --out " + (dir / "out").string();
    for (const std::string& o : overrides) args += " --set '" + o + "'";
    const testing::CliResult result = RunPlywood(args, dir);
    EXPECT_EQ(result.exit_code, 2) << result.err;
    ASSERT_FALSE(result.err.empty());
    EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << "not one line: " << result.err;
    EXPECT_EQ(result.err.rfind("plywood: " + experiment.string() + ": ", 0), 0u) << result.err;
    for (const std::string& text : must_contain) {
      EXPECT_NE(result.err.find(text), std::string::npos)
          << "expected '" << text << "' in: " << result.err;
    }
    EXPECT_FALSE(fs::exists(dir / "out" / "metrics.json"));
  }

  const std::string plugin_ = fs::path(PLYWOOD_EXAMPLE_PLUGIN).lexically_normal().string();
  const std::string with_plugin_ = "plugins=[" + plugin_ + "]";
};

TEST_F(PluginErrorsTest, MissingFile) {
  ExpectOneLineError({"plugins=[no/such/libplugin.so]"},
                     {"plugins[0]: no such file: no/such/libplugin.so"});
}

TEST_F(PluginErrorsTest, FileThatIsNotASharedLibrary) {
  const fs::path text = WriteFile(MakeTempDir("not_a_library") / "libfake.so", "not ELF\n");
  ExpectOneLineError({"plugins=[" + text.string() + "]"},
                     {"plugins[0]: " + text.string(), "cannot load it as a shared library"});
}

TEST_F(PluginErrorsTest, LibraryWithoutEntryPoint) {
  ExpectOneLineError({std::string("plugins=[") + PLYWOOD_NO_ENTRY_PLUGIN + "]"},
                     {std::string("plugins[0]: ") + PLYWOOD_NO_ENTRY_PLUGIN,
                      "no plywood_register_plugin entry point", "PLYWOOD_PLUGIN"});
}

TEST_F(PluginErrorsTest, LibraryBuiltForAnotherPlywood) {
  ExpectOneLineError({std::string("plugins=[") + PLYWOOD_WRONG_ABI_PLUGIN + "]"},
                     {std::string("plugins[0]: ") + PLYWOOD_WRONG_ABI_PLUGIN,
                      "built for plywood 0.0.1, gcc 4.8.5", "rebuild the plug-in"});
}

TEST_F(PluginErrorsTest, PluginsMustBeAList) {
  ExpectOneLineError({"plugins=" + plugin_}, {"plugins: expected a list"});
}

TEST_F(PluginErrorsTest, UnknownExtractorListsBuiltInAndRegisteredNames) {
  ExpectOneLineError({with_plugin_, "lines.extractors=[split_and_merge, lab_endpoint_fitt]"},
                     {"lines.extractors: unknown extractor 'lab_endpoint_fitt'", "split_and_merge",
                      "hough", "lab_endpoint_fit)"});
}

TEST_F(PluginErrorsTest, UnknownEstimatorListsBuiltInAndRegisteredNames) {
  ExpectOneLineError({with_plugin_, "odometry.lab_complementaryy={}"},
                     {"odometry.lab_complementaryy: unknown key", "ekf", "lab_complementary,"});
}

TEST_F(PluginErrorsTest, UnknownControllerListsBuiltInTypes) {
  ExpectOneLineError({with_plugin_, "controller.type=lab_controller"},
                     {"controller.type: unknown controller 'lab_controller'", "sonar_explorer"});
}

TEST_F(PluginErrorsTest, RegisteredNameWithoutThePluginIsUnknown) {
  ExpectOneLineError({"plugins=[]"}, {"odometry.lab_complementary: unknown key"});
}

TEST_F(PluginErrorsTest, OptionTheFactoryDoesNotRead) {
  ExpectOneLineError(
      {with_plugin_, "odometry.lab_complementary.gyro_wieght=0.5"},
      {"odometry.lab_complementary.gyro_wieght: unknown key", "(known here: gyro_weight)"});
  ExpectOneLineError({with_plugin_, "lines.lab_endpoint_fit.min_pionts=3"},
                     {"lines.lab_endpoint_fit.min_pionts: unknown key", "min_points"});
}

TEST_F(PluginErrorsTest, OptionTheFactoryRejects) {
  ExpectOneLineError({with_plugin_, "odometry.lab_complementary.gyro_weight=1.5"},
                     {"odometry.lab_complementary.gyro_weight: expected a number in [0, 1], got "
                      "'1.5'"});
  ExpectOneLineError({with_plugin_, "lines.lab_endpoint_fit.min_points=six"},
                     {"lines.lab_endpoint_fit.min_points: expected a whole number, got 'six'"});
  ExpectOneLineError({with_plugin_, "lines.lab_endpoint_fit.min_points=[6]"},
                     {"lines.lab_endpoint_fit.min_points: expected a number, true/false or text"});
}

TEST_F(PluginErrorsTest, EstimatorThatNeedsTheGyroWithoutIt) {
  ExpectOneLineError(
      {with_plugin_, "sensors.gyro.enabled=false", "odometry={encoder: {}, lab_complementary: {}}"},
      {"odometry.lab_complementary: this estimator needs sensors.gyro"});
}

}  // namespace
}  // namespace plywood
