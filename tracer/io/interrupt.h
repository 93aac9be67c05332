// SIGINT, SIGTERM and SIGHUP while a command builds a directory of its own making (gpu-pack's
// staging directory). A directory tree cannot be removed inside a signal handler, which may call
// only async-signal-safe functions, so the handler only notes the signal; the command asks
// between its steps (throw_if_interrupted), and while the Interrupted exception unwinds, its
// catch blocks and destructors remove what it made. main then ends the process by the same
// signal with its default action, so the shell sees what it sent. A second signal before the
// command next asks ends the process at once.
#pragma once
#include <csignal>
#include <stdexcept>

namespace tracer {

class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }

 private:
  int signal_;
};

// While alive, the three signals are noted instead of ending the process (a signal the process
// ignores stays ignored); the destructor restores their earlier actions.
class InterruptsNoted {
 public:
  InterruptsNoted();
  ~InterruptsNoted();
  InterruptsNoted(const InterruptsNoted&) = delete;
  InterruptsNoted& operator=(const InterruptsNoted&) = delete;

 private:
  struct sigaction earlier_[3];
};

// Throws Interrupted when one of the signals arrived.
void throw_if_interrupted();

// Ends the process by `signal` with its default action.
[[noreturn]] void end_by_signal(int signal);

}  // namespace tracer
