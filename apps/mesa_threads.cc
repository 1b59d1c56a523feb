#include "apps/mesa_threads.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdlib>

namespace plywood::apps {

void KeepMesaFromWaitingOnThreadsItCannotStart() {
  rlimit limit{};
  if (getrlimit(RLIMIT_NPROC, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return;
  if (limit.rlim_cur >= kFewProcesses || geteuid() == 0) return;  // root is not held to it
  setenv("LP_NUM_THREADS", "0", /*overwrite=*/0);
}

}  // namespace plywood::apps
