#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

namespace plywood::sim {

// The whole file as bytes; empty when it does not exist or cannot be read (callers that must tell
// the two apart check the file first).
std::string ReadTextFile(const std::filesystem::path& path);

// The temporary name WriteTextFile writes `path` under before renaming it into place:
// "PATH.partial-PID" (the pid keeps two processes writing one file, Slurm tasks or a sweep and
// --collect, apart); for a name within NAME_MAX whose staged name would not be, the name's head
// with that suffix, so the file system takes it.
std::filesystem::path StagedTextFilePath(const std::filesystem::path& path);

// The PID in `name` when it is the staged copy of `of` that StagedTextFilePath names
// ("OF.partial-PID", PID up to 9 digits), else nullopt: what a kill left behind is told from a
// user's own file by this, and a stale copy from a live writer's by the PID.
std::optional<long> StagedCopyPid(std::string_view name, std::string_view of);

// True when `path` is there and neither a file nor a folder: a device or a pipe (/dev/null,
// /dev/full, /dev/stdout into `| jq`, whose path resolves to "pipe:[N]", no path at all), which
// an output is written to as it is: renaming a staged copy over it would replace it.
bool IsADeviceOrAPipe(const std::filesystem::path& path);

// Writes `path` by `write(target)`: into `path` itself when it is there and not a regular file (a
// device or a pipe: a rename would replace it), else into StagedTextFilePath(path), which is
// removed when `write` throws (its exception passes on) and renamed into place after, so a failed
// write never leaves a cut file where a whole one is expected. Returns the rename's error (empty
// when it succeeded or nothing was renamed); the caller names it in its own words.
std::error_code WriteStagedThenRename(
    const std::filesystem::path& path,
    const std::function<void(const std::filesystem::path& target)>& write);

// Writes `text` under a temporary name beside `path` and renames it into place, so a reader (a
// resumed sweep, `--collect`, a person) never sees half a file.
// @throws std::runtime_error naming the file when it cannot be written.
void WriteTextFile(const std::filesystem::path& path, const std::string& text);

}  // namespace plywood::sim
