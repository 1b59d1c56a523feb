#pragma once

#include <cstdint>
#include <exception>
#include <filesystem>
#include <span>
#include <string>

namespace plywood::fuzz {

// The bytes as text (embedded NULs kept).
std::string AsText(std::span<const std::uint8_t> data);

// Writes `data` to the file `name` in this process's scratch folder (created under TMPDIR on first
// use, removed at exit) and returns its path. Readers that take a path get the fuzzed bytes this
// way.
std::filesystem::path WriteScratchFile(const std::string& name, std::span<const std::uint8_t> data);
std::filesystem::path ScratchFolder();

// Aborts with `what` (and the input being replayed, if any) when `condition` is false: a broken
// promise of a parser, reported by libFuzzer as a crash and failing the replay test.
void Require(bool condition, const std::string& what);

// A parse error as the apps print it: one non-empty line that names `source` (the file or the
// name the parser was given), as every reader promises.
void RequireCleanError(const std::exception& error, const std::string& source);

// The replayer names the input it runs, so a failed Require says which file broke.
void SetCurrentInput(const std::string& name);

}  // namespace plywood::fuzz
