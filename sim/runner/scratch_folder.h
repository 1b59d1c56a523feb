#pragma once

#include <filesystem>
#include <string_view>

namespace plywood::sim {

// The folder `train sonar-net` and `bench` write their scratch files in: $TMPDIR, or /tmp when it
// is unset or empty (POSIX's rule). std::filesystem::temp_directory_path took an empty TMPDIR as a
// folder named "" and a missing one as "plywood: No such file or directory", naming neither the
// variable nor the folder; one plywood may not write in (/sys) failed as exit 1.
// @throws std::invalid_argument naming TMPDIR when it is not a folder a file can be made in.
std::filesystem::path ScratchFolderRoot();

// Removes the folders root/PREFIX<pid> whose process has ended (kill(pid, 0) fails with ESRCH) and
// that this user owns. A command killed by SIGKILL cannot remove its own scratch folder (`bench`'s
// default run, `train`'s rooms), so each such kill left one behind for good. A live PID (this
// process, another command at work, or a reused PID) and other users' folders are left alone;
// errors are ignored (the folder stays, nothing else changes).
void RemoveScratchOfEndedProcesses(const std::filesystem::path& root, std::string_view prefix);

}  // namespace plywood::sim
