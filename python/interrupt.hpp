// Ctrl-C during a long call of the module (synth, fit, diagnose, analyze, run): the library's
// progress checkpoints stop the work as they stop the command line's (common/progress.hpp), and
// Python raises KeyboardInterrupt. Without it Python saw the signal only after the call had
// finished (a 1-h synth ran to its end and wrote its file, then raised).
#pragma once

namespace sinsim::python {

/// For its lifetime SIGINT sets the library's interrupt flag instead of Python's handler (which is
/// put back at the end, and told of the signal then). Scopes may overlap (threads): the first
/// installs, the last restores.
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

 private:
  int uncaught_;  // exceptions in flight at the start: an Interrupted unwinding is raised as one
};

}  // namespace sinsim::python
