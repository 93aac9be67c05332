#include "io/interrupt.h"

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <string>

namespace tracer {
namespace {

constexpr int kSignals[3] = {SIGINT, SIGTERM, SIGHUP};
std::atomic<int> noted_signal{0};

void note_signal(int signal) {
  int none = 0;
  if (!noted_signal.compare_exchange_strong(none, signal)) {  // the second one: now
    ::signal(signal, SIG_DFL);
    ::raise(signal);
  }
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by ") + ::strsignal(signal)), signal_(signal) {}

InterruptsNoted::InterruptsNoted() {
  noted_signal.store(0);
  struct sigaction noting {};
  noting.sa_handler = note_signal;
  sigemptyset(&noting.sa_mask);
  for (int i = 0; i < 3; ++i) {
    ::sigaction(kSignals[i], nullptr, &earlier_[i]);
    if (earlier_[i].sa_handler != SIG_IGN) ::sigaction(kSignals[i], &noting, nullptr);
  }
}

InterruptsNoted::~InterruptsNoted() {
  for (int i = 0; i < 3; ++i) ::sigaction(kSignals[i], &earlier_[i], nullptr);
}

void throw_if_interrupted() {
  if (const int signal = noted_signal.load()) throw Interrupted(signal);
}

void end_by_signal(int signal) {
  ::signal(signal, SIG_DFL);
  ::raise(signal);
  std::_Exit(128 + signal);  // the signal was blocked: exit as a shell reports it
}

}  // namespace tracer
