#pragma once

#include <filesystem>
#include <string>

namespace plywood::sim {

// The whole file as bytes; empty when it does not exist or cannot be read (callers that must tell
// the two apart check the file first).
std::string ReadTextFile(const std::filesystem::path& path);

// The temporary name WriteTextFile writes `path` under before renaming it into place:
// "PATH.partial-PID" (the pid keeps two processes writing one file, Slurm tasks or a sweep and
// --collect, apart).
std::filesystem::path StagedTextFilePath(const std::filesystem::path& path);

// Writes `text` under a temporary name beside `path` and renames it into place, so a reader (a
// resumed sweep, `--collect`, a person) never sees half a file.
// @throws std::runtime_error naming the file when it cannot be written.
void WriteTextFile(const std::filesystem::path& path, const std::string& text);

}  // namespace plywood::sim
