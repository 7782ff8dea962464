// splitmix64's output function (Steele, Lea, Flood 2014): a 64-bit mix in
// which every input bit moves about half the output bits. The grid-point
// table hashes with it (mirror_prediction.cc), the encoder picks its sample
// of the input with it (level_distance.cc), and the tools' generator is
// built on it (tools/lib/splitmix64.h).
#pragma once

#include <cstdint>

namespace qmc {

inline uint64_t splitmix64_mix(uint64_t x) {
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

}  // namespace qmc
