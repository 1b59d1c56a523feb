#pragma once

namespace plywood::apps {

// The smallest stack limit (`ulimit -s`) plywood runs in: below it Mesa's shader compiler
// (snapshots, `--pictures`, `bench`) overflowed the stack, SIGSEGV without a line. Every command
// was tried from 128 kB up; plywood's own code needs far less since its large buffers left the
// stack (s65 fifty-fourth pass).
inline constexpr unsigned long kMinimumStackKb = 128;

// @throws std::invalid_argument "ulimit -s: the stack limit is N kB; ..." below the minimum.
void RequireAStackLimitPlywoodRunsIn();

}  // namespace plywood::apps
