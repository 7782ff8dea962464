// The geometry-image encoder: spec/qmc-format.md section 13.11 (informative),
// seeds 000 and 002. Called by encode() when EncodeOptions::gim.size > 0.
#pragma once

#include <vector>

#include "qmc/encoder.h"
#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

Status encode_geometry_image(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* out,
                             EncodeStats* stats);

}  // namespace qmc
