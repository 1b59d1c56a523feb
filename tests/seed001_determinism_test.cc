// Seed 001 end to end: the same experiment and seed give the same map and metrics, byte for byte
// in cognitive_map.json, occupancy_grid.png and metrics.json (issue 5's acceptance: same seed ->
// identical map and metrics).

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "plywood_paths.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::MakeTempDir;
using testing::SourceRoot;

using testing::Slurp;

// Runs `plywood run` on the shipped layout-4 experiment, cut short, into dir/name.
int RunShort(const fs::path& dir, const std::string& name, int seed) {
  const fs::path binary = fs::path(PLYWOOD_BINARY_DIR) / "apps" / "plywood";
  const fs::path experiment = SourceRoot() / "experiments" / "seed001_room_4.yaml";
  const std::string command = binary.string() + " run " + experiment.string() + " --out " +
                              (dir / name).string() + " --seed " + std::to_string(seed) +
                              " --set duration_s=30 --quiet >" + (dir / (name + ".log")).string() +
                              " 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(Seed001DeterminismTest, SameSeedGivesIdenticalMapAndMetricsBytes) {
  const fs::path dir = MakeTempDir("seed001_determinism");
  ASSERT_EQ(RunShort(dir, "a", 1), 0) << Slurp(dir / "a.log");
  ASSERT_EQ(RunShort(dir, "b", 1), 0) << Slurp(dir / "b.log");
  ASSERT_EQ(RunShort(dir, "c", 2), 0) << Slurp(dir / "c.log");
  const std::string a = Slurp(dir / "a" / "metrics.json");
  const std::string b = Slurp(dir / "b" / "metrics.json");
  const std::string c = Slurp(dir / "c" / "metrics.json");
  ASSERT_NE(a.find("\"occupancy\""), std::string::npos) << a;
  ASSERT_NE(a.find("\"grid_error\""), std::string::npos) << a;
  EXPECT_EQ(a, b);
  // The noise really depends on the seed, so the equality above is not vacuous.
  EXPECT_NE(a, c);
  for (const char* file : {"cognitive_map.json", "occupancy_grid.png"}) {
    SCOPED_TRACE(file);
    const std::string map_a = Slurp(dir / "a" / file);
    ASSERT_FALSE(map_a.empty());
    EXPECT_EQ(map_a, Slurp(dir / "b" / file));
    EXPECT_NE(map_a, Slurp(dir / "c" / file));
  }
  // The explorer's decisions are written beside the map, the same for the same seed (30 s may end
  // before any decision differs, so seed 2's is not compared).
  const std::string log_a = Slurp(dir / "a" / "exploration_log.csv");
  EXPECT_EQ(log_a.rfind("time_s,event,detail,x_m,y_m\n", 0), 0u) << log_a;
  EXPECT_EQ(log_a, Slurp(dir / "b" / "exploration_log.csv"));
}

}  // namespace
}  // namespace plywood
