#pragma once

#include <filesystem>

namespace plywood::sim {

// The folder an experiment or sweep file's relative paths resolve against: the folder of the file
// itself, found by following the symbolic links its name goes through (the last component only,
// hop by hop), as an absolute path. A file reached through a link in another folder
// (`ln -s ../lab/e.yaml mine.yaml`) means what its author wrote beside it: the same file gives the
// same run whichever name it is given by. The folders above are taken as named (lexically), as
// everywhere else a path is resolved, unless that names another file than the kernel reads (a
// target's ".." climbing out of a folder reached through a link): then the file's real folder.
std::filesystem::path FolderBehindLinks(const std::filesystem::path& file);

}  // namespace plywood::sim
