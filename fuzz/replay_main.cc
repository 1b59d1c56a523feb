// Replays committed fuzz inputs through a harness without fuzzing: the regression test of every
// corpus (seeds and each crash input ever found). Usage: fuzz_replay TARGET FOLDER...
// Fails when a folder is missing or empty, the target is unknown, or any input breaks a promise.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz/fuzz_support.h"
#include "fuzz/fuzz_target.h"

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  if (argc < 3) {
    std::fprintf(stderr, "usage: fuzz_replay TARGET FOLDER...\n");
    return 2;
  }
  const plywood::fuzz::FuzzTarget target = plywood::fuzz::FindFuzzTarget(argv[1]);
  if (target == nullptr) {
    std::fprintf(stderr, "fuzz_replay: no fuzz target named %s\n", argv[1]);
    return 2;
  }
  std::vector<fs::path> inputs;
  for (int i = 2; i < argc; ++i) {
    std::error_code error;
    std::vector<fs::path> found;
    for (const auto& entry : fs::directory_iterator(argv[i], error)) {
      if (entry.is_regular_file() && entry.path().filename() != "README.md") {
        found.push_back(entry.path());
      }
    }
    if (error || found.empty()) {
      std::fprintf(stderr, "fuzz_replay: %s: no inputs\n", argv[i]);
      return 2;
    }
    inputs.insert(inputs.end(), found.begin(), found.end());
  }
  std::sort(inputs.begin(), inputs.end());
  for (const fs::path& input : inputs) {
    std::ifstream file(input, std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(file),
                                          std::istreambuf_iterator<char>()};
    plywood::fuzz::SetCurrentInput(input.string());
    try {
      target(bytes);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "fuzz_replay: %s: uncaught exception: %s\n", input.c_str(), e.what());
      return 1;
    }
  }
  std::printf("fuzz_replay %s: %zu inputs replayed\n", argv[1], inputs.size());
  return 0;
}
