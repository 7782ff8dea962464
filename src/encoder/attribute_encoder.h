// The aTTR chunk on the encoder side (spec/qmc-format.md section 15): one
// attribute of the input's corners, for the file's mesh in coder order.
#pragma once

#include <cstdint>
#include <vector>

#include "qmc/encoder.h"
#include "qmc/mesh.h"
#include "common/mirror_prediction.h"
#include "qmc/status.h"

namespace qmc {

// The aTTR payload of `attribute` (an attribute of the input mesh, already
// validated). file_mesh holds the faces in coder order with file vertex
// labels; file_vertex[l] is the input vertex of file label l (one entry a
// vertex); corner_source[k] is the input corner that file corner k is.
// quantized holds the POSN integers in file order (3 per vertex), from which
// unit normals are predicted (coding 3, 15.7); empty leaves them on a grid.
// With a plane (a mirror plane of those integers), values on a grid may
// take twin candidates (coding 9, 15.14).
Status encode_attribute(const MeshAttribute& attribute, const Mesh& file_mesh, const std::vector<uint32_t>& file_vertex,
                        const std::vector<uint32_t>& quantized, const std::vector<uint64_t>& corner_source,
                        const EncodeOptions& options, std::vector<uint8_t>* payload, AttributeStats* stats,
                        const MirrorPlane* plane = nullptr);

// Every problem that keeps attribute i of `mesh` out of the format, or "".
std::string attribute_problem(const Mesh& mesh, size_t i, bool exact);

}  // namespace qmc
