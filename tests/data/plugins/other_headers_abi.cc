// A plug-in built against the headers of another commit of this Plywood version, by this compiler:
// its ABI string is what PLYWOOD_PLUGIN_ABI was before the headers' hash joined it, the string
// every plug-in built against an earlier 0.1.0 claims. The host must refuse it before calling its
// entry point (tests/plugin_errors_test.cc): its structs may have another layout.
#include <cstdlib>

#include "perception/plugins/plugin.h"

extern "C" __attribute__((visibility("default"))) const char* plywood_plugin_abi() {
  return "plywood " PLYWOOD_VERSION ", " PLYWOOD_PLUGIN_COMPILER
         ", libstdc++ cxx11 abi " PLYWOOD_PLUGIN_STRINGIFY(_GLIBCXX_USE_CXX11_ABI);
}

extern "C" __attribute__((visibility("default"))) void plywood_register_plugin(
    plywood::perception::AlgorithmRegistry*) {
  std::abort();  // never called: the ABI check comes first
}
