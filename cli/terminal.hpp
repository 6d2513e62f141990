// The command line's side of long work (common/progress.hpp): Ctrl-C and the progress line.
//
// - SIGINT (and SIGTERM, alike) sets progress::interruptFlag(); the work stops at its next
//   checkpoint and main() prints a clear message and exits 130 (SIGTERM: 143). A SIGINT arriving within 1 s of the first counts as the
//   same one: `timeout -s INT` and a terminal's Ctrl-C under some launchers deliver it to the
//   process and to its group, i.e. twice. A second Ctrl-C after that stops at once (exit 130).
// - The progress line: when stdout and stderr are both terminals, a line on stderr redrawn every
//   0.25 s from the second second on (quick commands print none), erased when the work ends.
#pragma once

#include <string>
#include <thread>

namespace sinsim::cli {

/// One command's long work: installs the SIGINT handler and starts the progress line; the
/// destructor erases the line and restores the default SIGINT action.
class LongWork {
 public:
  explicit LongWork(std::string command);
  ~LongWork();
  LongWork(const LongWork&) = delete;
  LongWork& operator=(const LongWork&) = delete;

 private:
  std::string command_;
  std::thread line_;
};

/// Erases the progress line and draws no more: before a command prints its results, and for
/// `--no-progress`.
void endProgressLine();

/// "sinsim CMD: interrupted (Ctrl-C); " (or "(SIGTERM)") — the start of every interruption
/// message.
std::string interruptedMessage(const std::string& command);

/// 130 after Ctrl-C (SIGINT), 143 after SIGTERM: the shell's 128 + signal.
int interruptedExitCode();

}  // namespace sinsim::cli
