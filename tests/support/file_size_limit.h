#pragma once

#include <sys/resource.h>

#include <csignal>

namespace plywood::testing {

// Lowers this process's file-size limit while it lives, with SIGXFSZ ignored as plywood's main()
// does, so a write past the limit fails with "File too large" instead of killing the test; the
// destructor puts the limit and the signal's handler back.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    if (getrlimit(RLIMIT_FSIZE, &saved_) != 0) return;
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = saved_;
    small.rlim_cur = bytes;
    active_ = setrlimit(RLIMIT_FSIZE, &small) == 0;
  }
  ~FileSizeLimit() {
    if (previous_handler_ == SIG_ERR) return;
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

  bool active() const { return active_; }  // false when the limit could not be set

 private:
  rlimit saved_{};
  void (*previous_handler_)(int) = SIG_ERR;
  bool active_ = false;
};

}  // namespace plywood::testing
