// splitmix64 (Steele, Lea, Flood 2014): a tiny generator whose output is the
// same on every platform, unlike the std:: distributions. Every generated
// mesh and every sampled measurement in the tools uses it, so results can be
// reproduced exactly.
#pragma once

#include <cstdint>

#include "common/splitmix64_mix.h"

namespace qmc::tools {

class SplitMix64 {
 public:
  explicit SplitMix64(uint64_t seed) : state_(seed) {}

  uint64_t next() { return splitmix64_mix(state_ += 0x9E3779B97F4A7C15ull); }
  // Uniform enough in [0, n) for test data (multiply-shift, no rejection).
  uint32_t below(uint32_t n) { return static_cast<uint32_t>(((next() >> 32) * n) >> 32); }
  // Uniform in [0, 1) on the 2^-53 grid.
  double unit() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }
  // A multiple of 2^-23 in [-1, 1): exact in float.
  float coordinate() {
    const int32_t steps = static_cast<int32_t>(next() >> 40) - (1 << 23);
    return static_cast<float>(steps) * (1.0f / static_cast<float>(1 << 23));
  }

 private:
  uint64_t state_;
};

}  // namespace qmc::tools
