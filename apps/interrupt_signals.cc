#include "apps/interrupt_signals.h"

#include <signal.h>

#include <csignal>

namespace plywood::apps {
namespace {

volatile std::sig_atomic_t received_signal = 0;
struct sigaction previous_int {};
struct sigaction previous_term {};

void Remember(int signal_number) { received_signal = signal_number; }

}  // namespace

InterruptSignals::InterruptSignals() {
  received_signal = 0;
  struct sigaction action {};
  action.sa_handler = Remember;
  action.sa_flags = SA_RESTART;  // a read or write the signal lands in goes on, not EINTR
  sigemptyset(&action.sa_mask);
  // A signal the caller ignores (a background job's SIGINT, nohup) stays ignored: looked up
  // first, so it is never caught, not even between installing the handler and putting SIG_IGN
  // back.
  sigaction(SIGINT, nullptr, &previous_int);
  sigaction(SIGTERM, nullptr, &previous_term);
  if (previous_int.sa_handler != SIG_IGN) sigaction(SIGINT, &action, nullptr);
  if (previous_term.sa_handler != SIG_IGN) sigaction(SIGTERM, &action, nullptr);
}

InterruptSignals::~InterruptSignals() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

int InterruptSignals::Received() const { return received_signal; }

void InterruptSignals::DieOfTheReceivedSignal() {
  // The handlers go back before the flag is read: one read first lost a signal that came between
  // the two (caught, recorded and never acted on), and the process went on to exit 0.
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
  const int signal_number = received_signal;
  if (signal_number == 0) return;
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

}  // namespace plywood::apps
