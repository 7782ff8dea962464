// The decoder limits of the whole-file fuzz targets. The decoder's memory
// follows the output charged against them (spec 8.1), so with at most 8 MiB
// of output an allocation above fuzz.sh's malloc limit (64 MB) is a finding,
// never a valid file that is merely large.
#pragma once

#include "qmc/decoder.h"

namespace qmc::fuzz {

inline DecoderLimits small_output_limits() {
  DecoderLimits limits;
  limits.max_output_bytes = 8 << 20;
  return limits;
}

}  // namespace qmc::fuzz
