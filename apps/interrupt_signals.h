#pragma once

namespace plywood::apps {

// SIGINT and SIGTERM caught while this lives, so a command that writes many files in place can
// stop between two of them and remove what it wrote instead of dying mid-way; the handlers before
// are put back on destruction. One at a time per process.
class InterruptSignals {
 public:
  InterruptSignals();
  ~InterruptSignals();
  InterruptSignals(const InterruptSignals&) = delete;
  InterruptSignals& operator=(const InterruptSignals&) = delete;

  // The signal received since construction, or 0.
  int Received() const;

  // Puts the handlers back and, when a signal was received, dies of it as if never caught (exit
  // status 128 + the signal to a shell), so callers see the usual termination.
  void DieOfTheReceivedSignal();
};

}  // namespace plywood::apps
