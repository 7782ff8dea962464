// Vertex positions: bounding box, n-bit quantization and Huffman-coded
// deltas (seed 001 §2.6 and §5.1.2; spec/qmc-format.md section 6).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace qmc {

struct QuantizedPositions {
  int bits = 0;
  std::array<float, 3> min{}, max{};
  std::vector<uint32_t> q;  // 3 per vertex
};

// Quantizes finite positions (x y z per vertex) to `bits` bits per axis.
QuantizedPositions quantize_positions(const std::vector<float>& positions, int bits);

// POSN payload for positions already in file vertex order.
std::vector<uint8_t> encode_positions(const QuantizedPositions& positions);

}  // namespace qmc
