// Random quad disks for testing the quad coder (spec/qmc-format.md 5.3):
// random interaction sequences built by running the Spirale Reversi state
// machine (5.3.6) with random choices, so that every sequence is valid and
// every type, including the rare splits, occurs.
#pragma once

#include <cstdint>
#include <vector>

#include "qmc/mesh.h"

namespace qmc::tools {

// A valid sequence of `operations` interaction types (compression order)
// describing a disk; deterministic in `seed`. With `respect_claim`, no Q5,
// Q10, Q12 or Q13 is followed by Q1..Q5 (seed 001 §4.1), so that Codings
// I-III can code it.
std::vector<uint8_t> random_quad_sequence(uint64_t seed, uint32_t operations, bool respect_claim = false);

// The disk that sequence decodes to, with pseudo-random positions.
Mesh make_random_quad_disk(uint64_t seed, uint32_t operations);

}  // namespace qmc::tools
