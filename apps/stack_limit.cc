#include "apps/stack_limit.h"

#include <sys/resource.h>

#include <stdexcept>
#include <string>

namespace plywood::apps {

void RequireAStackLimitPlywoodRunsIn() {
  rlimit limit{};
  if (getrlimit(RLIMIT_STACK, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return;
  const unsigned long kb = limit.rlim_cur / 1024;
  if (kb >= kMinimumStackKb) return;
  throw std::invalid_argument("ulimit -s: the stack limit is " + std::to_string(kb) +
                              " kB; plywood needs at least " + std::to_string(kMinimumStackKb) +
                              " kB (Mesa compiles its shaders deep in the stack): raise it, e.g. "
                              "ulimit -s 8192, the usual");
}

}  // namespace plywood::apps
