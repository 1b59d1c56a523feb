#include "sim/runner/scratch_folder.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace plywood::sim {
namespace {

namespace fs = std::filesystem;

// The PID of a process that has ended (a child that exits at once, reaped).
pid_t EndedPid() {
  const pid_t pid = fork();
  if (pid == 0) _exit(0);
  waitpid(pid, nullptr, 0);
  return pid;
}

// A command killed by SIGKILL leaves its scratch folder (s65: `plywood bench`'s default run under
// TMPDIR). Only folders of the prefix and an ended PID go; live PIDs, other names and files stay.
TEST(ScratchFolderTest, RemovesTheFoldersOfEndedProcessesOnly) {
  const fs::path root =
      fs::temp_directory_path() / ("plywood-ScratchFolderTest-" + std::to_string(getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const std::string ended = std::to_string(EndedPid());
  const auto folder = [&](const std::string& name) {
    fs::create_directories(root / name / "runs");
    std::ofstream(root / name / "runs" / "metrics.json") << "{}\n";
    return root / name;
  };
  const fs::path killed = folder("plywood-x-" + ended);
  const fs::path parent = folder("plywood-x-" + std::to_string(getppid()));
  const fs::path self = folder("plywood-x-" + std::to_string(getpid()));
  const fs::path other_prefix = folder("plywood-y-" + ended);
  const fs::path not_a_pid = folder("plywood-x-" + ended + "a");
  const fs::path negative = folder("plywood-x--" + ended);
  std::ofstream(root / ("plywood-x-" + std::to_string(EndedPid()))) << "a file, not a folder\n";

  RemoveScratchOfEndedProcesses(root, "plywood-x-");

  EXPECT_FALSE(fs::exists(killed));
  for (const fs::path& kept : {parent, self, other_prefix, not_a_pid, negative}) {
    EXPECT_TRUE(fs::exists(kept / "runs" / "metrics.json")) << kept;
  }
  int files = 0;
  for (const auto& entry : fs::directory_iterator(root)) files += entry.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 1);
  // A root that does not exist is no error.
  RemoveScratchOfEndedProcesses(root / "nowhere", "plywood-x-");
  fs::remove_all(root);
}

}  // namespace
}  // namespace plywood::sim
