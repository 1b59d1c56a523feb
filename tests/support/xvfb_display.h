#pragma once

#include <sys/types.h>

#include <memory>
#include <string>

namespace plywood::testing {

// An Xvfb X server this process starts on a display number Xvfb picks itself (-displayfd: never
// one in use) and stops, by its own pid, when destroyed. DISPLAY points at it meanwhile.
class XvfbDisplay {
 public:
  // Null, with the reason in `*why_not`, when Xvfb is not installed or does not come up in 10 s.
  static std::unique_ptr<XvfbDisplay> Start(std::string* why_not);
  ~XvfbDisplay();
  XvfbDisplay(const XvfbDisplay&) = delete;
  XvfbDisplay& operator=(const XvfbDisplay&) = delete;

  int display() const { return display_; }

 private:
  XvfbDisplay(pid_t pid, int display) : pid_(pid), display_(display) {}
  pid_t pid_;
  int display_;
};

// For tests that need a display: starts one Xvfb for the whole test program (stopped at exit), or
// prints "SKIPPED: ..." and exits with 77, which ctest shows as a skipped test
// (SKIP_RETURN_CODE 77).
void RequireXvfbOrSkip();

}  // namespace plywood::testing
