#include "sim/runner/build_id.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "sim/runner/run_directory.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim {
namespace {

namespace fs = std::filesystem;

// What binutils' readelf says the build ID of `program` is ("" when readelf is missing or finds
// none).
std::string ReadelfBuildId(const fs::path& program) {
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(
      popen(("readelf -n '" + program.string() + "' 2>/dev/null").c_str(), "r"), pclose);
  std::string text;
  std::array<char, 4096> buffer{};
  while (pipe && std::fgets(buffer.data(), buffer.size(), pipe.get())) text += buffer.data();
  const std::string key = "Build ID: ";
  const std::size_t at = text.find(key);
  if (at == std::string::npos) return "";
  const std::size_t from = at + key.size();
  return text.substr(from, text.find('\n', from) - from);
}

TEST(BuildIdTest, IsTheBuildIdTheLinkerWroteIntoTheProgram) {
  if (std::system("command -v readelf >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "readelf (binutils) is not installed";
  }
  const std::string expected = ReadelfBuildId(fs::read_symlink("/proc/self/exe"));
  ASSERT_FALSE(expected.empty()) << "the test program has no build ID note";
  EXPECT_EQ(ProgramBuildId(), expected);
}

TEST(BuildIdTest, AFinishedRunRecordsTheBuildThatMadeIt) {
  const fs::path dir = testing::MakeTempDir("build_id_run");
  testing::WriteFile(dir / "metrics.json", "{}\n");
  EXPECT_EQ(RunBuildId(dir), "");  // no completion record yet
  WriteCompletionRecord(dir);
  EXPECT_EQ(RunBuildId(dir), ProgramBuildId());
  EXPECT_FALSE(RunBuildId(dir).empty());
}

}  // namespace
}  // namespace plywood::sim
