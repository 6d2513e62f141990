#include "common/progress.hpp"

#include <mutex>

namespace sinsim::progress {
namespace {

std::mutex gMutex;
Snapshot gCurrent;  // guarded by gMutex

}  // namespace

std::atomic<bool>& interruptFlag() {
  static std::atomic<bool> flag{false};
  return flag;
}

void update(std::string_view stage, std::uint64_t done, std::uint64_t total, Count unit) {
  std::lock_guard<std::mutex> lock(gMutex);
  if (gCurrent.stage != stage) gCurrent.stage.assign(stage);
  gCurrent.done = done;
  gCurrent.total = total;
  gCurrent.unit = unit;
}

void checkpoint(std::string_view stage, std::uint64_t done, std::uint64_t total, Count unit) {
  update(stage, done, total, unit);
  if (interruptFlag().load(std::memory_order_relaxed)) throw Interrupted();
}

Snapshot current() {
  std::lock_guard<std::mutex> lock(gMutex);
  return gCurrent;
}

}  // namespace sinsim::progress
