// The spot integrals of a fixed set of operating points, computed once. A fit evaluates the same
// rows at every iteration, and with the spot's aspect and the pressure shape held fixed the
// integrals (spot_integrals.hpp) do not change between iterations: f, kappa, h and h_y only
// recombine them. Keyed by the bits of the centre of rotation, so that a lookup finds exactly the
// point the model would integrate.
#pragma once

#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <utility>

#include <frictionid/model/spot_integrals.hpp>

namespace frictionid::model {

class SpotIntegralCache {
 public:
  // The integrals were computed for aspect q and pressure exponent n (n of a power law; any value
  // for other laws).
  SpotIntegralCache(double q, double n) : q_(q), n_(n) {}

  double q() const { return q_; }
  double n() const { return n_; }
  std::size_t size() const { return map_.size(); }

  void reserve(std::size_t points) { map_.reserve(points); }
  void insert(double cx, double cy, const SpotIntegrals& value) { map_[key(cx, cy)] = value; }

  // The integrals at (cx, cy), or null when that point was not cached.
  const SpotIntegrals* find(double cx, double cy) const {
    const auto it = map_.find(key(cx, cy));
    return it == map_.end() ? nullptr : &it->second;
  }

 private:
  struct Key {
    std::uint64_t x, y;
    bool operator==(const Key& o) const { return x == o.x && y == o.y; }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      // splitmix64 finaliser of the combined bits: the points of a sweep differ in few bits.
      std::uint64_t z = k.x ^ (k.y + 0x9e3779b97f4a7c15ULL + (k.x << 6) + (k.x >> 2));
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      return static_cast<std::size_t>(z ^ (z >> 31));
    }
  };
  static Key key(double cx, double cy) {
    Key k;
    std::memcpy(&k.x, &cx, sizeof cx);
    std::memcpy(&k.y, &cy, sizeof cy);
    return k;
  }

  double q_, n_;
  std::unordered_map<Key, SpotIntegrals, KeyHash> map_;
};

// The centre of rotation of a row with omega != 0, units of R (docs/physics.md §9.3). One
// function, so that a cache and the model compute the same bits. K: a double or a dual number.
template <typename K>
std::pair<K, K> rotation_centre(const K& v_x, const K& v_y, const K& omega, double R) {
  return {-v_y / (omega * R), v_x / (omega * R)};
}

}  // namespace frictionid::model
