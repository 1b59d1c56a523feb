#pragma once

#include <numbers>

// Angle constants every layer uses, defined once at the project's top namespace: file-local copies
// clash when a library compiles its sources in unity batches (cmake/plywood.cmake).
namespace plywood {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDegToRad = std::numbers::pi / 180.0;
inline constexpr double kRadToDeg = 180.0 / std::numbers::pi;

}  // namespace plywood
