// Values a table's build computes once and its threads share (a table law's stretch weights,
// ellipse_law_integrator.hpp; the uniform table's pieces summed at an angle,
// spot_integral_table.hpp). Each value is a function of its key alone, so what a lookup returns
// does not depend on which thread or point computed it first, and the build gives the same bits
// on any number of threads. Bounded: cleared once it holds more than Most entries.
#pragma once

#include <cstddef>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace frictionid::model {

template <typename Key, typename Value, typename Hash, std::size_t Most>
class SharedMemo {
 public:
  // values[i] for keys[i]: those kept, found under one lock; the others from make(i), computed
  // outside it, then kept under a second.
  template <typename Make>
  void get(const std::vector<Key>& keys, std::vector<Value>& values, const Make& make) {
    thread_local std::vector<char> known;
    const std::size_t n = keys.size();
    values.resize(n);
    known.assign(n, 0);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (std::size_t i = 0; i < n; ++i) {
        const auto it = map_.find(keys[i]);
        if (it != map_.end()) {
          values[i] = it->second;
          known[i] = 1;
        }
      }
    }
    bool added = false;
    for (std::size_t i = 0; i < n; ++i)
      if (!known[i]) {
        values[i] = make(i);
        added = true;
      }
    if (!added) return;
    std::lock_guard<std::mutex> lock(mutex_);
    if (map_.size() > Most) map_.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (!known[i]) map_.emplace(keys[i], values[i]);
  }

  std::size_t size() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return map_.size();
  }

 private:
  mutable std::mutex mutex_;
  std::unordered_map<Key, Value, Hash> map_;
};

}  // namespace frictionid::model
