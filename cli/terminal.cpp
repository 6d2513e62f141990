#include "cli/terminal.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <mutex>

#include "common/progress.hpp"

namespace sinsim::cli {
namespace {

using Clock = std::chrono::steady_clock;

// Written by the signal handler: lock-free atomics only.
std::atomic<long long> gFirstSigintMs{0};
std::atomic<int> gSignal{0};  // the first stopping signal (SIGINT or SIGTERM)

long long monotonicMs() {  // async-signal-safe (clock_gettime is)
  timespec ts{};
  ::clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<long long>(ts.tv_sec) * 1000 + ts.tv_nsec / 1000000;
}

extern "C" void onSigint(int sig) {
  const long long now = monotonicMs();
  if (!progress::interruptFlag().exchange(true)) {
    gSignal.store(sig);
    gFirstSigintMs.store(now);
    return;
  }
  if (now - gFirstSigintMs.load() < 1000) return;  // the same Ctrl-C, delivered twice
  static const char msg[] = "\nsinsim: interrupted twice: stopped at once\n";
  const ssize_t ignored = ::write(2, msg, sizeof msg - 1);
  (void)ignored;
  ::_exit(128 + sig);
}

std::atomic<bool> gLineEnabled{true};
std::atomic<bool> gStop{false};
std::mutex gWakeMutex;
std::condition_variable gWake;
std::mutex gLineMutex;
bool gLineShown = false;  // guarded by gLineMutex

void eraseLine() {
  std::lock_guard<std::mutex> lock(gLineMutex);
  if (!gLineShown) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  gLineShown = false;
}

/// One counted phase of the work (reading a file, then the channels): its rate and time left are
/// its own, from when the line first saw it (a channel count divided by the time since the
/// command started, reading included, gave "0.065/s, ~77 s left" for 35 s of work).
struct Phase {
  double start = 0;
  std::uint64_t done0 = 0, total = 0, last = 0;
  progress::Count unit = progress::Count::items;
};

/// A count as shown: items as they are, bytes in MB.
std::string countText(double n, progress::Count unit) {
  char buf[48];
  if (unit == progress::Count::bytes) std::snprintf(buf, sizeof buf, n < 1e7 ? "%.1f" : "%.0f", n / 1e6);
  else std::snprintf(buf, sizeof buf, "%.0f", n);
  return buf;
}

// "sinsim mc: runs 24/100 (24 %), 2.1/s, 12 s, ~38 s left";
// "sinsim diagnose: reading run1.csv 45.2/123 MB (37 %), 52 MB/s, 1 s, ~2 s left"
std::string lineText(const std::string& command, const progress::Snapshot& p, double elapsed, const Phase& phase) {
  std::string s = "sinsim " + command + ": " + (p.stage.empty() ? "working" : p.stage);
  const bool bytes = p.unit == progress::Count::bytes;
  char buf[96];
  if (p.total > 0) {
    std::snprintf(buf, sizeof buf, " %s/%s%s (%.0f %%)", countText(double(p.done), p.unit).c_str(),
                  countText(double(p.total), p.unit).c_str(), bytes ? " MB" : "",
                  100.0 * double(p.done) / double(p.total));
    s += buf;
  }
  const double span = elapsed - phase.start;
  const double rate = p.done > phase.done0 && span > 0 ? double(p.done - phase.done0) / span : 0.0;
  if (p.total > 0 && rate > 0) {
    const double shown = bytes ? rate / 1e6 : rate;
    std::snprintf(buf, sizeof buf, shown < 10 ? ", %.2g%s/s" : ", %.0f%s/s", shown, bytes ? " MB" : "");  // no exponent
    s += buf;
  }
  std::snprintf(buf, sizeof buf, ", %.0f s", elapsed);
  s += buf;
  if (p.total > 0 && rate > 0 && p.done < p.total) {
    std::snprintf(buf, sizeof buf, ", ~%.0f s left", std::ceil(double(p.total - p.done) / rate));
    s += buf;
  }
  if (progress::interruptFlag().load()) s += " — stopping (Ctrl-C)";
  return s;
}

void drawLines(const std::string& command) {
  const auto start = Clock::now();
  Phase phase;
  while (!gStop.load()) {
    {
      std::unique_lock<std::mutex> lock(gWakeMutex);  // the end of the work wakes it at once
      gWake.wait_for(lock, std::chrono::milliseconds(250), [] { return gStop.load(); });
    }
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    const progress::Snapshot p = progress::current();
    // A new phase: another total or unit, or a count that went back.
    if (p.total != phase.total || p.unit != phase.unit || p.done < phase.last)
      phase = Phase{elapsed, p.done, p.total, p.done, p.unit};
    phase.last = p.done;
    if (gStop.load() || elapsed < 1.0 || !gLineEnabled.load()) continue;
    const std::string text = lineText(command, p, elapsed, phase);
    std::lock_guard<std::mutex> lock(gLineMutex);
    if (!gLineEnabled.load()) continue;  // ended while the text was made
    std::fprintf(stderr, "\r\033[K%s", text.c_str());
    std::fflush(stderr);
    gLineShown = true;
  }
}

}  // namespace

LongWork::LongWork(std::string command) : command_(std::move(command)) {
  std::signal(SIGINT, onSigint);
  std::signal(SIGTERM, onSigint);  // `kill`, `timeout`, a batch system: the same clean stop
  gStop.store(false);
  if (::isatty(1) && ::isatty(2)) line_ = std::thread(drawLines, command_);
}

LongWork::~LongWork() {
  {
    std::lock_guard<std::mutex> lock(gWakeMutex);
    gStop.store(true);
  }
  gWake.notify_all();
  if (line_.joinable()) line_.join();
  eraseLine();
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

void endProgressLine() {
  gLineEnabled.store(false);
  eraseLine();
}

std::string interruptedMessage(const std::string& command) {
  return "sinsim " + command + ": interrupted (" + (gSignal.load() == SIGTERM ? "SIGTERM" : "Ctrl-C") +
         "); ";
}

int interruptedExitCode() { return 128 + (gSignal.load() == SIGTERM ? SIGTERM : SIGINT); }

}  // namespace sinsim::cli
