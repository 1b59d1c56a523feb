// Sonar-net weight files (perception/sonar_map/sonar_net.h): a file that loads writes text that
// loads back to the same text (Save(Load(f)) is the identity on what Save writes).
#include "fuzz/fuzz_support.h"
#include "fuzz/fuzz_target.h"
#include "perception/sonar_map/sonar_net.h"

namespace plywood::fuzz {
namespace {

void FuzzSonarNetWeights(std::span<const std::uint8_t> data) {
  const std::string source = "fuzz_weights.txt";
  std::string written;
  try {
    written = perception::SonarNet::FromText(AsText(data), source).ToText();
  } catch (const std::runtime_error& e) {
    RequireCleanError(e, source);
    return;
  }
  try {
    const std::string again = perception::SonarNet::FromText(written, "written.txt").ToText();
    Require(again == written, "the written weights read back differently");
  } catch (const std::runtime_error& e) {
    Require(false, std::string("the written weights do not load: ") + e.what());
  }
}

}  // namespace
}  // namespace plywood::fuzz

PLYWOOD_FUZZ_TARGET("sonar_net_weights", plywood::fuzz::FuzzSonarNetWeights)
