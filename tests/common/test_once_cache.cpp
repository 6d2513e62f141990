// OnceCache (common/once_cache.hpp): each key computed once, also when threads ask at the same
// moment; a failed computation reaches its waiters and is retried by the next call.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "common/once_cache.hpp"

TEST_CASE("OnceCache: threads asking for one key at the same moment share one computation", "[cache]") {
  sinsim::OnceCache<int, std::vector<double>> cache;
  std::atomic<int> computed{0};
  std::atomic<int> started{0};
  const auto slow = [&] {
    ++computed;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the others arrive meanwhile
    return std::vector<double>(1000, 2.5);
  };
  std::vector<const std::vector<double>*> seen(4, nullptr);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      ++started;
      while (started < 4) std::this_thread::yield();
      seen[std::size_t(t)] = &cache.get(7, slow);
    });
  for (auto& th : threads) th.join();
  CHECK(computed == 1);  // a look-up-then-insert cache computes it up to 4 times here
  for (const auto* p : seen) {
    REQUIRE(p == seen[0]);  // one value, the same object for every caller
    CHECK(p->size() == 1000);
  }
  CHECK(&cache.get(7, slow) == seen[0]);
  CHECK(computed == 1);
  CHECK(cache.get(8, [] { return std::vector<double>(3, 1.0); }).size() == 3);  // another key: its own
}

TEST_CASE("OnceCache: a computation that throws reaches the caller and is retried next time", "[cache]") {
  sinsim::OnceCache<int, double> cache;
  int calls = 0;
  CHECK_THROWS_AS(cache.get(1, [&]() -> double { ++calls; throw std::runtime_error("no"); }), std::runtime_error);
  CHECK(cache.get(1, [&] { ++calls; return 4.0; }) == 4.0);
  CHECK(calls == 2);
}
