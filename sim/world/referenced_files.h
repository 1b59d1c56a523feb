#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace plywood::sim {

// Checks the files an MJCF text names (file=, fileup=, ... of <include>, <mesh>, <texture>,
// <hfield>, <skin>), and those the included files name, before MuJoCo opens them: MuJoCo reads a
// FIFO or a device named there for ever (a world whose mesh was a FIFO hung `plywood run`).
// Relative names are tried against `dir` (the main file's folder), the naming file's folder and
// every meshdir / texturedir / assetdir given; a name that is nowhere is left to MuJoCo's error.
// @throws std::runtime_error "<path>: not a regular file (a folder or a device?), named by
// <attribute>= in <file>" for the first such name.
void RequireRegularReferencedFiles(const std::string& mjcf, const std::filesystem::path& dir,
                                   const std::string& source_name);

// The files an MJCF text names, found as RequireRegularReferencedFiles looks for them (included
// files' own names too), each once, canonical, in the order first named: what a world is made of
// besides its own text. A name found nowhere is left out.
// @throws std::runtime_error as RequireRegularReferencedFiles does.
std::vector<std::filesystem::path> ReferencedFiles(const std::string& mjcf,
                                                   const std::filesystem::path& dir,
                                                   const std::string& source_name);

}  // namespace plywood::sim
