// `plywood worlds generate` end to end: it writes the worlds, their sidecars and index.csv, the
// same bytes for the same seed, and bad input gives one line naming the field and exit code 2.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::MakeTempDir;
using testing::RunPlywood;
using testing::Slurp;

TEST(WorldsCliTest, GeneratesTheSameBytesForTheSameSeed) {
  const fs::path dir = MakeTempDir("worlds_cli_generate");
  for (const char* out : {"a", "b"}) {
    const auto result =
        RunPlywood("worlds generate seed001 --count 2 --seed 4 --out " + (dir / out).string(), dir);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.out.find("2 seed001 worlds (seed 4)"), std::string::npos) << result.out;
  }
  for (const char* file : {"seed001_s4_00000.xml", "seed001_s4_00001.json", "index.csv"}) {
    const std::string a = Slurp(dir / "a" / file);
    EXPECT_FALSE(a.empty()) << file;
    EXPECT_EQ(a, Slurp(dir / "b" / file)) << file;
  }
  const auto list = RunPlywood("worlds list", dir);
  EXPECT_EQ(list.exit_code, 0);
  EXPECT_NE(list.out.find("office"), std::string::npos);
}

TEST(WorldsCliTest, BadInputNamesTheField) {
  const fs::path dir = MakeTempDir("worlds_cli_bad");
  testing::WriteFile(dir / "a_file", "x");
  const std::string out = " --out " + (dir / "out").string();
  const std::pair<std::string, std::string> cases[] = {
      {"worlds generate castle --count 1 --seed 1" + out, "FAMILY: unknown world family 'castle'"},
      {"worlds generate room --count 0 --seed 1" + out, "--count"},
      {"worlds generate room --count -4 --seed 1" + out, "--count"},
      {"worlds generate room --count 100001 --seed 1" + out, "--count"},
      {"worlds generate room --count 2.5 --seed 1" + out, "--count"},
      {"worlds generate room --seed 1" + out, "--count"},
      {"worlds generate room --count 1 --seed -1" + out, "--seed"},
      {"worlds generate room --count 1 --seed one" + out, "--seed"},
      {"worlds generate room --count 1 --seed 1 --out " + (dir / "a_file" / "x").string(),
       "--out: cannot create directory"},
      {"worlds generate room --count 1 --seed 1 --out " + (dir / "a_file").string(),
       "--out: cannot create directory"},
      {"worlds generate room --count 1 --seed 1", "--out"},
      {"worlds generate room --count 1 --seed 1 --colour red" + out, "--colour"},
      {"worlds make room", "subcommand"},
  };
  for (const auto& [args, expected] : cases) {
    SCOPED_TRACE(args);
    const auto result = RunPlywood(args, dir);
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(result.err.rfind("plywood: ", 0), 0u) << result.err;
    EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
    EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << "not one line: " << result.err;
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace plywood

namespace plywood {
namespace {

// Whole-number flags are read in decimal, as an experiment's numbers are: CLI11's own conversion
// (strtoll base 0) made `--count 010` 8 worlds and took `--count 0x2` as 2 (seventh pass).
TEST(WorldsCliTest, WholeNumberFlagsAreReadInDecimal) {
  namespace fs = std::filesystem;
  const fs::path dir = testing::MakeTempDir("worlds_cli_decimal");
  ASSERT_EQ(
      testing::RunPlywood(
          "worlds generate room --count 010 --seed 2 --quiet --out " + (dir / "a").string(), dir)
          .exit_code,
      0);
  int xml = 0;
  for (const auto& e : fs::directory_iterator(dir / "a")) xml += e.path().extension() == ".xml";
  EXPECT_EQ(xml, 10);
  for (const std::string& args : std::vector<std::string>{
           "worlds generate room --count 0x2 --seed 2 --out " + (dir / "b").string(),
           "train sonar-net --seed 0x10 --out " + (dir / "n.txt").string(),
           "train sonar-net --epochs 0b1 --out " + (dir / "n.txt").string(),
           "sweep s.yaml --jobs 0x2", "bench --repeats 0x1"}) {
    SCOPED_TRACE(args);
    const auto r = testing::RunPlywood(args, dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("plywood: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("expected a whole number in decimal digits"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "b"));
  EXPECT_FALSE(fs::exists(dir / "n.txt"));
}

TEST(WorldsCliTest, ASecondGenerationReplacesTheFirstAndNothingElse) {
  namespace fs = std::filesystem;
  const fs::path dir = testing::MakeTempDir("worlds_cli_again");
  const std::string out = (dir / "out").string();
  ASSERT_EQ(
      testing::RunPlywood("worlds generate room --count 3 --seed 2 --out " + out, dir).exit_code,
      0);
  ASSERT_EQ(
      testing::RunPlywood("worlds generate clutter --count 1 --seed 2 --out " + out, dir).exit_code,
      0);
  int xml = 0;
  for (const auto& e : fs::directory_iterator(dir / "out")) xml += e.path().extension() == ".xml";
  EXPECT_EQ(xml, 1) << "worlds of the earlier generation were left behind";
  testing::WriteFile(dir / "out" / "notes.txt", "mine\n");
  const auto r = testing::RunPlywood("worlds generate room --count 1 --seed 2 --out " + out, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("notes.txt"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "notes.txt"));
}

}  // namespace
}  // namespace plywood
