// Grid images of `plywood score` (eval/score/grid_image.h), PNG or PGM: what loads has as many
// pixels as its size says, each brightness in [0, 1].
#include "eval/score/grid_image.h"
#include "fuzz/fuzz_support.h"
#include "fuzz/fuzz_target.h"

namespace plywood::fuzz {
namespace {

void FuzzScoreGrid(std::span<const std::uint8_t> data) {
  const std::filesystem::path path = WriteScratchFile("grid.fuzz", data);
  try {
    const eval::GridImage image = eval::ReadGridImage(path);
    Require(image.width > 0 && image.height > 0, "an empty image");
    Require(image.brightness.size() ==
                static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height),
            "pixel count and size disagree");
    for (double b : image.brightness) Require(b >= 0.0 && b <= 1.0, "brightness outside [0, 1]");
  } catch (const std::runtime_error& e) {  // sim::ConfigError
    RequireCleanError(e, path.string());
  }
}

}  // namespace
}  // namespace plywood::fuzz

PLYWOOD_FUZZ_TARGET("score_grid", plywood::fuzz::FuzzScoreGrid)
