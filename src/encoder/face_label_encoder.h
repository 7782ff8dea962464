// The fLBL chunk on the encoder side (spec/qmc-format.md section 16).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "qmc/mesh.h"

namespace qmc {

// The fLBL payload of face labels `i` of `mesh`, for the faces in file
// order: face_source[j] is the input face of file face j.
std::vector<uint8_t> encode_face_labels(const FaceLabels& labels, const std::vector<uint32_t>& face_source);

// What keeps face labels `i` of `mesh` out of the format, or "".
std::string face_label_problem(const Mesh& mesh, size_t i);

}  // namespace qmc
