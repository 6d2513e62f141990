// Independent work items (Monte Carlo realisations, channels, runs) on worker threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace sinsim {

/// The worker threads of `threads` (0: every core), never more than the items.
inline unsigned workerCount(unsigned threads, std::size_t items) {
  const unsigned nt = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
  return unsigned(std::max<std::size_t>(1, std::min<std::size_t>(nt, items)));
}

/// fn(i, state) for i = 0..n-1 on workerCount(threads, n) threads (the caller's among them), each
/// with its own default-constructed State (scratch buffers). Items are taken in order from a
/// shared counter; fn must write its result to slot i only, so that the result does not depend on
/// which thread ran which item. The first exception stops the other workers after their current
/// item and is rethrown here.
template <class State, class Fn>
void parallelFor(std::size_t n, unsigned threads, Fn fn) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr failure;
  auto worker = [&] {
    State state{};
    for (;;) {
      const std::size_t i = next++;
      if (i >= n || failed) return;
      try {
        fn(i, state);
      } catch (...) {
        if (!failed.exchange(true)) failure = std::current_exception();
        return;
      }
    }
  };
  const unsigned nt = workerCount(threads, n);
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < nt; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace sinsim
