// One run by several paths (docs/reproducibility.md, the s65 fifty-fifth pass): the experiment
// file, its run's config.yaml, a sweep's cell, the process pinned to one CPU, two copies at once.
// Each must write the same bytes; only timing.json and complete.json (the build id) may differ.

#include <gtest/gtest.h>
#include <sched.h>

#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::MakeTempDir;
using testing::RunPlywood;
using testing::Slurp;
using testing::SourceRoot;
using testing::WriteFile;

// Every file of a run folder but the two that record the process rather than the run.
std::map<std::string, std::string> RunFiles(const fs::path& run) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(run)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = fs::relative(entry.path(), run).string();
    if (name == "timing.json" || name == "complete.json") continue;
    files[name] = Slurp(entry.path());
  }
  return files;
}

void ExpectSameBytes(const fs::path& expected, const fs::path& actual, const std::string& path) {
  const auto want = RunFiles(expected);
  const auto got = RunFiles(actual);
  ASSERT_FALSE(want.empty()) << expected;
  for (const auto& [name, bytes] : want) {
    const auto it = got.find(name);
    ASSERT_NE(it, got.end()) << path << ": no " << name;
    EXPECT_TRUE(it->second == bytes) << path << ": " << name << " differs from " << expected;
  }
  EXPECT_EQ(got.size(), want.size()) << path << ": other files than " << expected;
}

// 20 s of the default experiment, snapshot and sensor logs on: the run whose files are drawn and
// formatted on threads beside the simulation (render/async_snapshot_writer, sensor_log_stream).
std::string RunArgs(const fs::path& out) {
  return "run " + (SourceRoot() / "experiments/default.yaml").string() +
         " --set duration_s=20 --quiet --out " + out.string();
}

TEST(RunPathsTest, EveryPathToOneRunWritesTheSameBytes) {
  const fs::path dir = MakeTempDir("RunPaths");
  const fs::path base = dir / "base";
  fs::create_directories(dir / "logs");
  const CliResult first = RunPlywood(RunArgs(base), dir);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  ASSERT_TRUE(fs::exists(base / "snapshot.png"));

  // Its config.yaml, run again from another current folder.
  fs::create_directories(dir / "elsewhere");
  const CliResult rerun = RunPlywood(
      "run " + (base / "config.yaml").string() + " --quiet --out ../rerun", dir, dir / "elsewhere");
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  ExpectSameBytes(base, dir / "rerun", "config.yaml re-run");

  // Pinned to one CPU: the threads beside the simulation take turns with it.
  cpu_set_t all;
  ASSERT_EQ(sched_getaffinity(0, sizeof all, &all), 0);
  cpu_set_t one;
  CPU_ZERO(&one);
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
    if (CPU_ISSET(cpu, &all)) {
      CPU_SET(cpu, &one);
      break;
    }
  }
  ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
  const CliResult pinned = RunPlywood(RunArgs(dir / "pinned"), dir);
  ASSERT_EQ(sched_setaffinity(0, sizeof all, &all), 0);
  ASSERT_EQ(pinned.exit_code, 0) << pinned.err;
  ExpectSameBytes(base, dir / "pinned", "one CPU");

  // Two copies at once, into two folders.
  fs::create_directories(dir / "a");
  fs::create_directories(dir / "b");
  CliResult a, b;
  std::thread other([&] { a = RunPlywood(RunArgs(dir / "a" / "run"), dir / "a"); });
  b = RunPlywood(RunArgs(dir / "b" / "run"), dir / "b");
  other.join();
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  ExpectSameBytes(base, dir / "a" / "run", "first of two at once");
  ExpectSameBytes(base, dir / "b" / "run", "second of two at once");

  // The same cell of a sweep, two jobs at a time beside a cell of another seed.
  const fs::path sweep = WriteFile(
      dir / "cells.yaml", "experiment: " + (SourceRoot() / "experiments/default.yaml").string() +
                              "\nseeds: [1, 2]\nset:\n  duration_s: [20]\n");
  const CliResult swept = RunPlywood(
      "sweep " + sweep.string() + " --jobs 2 --quiet --out " + (dir / "sweep").string(), dir);
  ASSERT_EQ(swept.exit_code, 0) << swept.err;
  std::vector<fs::path> seed_one;
  for (const auto& run : fs::directory_iterator(dir / "sweep" / "runs")) {
    if (!run.is_directory() || run.path().filename() == ".partial") continue;
    if (Slurp(run.path() / "config.yaml").find("\nseed: 1\n") != std::string::npos) {
      seed_one.push_back(run.path());
    }
  }
  ASSERT_EQ(seed_one.size(), 1u);
  ExpectSameBytes(base, seed_one.front(), "sweep cell");
}

}  // namespace
}  // namespace plywood
