#include "apps/owner_umask.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>
#include <string>

namespace plywood::apps {

void RequireAUmaskThatLeavesTheOwnerItsFiles() {
  const mode_t mask = umask(0);  // reading it sets it: put straight back, before any thread starts
  umask(mask);
  if ((mask & S_IRWXU) == 0 || geteuid() == 0) return;
  char octal[16];
  std::snprintf(octal, sizeof octal, "%04o", static_cast<unsigned>(mask & 07777));
  throw std::invalid_argument(
      std::string("umask ") + octal +
      ": the folders and files plywood makes would deny their owner, plywood itself, the "
      "permission to enter, write or read them back: set a umask that leaves the owner rwx "
      "(umask 022, or 077 to keep them private)");
}

}  // namespace plywood::apps
