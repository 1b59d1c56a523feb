#pragma once

#include <filesystem>

namespace plywood::sim {

// The folder `train sonar-net` and `bench` write their scratch files in: $TMPDIR, or /tmp when it
// is unset or empty (POSIX's rule). std::filesystem::temp_directory_path took an empty TMPDIR as a
// folder named "" and a missing one as "plywood: No such file or directory", naming neither the
// variable nor the folder; one plywood may not write in (/sys) failed as exit 1.
// @throws std::invalid_argument naming TMPDIR when it is not a folder a file can be made in.
std::filesystem::path ScratchFolderRoot();

}  // namespace plywood::sim
