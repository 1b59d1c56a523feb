#pragma once

#include <filesystem>
#include <string>

namespace plywood::sim {

// The GNU build ID of the running program (the linker's hash of its code, `readelf -n`), as hex;
// empty when the program was linked without one. Two runs with the same ID ran the same code, so
// sweeps use it to tell results they can keep from results an earlier build made.
const std::string& ProgramBuildId();

// The build ID recorded in a finished run's completion marker (complete.json's
// "plywood_build_id"); empty when there is none (a run made before builds were recorded).
std::string RunBuildId(const std::filesystem::path& run_dir);

}  // namespace plywood::sim
