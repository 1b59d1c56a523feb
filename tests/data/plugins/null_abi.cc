// A plug-in whose ABI function returns a null pointer instead of the build it was made for: the
// host must refuse it in one line before calling its entry point (tests/plugin_errors_test.cc).
#include <cstdlib>

namespace plywood::perception {
struct AlgorithmRegistry;
}

extern "C" __attribute__((visibility("default"))) const char* plywood_plugin_abi() {
  return nullptr;
}

extern "C" __attribute__((visibility("default"))) void plywood_register_plugin(
    plywood::perception::AlgorithmRegistry*) {
  std::abort();  // never called: the ABI check comes first
}
