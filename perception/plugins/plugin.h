#pragma once

// The one header a plug-in includes (docs/plugins.md): a shared library that adds line extractors,
// odometry estimators and controllers to the host's registries. An experiment names it under
// `plugins:`; plywood loads it with dlopen before reading the rest of the experiment and calls
//
//   PLYWOOD_PLUGIN(registry) {
//     registry.line_extractors.Add({"my_extractor", [](const robot::ParameterMap& options) {...}});
//   }
//
// with the host's registry. The host links Plywood's static libraries and so does the plug-in, so
// each has its own copy of every non-inline function and global: everything a plug-in does to the
// host's objects goes through the header-only code below and the algorithms' virtual functions.
// That only works when both were built from the same Plywood headers with the same compiler and
// standard library; the host checks PLYWOOD_PLUGIN_ABI before calling anything else.

#include <string>

#include "perception/lines/line_extractor_registry.h"
#include "perception/plugins/plywood_headers.h"
#include "perception/plugins/plywood_version.h"
#include "robot/control/controller_registry.h"
#include "robot/odometry/odometry_estimator_registry.h"

namespace plywood::perception {

// Everything a plug-in may add to.
struct AlgorithmRegistry {
  LineExtractorRegistry line_extractors;
  robot::OdometryEstimatorRegistry odometry_estimators;
  robot::ControllerRegistry controllers;
};

// The exported symbols PLYWOOD_PLUGIN defines, which the host looks up.
inline constexpr const char* kPluginEntryPoint = "plywood_register_plugin";
inline constexpr const char* kPluginAbiSymbol = "plywood_plugin_abi";

}  // namespace plywood::perception

#define PLYWOOD_PLUGIN_STRINGIFY_(x) #x
#define PLYWOOD_PLUGIN_STRINGIFY(x) PLYWOOD_PLUGIN_STRINGIFY_(x)
#if defined(__clang__)
#define PLYWOOD_PLUGIN_COMPILER "clang " __clang_version__
#elif defined(__GNUC__)
#define PLYWOOD_PLUGIN_COMPILER "gcc " __VERSION__
#else
#define PLYWOOD_PLUGIN_COMPILER "unknown compiler"
#endif
// What host and plug-in must share: Plywood's version, the headers (a hash of every installed
// header: another commit's struct or interface may differ under the same version), the compiler
// and libstdc++'s string ABI.
#define PLYWOOD_PLUGIN_ABI                                                                   \
  "plywood " PLYWOOD_VERSION " (headers " PLYWOOD_HEADERS_HASH "), " PLYWOOD_PLUGIN_COMPILER \
  ", libstdc++ cxx11 abi " PLYWOOD_PLUGIN_STRINGIFY(_GLIBCXX_USE_CXX11_ABI)

// Defines the plug-in's two exported entry points; the braces that follow are the body of the
// registration function, with `registry` the host's AlgorithmRegistry.
#define PLYWOOD_PLUGIN(registry)                                                         \
  extern "C" __attribute__((visibility("default"))) const char* plywood_plugin_abi() {   \
    return PLYWOOD_PLUGIN_ABI;                                                           \
  }                                                                                      \
  static void PlywoodRegisterPlugin(::plywood::perception::AlgorithmRegistry& registry); \
  extern "C" __attribute__((visibility("default"))) void plywood_register_plugin(        \
      ::plywood::perception::AlgorithmRegistry* plywood_host_registry) {                 \
    PlywoodRegisterPlugin(*plywood_host_registry);                                       \
  }                                                                                      \
  static void PlywoodRegisterPlugin(::plywood::perception::AlgorithmRegistry& registry)
