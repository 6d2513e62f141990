#include "python/interrupt.hpp"

#include <Python.h>

#include <csignal>
#include <exception>
#include <mutex>

#include "common/progress.hpp"

namespace sinsim::python {
namespace {

struct State {
  std::mutex mutex;
  int scopes = 0;
  struct sigaction python {};  // the handler the first scope replaced
};

State& state() {
  static State s;
  return s;
}

void onSigint(int) { progress::interruptFlag().store(true); }  // lock-free: async-signal-safe

}  // namespace

InterruptScope::InterruptScope() : uncaught_(std::uncaught_exceptions()) {
  std::lock_guard<std::mutex> lock(state().mutex);
  if (state().scopes++ > 0) return;
  progress::interruptFlag().store(false);
  struct sigaction ours {};
  ours.sa_handler = onSigint;
  sigemptyset(&ours.sa_mask);
  sigaction(SIGINT, &ours, &state().python);
}

InterruptScope::~InterruptScope() {
  std::lock_guard<std::mutex> lock(state().mutex);
  if (--state().scopes > 0) return;
  sigaction(SIGINT, &state().python, nullptr);
  // Python raises KeyboardInterrupt at its next check (PyErr_SetInterrupt is async-signal-safe and
  // needs no GIL); the flag is the library's, cleared for the next call.
  // A call that stopped by throwing Interrupted is raised by the translator (python/module.cpp),
  // not twice.
  if (progress::interruptFlag().exchange(false) && std::uncaught_exceptions() <= uncaught_) PyErr_SetInterrupt();
}

}  // namespace sinsim::python
