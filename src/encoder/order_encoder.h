// The oRDR chunk on the encoder side (spec/qmc-format.md section 4.5): the
// maps that turn the mesh in file (coder) order back into the input's order.
#pragma once

#include <cstdint>
#include <vector>

#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

// Builds the oRDR payload from the input mesh and the mesh the file carries:
// `file_mesh` holds the faces in file order with file vertex labels,
// file_vertex[l] is the input index of file vertex l and face_source[j] the
// input index of file face j. Each face's rotation is found by matching its
// corners against its input face; no match is an internal error (the file
// face is not its input face rotated). *payload is left empty when all
// three maps are identities: the file then needs no oRDR chunk.
// Section 4.5's rotation of every file face: input corner k of face
// face_source[j] is file corner (k + rotation[j]) mod d_j (for a face that
// repeats a vertex, the one oRDR writes). An internal error if a file face
// is not its input face rotated.
Status face_rotations(const Mesh& input, const Mesh& file_mesh, const std::vector<uint32_t>& file_vertex,
                      const std::vector<uint32_t>& face_source, std::vector<uint32_t>* rotation);

Status encode_order(const Mesh& input, const Mesh& file_mesh, const std::vector<uint32_t>& file_vertex,
                    const std::vector<uint32_t>& face_source, std::vector<uint8_t>* payload);

}  // namespace qmc
