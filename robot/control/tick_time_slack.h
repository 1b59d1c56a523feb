#pragma once

namespace plywood::robot {

// Time comparisons of the controllers allow this much: tick times accumulate round-off, so an
// interval that should end on a tick may end 1e-15 s after it.
inline constexpr double kTickTimeSlackS = 1e-9;

}  // namespace plywood::robot
