// What the aTTR fuzz targets share: one decode of a payload (spec 15) under
// the targets' output limit, and the shape an accepted attribute must have.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "decoder/attribute_decoder.h"

namespace qmc::fuzz {

inline constexpr uint64_t kAttributeOutputLimit = uint64_t(64) << 20;

// True if the payload decodes over the mesh and positions and is not skipped.
inline bool decode_attribute_payload(const uint8_t* payload, size_t length, const Mesh& mesh, uint32_t vertex_count,
                                     const std::vector<uint32_t>& positions, MeshAttribute* attribute,
                                     AttributeCoding* coding) {
  OutputBudget budget(kAttributeOutputLimit);
  bool skipped = false;
  return decode_attribute(payload, length, mesh, vertex_count, positions, {}, &budget, attribute, coding, &skipped)
             .ok() &&
         !skipped;
}

// Every corner names a value of the table, which holds C numbers a value.
inline bool well_formed(const MeshAttribute& attribute, const Mesh& mesh) {
  const size_t values = attribute.value_count();
  if (attribute.values.size() != values * attribute.components) return false;
  if (attribute.corner_values.size() != mesh.corners.size()) return false;
  for (uint32_t m : attribute.corner_values)
    if (m >= values) return false;
  return true;
}

}  // namespace qmc::fuzz
