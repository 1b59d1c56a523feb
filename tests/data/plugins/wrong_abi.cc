// A plug-in that claims another Plywood build: the host must refuse it before calling its entry
// point (tests/plugin_errors_test.cc).
#include <cstdlib>

namespace plywood::perception {
struct AlgorithmRegistry;
}

extern "C" __attribute__((visibility("default"))) const char* plywood_plugin_abi() {
  return "plywood 0.0.1, gcc 4.8.5, libstdc++ cxx11 abi 0";
}

extern "C" __attribute__((visibility("default"))) void plywood_register_plugin(
    plywood::perception::AlgorithmRegistry*) {
  std::abort();  // never called: the ABI check comes first
}
