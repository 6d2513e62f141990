// A thread-safe cache that computes each key's value once: the first caller computes, callers
// asking for the same key meanwhile wait for that result instead of computing it again (a plain
// "look up, else compute, then insert" lets every thread that misses at the same moment do the
// whole work). Values are never evicted; a failed computation is retried by the next call.
#pragma once

#include <exception>
#include <future>
#include <map>
#include <memory>
#include <mutex>

namespace sinsim {

template <class Key, class Value>
class OnceCache {
 public:
  /// The value of `key`, from compute() (returning a Value) on the first call; the reference stays
  /// valid for the cache's life. compute's exception reaches every caller waiting for this key.
  template <class Compute>
  const Value& get(const Key& key, Compute&& compute) {
    std::promise<const Value*> mine;
    std::shared_future<const Value*> result;
    bool owner = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto it = entries_.find(key);
      if (it == entries_.end()) {
        result = mine.get_future().share();
        entries_.emplace(key, Entry{result, nullptr});
        owner = true;
      } else {
        result = it->second.result;
      }
    }
    if (owner) {
      try {
        auto value = std::make_unique<const Value>(compute());
        const Value* p = value.get();
        {
          std::lock_guard<std::mutex> lock(mutex_);
          entries_.at(key).value = std::move(value);
        }
        mine.set_value(p);
      } catch (...) {
        {
          std::lock_guard<std::mutex> lock(mutex_);
          entries_.erase(key);
        }
        mine.set_exception(std::current_exception());
      }
    }
    return *result.get();
  }

 private:
  struct Entry {
    std::shared_future<const Value*> result;
    std::unique_ptr<const Value> value;
  };
  std::mutex mutex_;
  std::map<Key, Entry> entries_;
};

}  // namespace sinsim
