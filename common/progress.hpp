// Long work: what it is doing, and whether the user asked it to stop. The one home of both.
//
// Library code (sim/, errormodels/) publishes its stage and count with progress::update, and at
// safe points calls progress::checkpoint: once the interrupt flag is set, checkpoint throws
// Interrupted, which unwinds through the atomic writers (common/atomic_file.hpp, sim OutputFiles)
// so that no half-written file is left. Loops that stop on their own and keep what they finished
// (the navigation loop, mc's workers) read interruptFlag() instead.
// Who sets the flag and draws the published progress is the caller's business: the command line
// does both (cli/terminal.hpp: SIGINT handler, progress line on a terminal). Without a caller that
// sets the flag, checkpoint never throws and update only stores a few values.
#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>

namespace sinsim {

/// The user asked to stop (Ctrl-C). Deliberately not a sinsim::Error: code that tries a fit and
/// catches Error to try the next one must not swallow it.
class Interrupted : public std::exception {
 public:
  const char* what() const noexcept override { return "interrupted"; }
};

namespace progress {

/// Set (once) when the user asks to stop; never cleared by the library.
std::atomic<bool>& interruptFlag();

/// What done and total count: items (runs, channels) or bytes (of a file being read).
enum class Count { items, bytes };

/// Publishes the current stage ("reading run1.csv", "realisations") and, when total > 0, how far
/// it is (done of total). Thread-safe; cheap enough for a call every few milliseconds.
void update(std::string_view stage, std::uint64_t done = 0, std::uint64_t total = 0, Count unit = Count::items);

/// update(), then throws Interrupted if the interrupt flag is set.
void checkpoint(std::string_view stage, std::uint64_t done = 0, std::uint64_t total = 0,
                Count unit = Count::items);

/// What update() last published.
struct Snapshot {
  std::string stage;
  std::uint64_t done = 0, total = 0;
  Count unit = Count::items;
};
Snapshot current();

}  // namespace progress
}  // namespace sinsim
