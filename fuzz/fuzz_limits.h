// The limits the fuzz targets decode under. Whole files: the decoder's
// memory follows the output charged against its limits (spec 8.1), so with
// at most 8 MiB of output an allocation above fuzz.sh's malloc limit (64 MB)
// is a finding, never a valid file that is merely large. Targets of one
// component, which have no such limits: the vertex counts below.
#pragma once

#include <cstdint>

#include "qmc/decoder.h"

namespace qmc::fuzz {

// The most vertices a target decodes when it takes a vertex count from its
// input without a whole file's limits: spec 8.1's limits bound V in a whole
// file, and 2^20 vertices keep each allocation under fuzz.sh's 64 MB.
inline constexpr uint32_t kMaxVertices = 1u << 20;
// The same for targets that decode a payload over positions they make up:
// in a file, POSN would have to back the vertices.
inline constexpr uint32_t kMaxVerticesWithoutPositions = 1u << 16;

inline DecoderLimits small_output_limits() {
  DecoderLimits limits;
  limits.max_output_bytes = 8 << 20;
  return limits;
}

}  // namespace qmc::fuzz
