// Bad plug-in input ends `plywood run` with one line naming the experiment file and the field,
// and exit code 2: a missing file, a file that is not a shared library, a library without the
// entry point or built for another Plywood, an unknown algorithm name (the message lists the
// built-in and the registered ones), and an option a plug-in's factory does not read or rejects.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"
#include "tests/support/metrics_json_test_support.h"
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

// audit s40: a plywood_plugin_abi() that returns a null pointer ended the run with
// `plywood: error: basic_string: construction from null is not valid`, exit 1, naming nothing.
TEST_F(PluginErrorsTest, LibraryWhoseAbiFunctionReturnsNullIsRefused) {
  ExpectOneLineError({std::string("plugins=[") + PLYWOOD_NULL_ABI_PLUGIN + "]"},
                     {std::string("plugins[0]: ") + PLYWOOD_NULL_ABI_PLUGIN,
                      "plywood_plugin_abi() returns a null pointer", "PLYWOOD_PLUGIN"});
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

// An experiment in the hall whose lines: section runs split_and_merge beside a misbehaving
// plug-in extractor (tests/data/plugins/misbehaving_algorithms.cc).
testing::CliResult RunMisbehavingExtractor(const std::string& extractor, const fs::path& dir) {
  const fs::path experiment =
      WriteFile(dir / "experiment.yaml",
                "name: misbehaving\n"
                "duration_s: 2\n"
                "world: " +
                    (SourceRoot() / "worlds/hall.xml").string() +
                    "\n"
                    "robot: {model: p3dx, spawn: {x_m: 0, y_m: 0, theta_deg: 0}}\n"
                    "controller: {type: square_path}\n"
                    "sensors: {laser: {rate_hz: 5}, encoders: {}}\n"
                    "plugins: [" +
                    std::string(PLYWOOD_MISBEHAVING_PLUGIN) +
                    "]\n"
                    "lines: {extractors: [split_and_merge, " +
                    extractor +
                    "]}\n"
                    "output: {snapshot: false}\n");
  return RunPlywood("run " + experiment.string() + " --quiet --out " + (dir / "out").string(), dir);
}

// An algorithm that throws something that is not a std::exception (here an int) aborted plywood
// ("terminate called after throwing an instance of 'int'", SIGABRT): now one line, exit 1.
TEST(PluginMisbehaviourTest, AnAlgorithmThrowingANonStdExceptionEndsTheRunWithOneLine) {
  const fs::path dir = MakeTempDir("plugin_throws_int");
  const testing::CliResult result = RunMisbehavingExtractor("throwing_lines", dir);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_EQ(result.err,
            "plywood: error: an exception that is not a std::exception ended the run (thrown by a "
            "plug-in's algorithm?)\n");
  EXPECT_FALSE(fs::exists(dir / "out" / "metrics.json"));
}

// Segments of NaN are false lines: they were scored as found (precision 1, recall 1/3).
TEST(PluginMisbehaviourTest, NanSegmentsAreScoredAsFalseLines) {
  const fs::path dir = MakeTempDir("plugin_nan_lines");
  const testing::CliResult result = RunMisbehavingExtractor("nan_lines", dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::map<std::string, std::string> metrics =
      testing::FlattenMetricsJson(testing::Slurp(dir / "out" / "metrics.json"));
  EXPECT_EQ(metrics.at("lines.nan_lines.precision"), "0");
  EXPECT_EQ(metrics.at("lines.nan_lines.recall"), "0");
  EXPECT_EQ(metrics.at("lines.nan_lines.lines_per_scan"), "1");
  EXPECT_NE(metrics.at("lines.split_and_merge.recall"), "0");
}

}  // namespace
}  // namespace plywood
